#include "ArrayChoice.h"

#include "Error.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vtkDataSetAttributes.h>

namespace art
{
vtkDataArray* ChooseArray(vtkDataSetAttributes* d, const std::string& name, bool named)
{
  if (!name.empty())
  {
    return d->GetArray(name.c_str());
  }
  if (vtkDataArray* s = d->GetScalars())
  {
    return s;
  }
  // VTK's own bookkeeping arrays (vtkOriginalPointIds from ParaView's Extract Selection,
  // vtkValidPointMask from a probe, vtkGhostType, ...) come last: a file without active scalars
  // rendered its point ids as the field when they came first.
  for (const bool bookkeeping : { false, true })
  {
    for (int i = 0; i < d->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* a = d->GetArray(i);
      const bool vtks = a && a->GetName() && std::string(a->GetName()).rfind("vtk", 0) == 0;
      if (a && vtks == bookkeeping && a->GetNumberOfComponents() == 1 && (!named || a->GetName()))
      {
        return a;
      }
    }
  }
  return nullptr;
}

std::string ArrayNames(std::initializer_list<vtkFieldData*> fields)
{
  std::string names;
  for (vtkFieldData* fd : fields)
  {
    for (int i = 0; i < fd->GetNumberOfArrays(); ++i)
    {
      names += (names.empty() ? "" : ", ") + std::string(fd->GetArrayName(i) ? fd->GetArrayName(i) : "(unnamed)");
    }
  }
  return names.empty() ? "none" : names;
}

std::string SplitComponent(const std::string& spec, int* component)
{
  *component = WholeArray;
  const size_t colon = spec.rfind(':');
  if (colon == std::string::npos)
  {
    return spec;
  }
  std::string suffix = spec.substr(colon + 1);
  for (char& c : suffix)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  if (suffix == "magnitude" || suffix == "mag")
  {
    *component = Magnitude;
  }
  else if (suffix.size() == 1 && suffix[0] >= 'x' && suffix[0] <= 'z')
  {
    *component = suffix[0] - 'x';
  }
  else if (!suffix.empty() && suffix.size() < 4 &&
    std::all_of(suffix.begin(), suffix.end(), [](char c) { return c >= '0' && c <= '9'; }))
  {
    *component = std::stoi(suffix);
  }
  else
  {
    return spec; // a name that holds a colon
  }
  return spec.substr(0, colon);
}

vtkSmartPointer<vtkDataArray> TakeComponent(vtkDataArray* a, int component)
{
  if (!a || component == WholeArray)
  {
    return a;
  }
  const int nc = a->GetNumberOfComponents();
  const std::string name = a->GetName() ? a->GetName() : "";
  if (component >= nc)
  {
    throw Error("array '" + name + "' has " + std::to_string(nc) + " component" + (nc == 1 ? "" : "s") +
      " (0 .. " + std::to_string(nc - 1) + "), not a component " + std::to_string(component));
  }
  auto out = vtkSmartPointer<vtkDoubleArray>::New();
  out->SetName((name + ":" + (component == Magnitude ? std::string("magnitude") : std::to_string(component))).c_str());
  out->SetNumberOfTuples(a->GetNumberOfTuples());
  for (vtkIdType t = 0; t < a->GetNumberOfTuples(); ++t)
  {
    double v = 0;
    if (component == Magnitude)
    {
      for (int c = 0; c < nc; ++c)
      {
        const double x = a->GetComponent(t, c);
        v += x * x;
      }
      v = std::sqrt(v);
    }
    else
    {
      v = a->GetComponent(t, component);
    }
    out->SetValue(t, v);
  }
  return out;
}

std::string ComponentHint(vtkDataArray* a)
{
  const std::string name = a && a->GetName() ? a->GetName() : "";
  const int nc = a ? a->GetNumberOfComponents() : 0;
  return name + ":magnitude or " + name + ":0 .. " + name + ":" + std::to_string(nc - 1);
}
} // namespace art
