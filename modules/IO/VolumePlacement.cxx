#include "VolumePlacement.h"
#include "Error.h"
#include "NrrdCheck.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkNIFTIImageHeader.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace art
{
namespace
{
const char* CodeName(int code)
{
  switch (code)
  {
    case 1:
      return "scanner";
    case 2:
      return "aligned anatomy";
    case 3:
      return "Talairach";
    case 4:
      return "MNI-152";
    case 5:
      return "template";
    default:
      return "unknown kind";
  }
}

struct Transform
{
  const char* Name = nullptr; // "sform" or "qform"; null: neither
  int Code = 0;
  vtkMatrix4x4* M = nullptr; // maps VTK's data coordinates (origin + index * spacing) to RAS
};

// Unit axes (the columns of m's 3x3) and their lengths; false when an axis is zero or two are
// not perpendicular (a sheared sform: a direction matrix holds only rotations and flips).
bool Axes(vtkMatrix4x4* m, double axis[3][3], double length[3])
{
  for (int c = 0; c < 3; ++c)
  {
    length[c] = std::sqrt(m->GetElement(0, c) * m->GetElement(0, c) + m->GetElement(1, c) * m->GetElement(1, c) +
      m->GetElement(2, c) * m->GetElement(2, c));
    if (!(length[c] > 0) || !std::isfinite(length[c]))
    {
      return false;
    }
    for (int r = 0; r < 3; ++r)
    {
      axis[c][r] = m->GetElement(r, c) / length[c];
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    for (int b = a + 1; b < 3; ++b)
    {
      const double dot = axis[a][0] * axis[b][0] + axis[a][1] * axis[b][1] + axis[a][2] * axis[b][2];
      if (std::abs(dot) > 1e-4)
      {
        return false;
      }
    }
  }
  return true;
}

// nibabel's choice: the sform when its code is set, else the qform, else neither. A sheared
// sform gives way to the qform; with no qform to fall back on it is an error.
Transform Choose(vtkNIFTIImageReader* r, const std::string& path)
{
  vtkNIFTIImageHeader* h = r->GetNIFTIHeader();
  const Transform sform{ "sform", h->GetSFormCode(), r->GetSFormMatrix() };
  const Transform qform{ "qform", h->GetQFormCode(), r->GetQFormMatrix() };
  double axis[3][3], length[3];
  if (sform.Code > 0 && sform.M)
  {
    if (Axes(sform.M, axis, length))
    {
      return sform;
    }
    if (!(qform.Code > 0 && qform.M))
    {
      throw Error("the NIfTI sform's axes are zero or not perpendicular (a sheared transform), and there is no qform "
                  "to place the voxels by",
        path);
    }
  }
  if (qform.Code > 0 && qform.M)
  {
    if (!Axes(qform.M, axis, length))
    {
      throw Error("the NIfTI qform's axes are zero or not perpendicular", path);
    }
    return qform;
  }
  return {};
}
// "space directions": one "(x,y,z)" vector per axis, or "none" (an empty vector) for a
// non-spatial axis.
std::vector<std::vector<double>> NrrdDirections(const std::string& value, const std::string& path)
{
  std::vector<std::vector<double>> axes;
  std::istringstream words(value);
  std::string w;
  while (words >> w)
  {
    std::vector<double> v;
    if (w != "none")
    {
      std::string inside = w.substr(w.find('(') + 1);
      inside = inside.substr(0, inside.find(')'));
      std::replace(inside.begin(), inside.end(), ',', ' ');
      std::istringstream numbers(inside);
      double x;
      while (numbers >> x)
      {
        v.push_back(x);
      }
      if (w.front() != '(' || w.back() != ')' || v.empty())
      {
        throw Error("cannot read space directions '" + value + "'", path);
      }
    }
    axes.push_back(v);
  }
  return axes;
}
} // namespace

namespace
{
// The header's fields PlaceNrrd needs.
struct NrrdHeader
{
  std::map<std::string, std::string> Keys;
  std::vector<long long> Sizes;
  std::vector<std::string> Kinds; // lower case
  std::vector<std::vector<double>> Directions;
};

NrrdHeader ReadNrrdHeader(const std::string& path)
{
  std::ifstream file(path, std::ios::binary);
  NrrdHeader h;
  h.Keys = ReadNrrdFields(file);
  std::istringstream sizes(h.Keys["sizes"]);
  for (long long n; sizes >> n;)
  {
    h.Sizes.push_back(n);
  }
  std::istringstream kinds(h.Keys["kinds"]);
  for (std::string k; kinds >> k;)
  {
    std::transform(k.begin(), k.end(), k.begin(), [](unsigned char c) { return std::tolower(c); });
    h.Kinds.push_back(k);
  }
  h.Directions = NrrdDirections(h.Keys["space directions"], path);
  return h;
}

// vtkNrrdReader makes a first axis of <= 9 samples the components; undo it unless the header
// says the axis is not in space (a kind such as vector, or no space direction): three axes are
// a volume, and a minimal header (type, dimension, sizes, encoding) names neither (the voxels'
// memory order is the same either way). Returns the image with that axis as x, or null.
vtkSmartPointer<vtkImageData> ComponentsAsFirstAxis(vtkImageData* img, NrrdHeader& h)
{
  vtkDataArray* s = img->GetPointData()->GetScalars();
  const auto& kinds = h.Kinds;
  const auto& dirs = h.Directions;
  const bool spatialFirst = h.Sizes.size() == 3 &&
    (kinds.size() == 3 ? (kinds[0] == "domain" || kinds[0] == "space") : (dirs.size() != 3 || !dirs[0].empty()));
  if (!(spatialFirst && s && s->GetNumberOfComponents() > 1 && s->GetNumberOfComponents() == h.Sizes[0]))
  {
    return nullptr;
  }
  vtkSmartPointer<vtkDataArray> one = vtk::TakeSmartPointer(s->NewInstance());
  one->SetName(s->GetName());
  one->SetNumberOfComponents(1);
  one->SetNumberOfTuples(s->GetNumberOfValues());
  std::memcpy(one->GetVoidPointer(0), s->GetVoidPointer(0), s->GetNumberOfValues() * s->GetDataTypeSize());
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetDimensions(int(h.Sizes[0]), int(h.Sizes[1]), int(h.Sizes[2]));
  out->SetOrigin(img->GetOrigin());
  out->GetPointData()->SetScalars(one);
  double spacing[3] = { 1, 1, 1 };
  std::istringstream in(h.Keys["spacings"]);
  for (double& d : spacing)
  {
    double x;
    if (in >> x && x > 0 && std::isfinite(x))
    {
      d = x;
    }
  }
  out->SetSpacing(spacing);
  return out;
}

// The spatial axes' directions (signs and rotation; VTK kept their lengths as the spacing).
void ApplyNrrdDirections(vtkImageData* out, const NrrdHeader& h, double direction[9], const std::string& path)
{
  std::vector<std::vector<double>> spatial;
  std::copy_if(h.Directions.begin(), h.Directions.end(), std::back_inserter(spatial), [](const auto& v) { return !v.empty(); });
  if (spatial.size() != 3)
  {
    return;
  }
  double spacing[3];
  for (int c = 0; c < 3; ++c)
  {
    if (spatial[c].size() != 3)
    {
      throw Error("a space direction has " + std::to_string(spatial[c].size()) + " coordinates, expected 3", path);
    }
    const double len = std::sqrt(spatial[c][0] * spatial[c][0] + spatial[c][1] * spatial[c][1] + spatial[c][2] * spatial[c][2]);
    if (!(len > 0) || !std::isfinite(len))
    {
      throw Error("a space direction has zero or non-finite length", path);
    }
    spacing[c] = len;
    for (int r = 0; r < 3; ++r)
    {
      direction[3 * r + c] = spatial[c][r] / len;
    }
  }
  out->SetSpacing(spacing);
}

// A RAS or LAS "space" becomes LPS, as ITK reads it. In a left-handed space vtkNrrdReader
// reverses the rows of its y axis (the header's second axis, or its third when the first became
// components) and keeps the origin: the first voxel is then the header's last along that axis.
void ToLps(vtkImageData* out, NrrdHeader& h, bool rebuilt, double direction[9])
{
  std::string space = h.Keys["space"];
  std::transform(space.begin(), space.end(), space.begin(), [](unsigned char c) { return std::tolower(c); });
  const bool ras = space == "right-anterior-superior" || space == "ras" || space == "right-anterior-superior-time" || space == "rast";
  const bool las = space == "left-anterior-superior" || space == "las" || space == "left-anterior-superior-time" || space == "last";
  double origin[3];
  out->GetOrigin(origin);
  if (las || space == "3d-left-handed" || space == "3d-left-handed-time")
  {
    const int a = rebuilt ? 2 : 1;
    const int n = out->GetDimensions()[a];
    const double step = out->GetSpacing()[a];
    for (int r = 0; r < 3; ++r)
    {
      origin[r] += direction[3 * r + a] * step * (n - 1);
      direction[3 * r + a] = -direction[3 * r + a];
    }
  }
  for (int r = 0; r < 2; ++r)
  {
    if (ras || (las && r == 1))
    {
      origin[r] = -origin[r];
      for (int c = 0; c < 3; ++c)
      {
        direction[3 * r + c] = -direction[3 * r + c];
      }
    }
  }
  out->SetOrigin(origin);
}
} // namespace

vtkSmartPointer<vtkImageData> NrrdAxesAsVtk(vtkImageData* img, const std::string& path)
{
  NrrdHeader h = ReadNrrdHeader(path);
  vtkSmartPointer<vtkImageData> out = ComponentsAsFirstAxis(img, h);
  if (!out)
  {
    out = vtkSmartPointer<vtkImageData>::New();
    out->ShallowCopy(img);
  }
  return out;
}

vtkSmartPointer<vtkImageData> PlaceNrrd(vtkImageData* img, const std::string& path)
{
  NrrdHeader h = ReadNrrdHeader(path);
  vtkSmartPointer<vtkImageData> out = ComponentsAsFirstAxis(img, h);
  const bool rebuilt = out != nullptr;
  if (!out)
  {
    out = vtkSmartPointer<vtkImageData>::New();
    out->ShallowCopy(img);
  }
  double direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  ApplyNrrdDirections(out, h, direction, path);
  ToLps(out, h, rebuilt, direction);
  out->SetDirectionMatrix(direction);
  return out;
}

void PlaceNifti(vtkImageData* img, vtkNIFTIImageReader* reader, const std::string& path)
{
  const Transform t = Choose(reader, path);
  if (!t.M)
  {
    return;
  }
  double axis[3][3], length[3];
  Axes(t.M, axis, length);
  const double* o = img->GetOrigin();
  const double* s = img->GetSpacing();
  double origin[3], spacing[3], direction[9];
  for (int r = 0; r < 3; ++r)
  {
    // RAS to LPS: x and y change sign.
    const double flip = r < 2 ? -1.0 : 1.0;
    origin[r] = flip *
      (t.M->GetElement(r, 0) * o[0] + t.M->GetElement(r, 1) * o[1] + t.M->GetElement(r, 2) * o[2] +
        t.M->GetElement(r, 3));
    spacing[r] = s[r] * length[r]; // an sform may scale beyond pixdim
    for (int c = 0; c < 3; ++c)
    {
      direction[3 * r + c] = flip * axis[c][r];
    }
  }
  img->SetOrigin(origin);
  img->SetSpacing(spacing);
  img->SetDirectionMatrix(direction);
}

NiftiPlacementInfo NiftiPlacement(const std::string& path)
{
  vtkNew<vtkNIFTIImageReader> r;
  r->SetFileName(path.c_str());
  r->UpdateInformation();
  const Transform t = Choose(r, path);
  NiftiPlacementInfo info;
  info.How = t.M ? std::string(t.Name) + " code " + std::to_string(t.Code) + " (" + CodeName(t.Code) + ")"
                 : "none (no qform or sform: axes as stored, origin 0)";
  info.Placed = t.M != nullptr;
  info.SlicesReversed = r->GetQFac() < 0;
  vtkNIFTIImageHeader* h = r->GetNIFTIHeader();
  for (int d = 4; d <= std::min<long long>(h->GetDim(0), 7); ++d)
  {
    info.TimePoints *= std::max<long long>(h->GetDim(d), 1);
  }
  return info;
}

std::string AxisCodes(vtkImageData* img)
{
  const double* d = img->GetDirectionMatrix()->GetData();
  const char plus[3] = { 'L', 'P', 'S' }, minus[3] = { 'R', 'A', 'I' };
  std::string codes;
  for (int c = 0; c < 3; ++c)
  {
    int best = 0;
    for (int r = 1; r < 3; ++r)
    {
      best = std::abs(d[3 * r + c]) > std::abs(d[3 * best + c]) ? r : best;
    }
    codes += d[3 * best + c] >= 0 ? plus[best] : minus[best];
  }
  return codes;
}
} // namespace art
