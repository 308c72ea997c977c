#include "ArrayChoice.h"

#include <vtkDataArray.h>
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
  for (int i = 0; i < d->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* a = d->GetArray(i);
    if (a && a->GetNumberOfComponents() == 1 && (!named || a->GetName()))
    {
      return a;
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
} // namespace art
