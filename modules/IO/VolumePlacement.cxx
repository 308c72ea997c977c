#include "VolumePlacement.h"
#include "Error.h"

#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkNIFTIImageHeader.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>

#include <cmath>

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
} // namespace

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
  info.SlicesReversed = r->GetQFac() < 0;
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
