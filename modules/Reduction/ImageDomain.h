// ImageDomain: a request to mesh the voxels of a region or of a label map with tets whose boundary
// follows the region's surface (and the interfaces between labels), and the mesh that comes back.
// vtkImageDomainMesher meshes it (CGAL's Mesh_3 in AdaptiveRT::Meshing). Coordinates are the
// voxels' scaled index space: voxel (i, j, k) sits at (i sx, j sy, k sz).
#ifndef art_ImageDomain_h
#define art_ImageDomain_h

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace art
{
/// A scalar field on a regular grid of nodes (Step apart from the origin), trilinear between
/// them and clamped outside: the mesh size and the boundary's distance bound, place by place.
struct SizeGrid
{
  int Dims[3] = { 1, 1, 1 };
  double Step = 1;
  std::vector<float> Values = { 1.f };

  double At(const double p[3]) const
  {
    int i0[3];
    double f[3];
    for (int a = 0; a < 3; ++a)
    {
      const double u = std::clamp(p[a] / Step, 0.0, static_cast<double>(Dims[a] - 1));
      i0[a] = std::min(static_cast<int>(u), std::max(Dims[a] - 2, 0));
      f[a] = Dims[a] > 1 ? u - i0[a] : 0.0;
    }
    double s = 0;
    for (int c = 0; c < 8; ++c)
    {
      const int di = c & 1, dj = (c >> 1) & 1, dk = (c >> 2) & 1;
      const int i = std::min(i0[0] + di, Dims[0] - 1), j = std::min(i0[1] + dj, Dims[1] - 1),
                k = std::min(i0[2] + dk, Dims[2] - 1);
      const double w = (di ? f[0] : 1 - f[0]) * (dj ? f[1] : 1 - f[1]) * (dk ? f[2] : 1 - f[2]);
      s += w * Values[static_cast<size_t>(i + Dims[0] * (j + static_cast<long long>(Dims[1]) * k))];
    }
    return s;
  }
  static SizeGrid Constant(double v)
  {
    SizeGrid g;
    g.Values = { static_cast<float>(v) };
    return g;
  }
};

struct ImageDomainRequest
{
  int Dims[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  /// A region by value: where the trilinear interpolant of Values lies in [Lo, Hi].
  const float* Values = nullptr;
  double Lo = 0, Hi = 0;
  /// Or a label map: each voxel's subdomain (0 outside, 1.. inside), with optional weights
  /// (0..255 per voxel) that smooth its surfaces (Stalling, Zoeckler & Hege 1998).
  const int32_t* Slots = nullptr;
  const uint8_t* Weights = nullptr;
  SizeGrid Size;     ///< bound on the tets' and the boundary facets' circumradius
  SizeGrid Distance; ///< bound on the boundary facets' distance to the surface
  double FacetAngle = 25;   ///< degrees, lower bound on the boundary facets' angles
  double RadiusEdge = 3;    ///< upper bound on the tets' circumradius over shortest edge
  double RelativeError = 1e-5; ///< precision of surface points, relative to the box's diagonal
  bool Exude = true;        ///< remove slivers (sliver exudation) after refinement
};

struct ImageDomainMesh
{
  std::vector<double> Points; ///< x y z per vertex, scaled index space
  std::vector<int> Tets;      ///< 4 vertex ids per tet, positively oriented
  std::vector<int> Subdomain; ///< per tet: 1 for a region, the slot for a label map
  double Seconds = 0;
};
} // namespace art

#endif
