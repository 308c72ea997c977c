#include "VisibleBounds.h"

#include "TetMesh.h"
#include "TetRayCaster.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace art
{
namespace
{
bool Visible(const RenderSettings& s, double lo, double hi)
{
  // A NaN or infinite voxel is refused by the caster with its place; here it frames nothing
  // (the transfer function's lookup is not defined there).
  if (!std::isfinite(lo) || !std::isfinite(hi))
  {
    return false;
  }
  if (lo > hi)
  {
    std::swap(lo, hi);
  }
  if (!s.tf.Transparent(lo, hi))
  {
    return true;
  }
  return std::any_of(s.isos.begin(), s.isos.end(), [&](const IsoSurface& i) { return i.value >= lo && i.value <= hi; });
}

// The index range along one axis holding all but `drop` of the counted voxels at each end.
std::array<int, 2> Trimmed(const std::vector<long long>& count, long long drop)
{
  int a = 0, b = static_cast<int>(count.size()) - 1;
  for (long long seen = 0; a < b && seen + count[a] <= drop; ++a)
  {
    seen += count[a];
  }
  for (long long seen = 0; b > a && seen + count[b] <= drop; --b)
  {
    seen += count[b];
  }
  return { a, b };
}
} // namespace

Box3 VisibleBounds(vtkImageData* image, const RenderSettings& s)
{
  vtkDataArray* a = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!a)
  {
    return {};
  }
  int d[3], e[6];
  image->GetDimensions(d);
  image->GetExtent(e);
  std::vector<long long> count[3] = { std::vector<long long>(d[0]), std::vector<long long>(d[1]),
    std::vector<long long>(d[2]) };
  // Each voxel's own opacity once; the neighbour tests below read it back.
  const vtkIdType n = static_cast<vtkIdType>(d[0]) * d[1] * d[2];
  std::vector<char> opaque(static_cast<std::size_t>(n));
  for (vtkIdType v = 0; v < n; ++v)
  {
    const double x = a->GetComponent(v, 0);
    opaque[static_cast<std::size_t>(v)] = Visible(s, x, x) ? 1 : 0;
  }
  long long visible = 0;
  const bool isos = !s.isos.empty();
  const vtkIdType step[3] = { 1, d[0], static_cast<vtkIdType>(d[0]) * d[1] };
  for (int k = 0; k < d[2]; ++k)
  {
    for (int j = 0; j < d[1]; ++j)
    {
      const vtkIdType row = (static_cast<vtkIdType>(k) * d[1] + j) * d[0];
      for (int i = 0; i < d[0]; ++i)
      {
        const vtkIdType at = row + i;
        const int ijk[3] = { i, j, k };
        bool seen = false;
        if (opaque[static_cast<std::size_t>(at)])
        {
          // A visible voxel without a visible neighbour is noise (an MRI's hot voxels), not the object.
          for (int axis = 0; axis < 3 && !seen; ++axis)
          {
            seen = (ijk[axis] > 0 && opaque[static_cast<std::size_t>(at - step[axis])]) ||
              (ijk[axis] + 1 < d[axis] && opaque[static_cast<std::size_t>(at + step[axis])]);
          }
        }
        else if (isos)
        {
          // An iso-surface between this voxel and a neighbour along +x, +y or +z.
          const double v = a->GetComponent(at, 0);
          for (int axis = 0; axis < 3 && !seen; ++axis)
          {
            seen = ijk[axis] + 1 < d[axis] && Visible(s, v, a->GetComponent(at + step[axis], 0));
          }
        }
        if (seen)
        {
          ++count[0][i], ++count[1][j], ++count[2][k];
          ++visible;
        }
      }
    }
  }
  if (visible == 0)
  {
    return {};
  }
  const long long drop = visible / 2000;
  Box3 box;
  std::array<int, 2> r[3];
  for (int axis = 0; axis < 3; ++axis)
  {
    r[axis] = Trimmed(count[axis], drop);
    // Between samples the field is interpolated: a voxel's opacity reaches to its neighbours.
    r[axis][0] = std::max(0, r[axis][0] - 1);
    r[axis][1] = std::min(d[axis] - 1, r[axis][1] + 1);
  }
  for (int c = 0; c < 8; ++c)
  {
    const double ijk[3] = { double(e[0] + r[0][c & 1]), double(e[2] + r[1][(c >> 1) & 1]),
      double(e[4] + r[2][(c >> 2) & 1]) };
    double w[3];
    image->TransformContinuousIndexToPhysicalPoint(ijk, w);
    box.Expand({ w[0], w[1], w[2] });
  }
  return box;
}

Box3 VisibleBounds(const TetMesh& mesh, const RenderSettings& s)
{
  const std::vector<double>& v = mesh.Scalars();
  const std::vector<Vec3>& p = mesh.PointsArray();
  Box3 box;
  for (std::size_t t = 0; t < mesh.NumberOfTets(); ++t)
  {
    const std::array<int, 4>& q = mesh.Tet(t);
    const double lo = std::min({ v[q[0]], v[q[1]], v[q[2]], v[q[3]] });
    const double hi = std::max({ v[q[0]], v[q[1]], v[q[2]], v[q[3]] });
    if (Visible(s, lo, hi))
    {
      for (int k = 0; k < 4; ++k)
      {
        box.Expand(p[q[k]]);
      }
    }
  }
  return box;
}
} // namespace art
