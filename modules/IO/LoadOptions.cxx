// LoadOptions: what DataLoader.h's LoadOptions hold, from text (a raw layout's --raw-* values,
// a frame's name), and the record of a data set's placement in its field data.
#include "DataLoader.h"
#include "Error.h"

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkNew.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace art
{
void SetRawOption(RawLayout& raw, const std::string& option, const std::string& value)
{
  auto numbers = [&](int n, bool whole) {
    std::vector<double> v;
    std::stringstream in(value);
    std::string item;
    while (std::getline(in, item, ','))
    {
      char* end = nullptr;
      const double x = std::strtod(item.c_str(), &end);
      if (item.empty() || *end != '\0' || item.find_first_of("xXnNiI") != std::string::npos || !std::isfinite(x) ||
        !(x > 0) || (whole && (x != std::floor(x) || x > 1e9)))
      {
        v.clear();
        break;
      }
      v.push_back(x);
    }
    if (static_cast<int>(v.size()) != n)
    {
      throw std::invalid_argument("--" + option + " expects " + (n == 3 ? "X,Y,Z" : "N") + " (" +
        (whole ? "positive whole numbers" : "positive numbers") + "), got '" + value + "'");
    }
    return v;
  };
  if (option == "raw-dims")
  {
    const auto v = numbers(3, true);
    for (int a = 0; a < 3; ++a)
    {
      raw.Dims[a] = static_cast<int>(v[a]);
    }
  }
  else if (option == "raw-spacing")
  {
    const auto v = numbers(3, false);
    std::copy(v.begin(), v.end(), raw.Spacing);
    raw.SpacingGiven = true;
  }
  else if (option == "raw-components")
  {
    raw.Components = static_cast<int>(numbers(1, true)[0]);
  }
  else if (option == "raw-header")
  {
    char* end = nullptr;
    const long long n = std::strtoll(value.c_str(), &end, 10);
    if (value.empty() || *end != '\0' || n < 0 || value.find_first_not_of("0123456789") != std::string::npos)
    {
      throw std::invalid_argument("--raw-header expects a byte count >= 0, got '" + value + "'");
    }
    raw.HeaderBytes = n;
  }
  else if (option == "raw-endian")
  {
    if (value != "little" && value != "big")
    {
      throw std::invalid_argument("--raw-endian is little or big, got '" + value + "'");
    }
    raw.BigEndian = value == "big";
  }
  else if (option == "raw-type")
  {
    static const std::set<std::string> types = { "uint8", "int8", "uint16", "int16", "uint32", "int32", "uint64",
      "int64", "float32", "float64", "uchar", "char", "ushort", "short", "uint", "int", "float", "double" };
    if (!types.count(value))
    {
      throw std::invalid_argument("--raw-type is one of uint8 int8 uint16 int16 uint32 int32 uint64 int64 float32 "
                                  "float64, got '" + value + "'");
    }
    raw.Type = value;
  }
  else
  {
    throw std::invalid_argument("unknown raw option '--" + option + "'");
  }
}

Frame ParseFrame(const std::string& name)
{
  if (name == "patient")
  {
    return Frame::Patient;
  }
  if (name == "vtk")
  {
    return Frame::Vtk;
  }
  throw Error("--frame is patient or vtk, got '" + name + "'");
}

const char* FrameName(Frame f)
{
  return f == Frame::Patient ? "patient" : "vtk";
}

void RecordPlacement(vtkDataSet* data, const std::string& frame)
{
  double m[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  if (auto* img = vtkImageData::SafeDownCast(data))
  {
    const double* d = img->GetDirectionMatrix()->GetData();
    const double* sp = img->GetSpacing();
    const double* o = img->GetOrigin();
    int e[6];
    img->GetExtent(e);
    for (int r = 0; r < 3; ++r)
    {
      // world = origin + D diag(spacing) (ijk), ijk counted from the extent's first index.
      for (int c = 0; c < 3; ++c)
      {
        m[4 * r + c] = d[3 * r + c] * sp[c];
      }
      m[4 * r + 3] = o[r];
    }
  }
  vtkNew<vtkDoubleArray> matrix;
  matrix->SetName("IndexToWorld");
  matrix->SetNumberOfComponents(16);
  matrix->InsertNextTuple(m);
  vtkNew<vtkStringArray> name;
  name->SetName("Frame");
  name->InsertNextValue(frame);
  data->GetFieldData()->AddArray(matrix);
  data->GetFieldData()->AddArray(name);
}

} // namespace art
