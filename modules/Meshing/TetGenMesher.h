// TetGenMesher: constrained Delaunay tetrahedralisation of a closed surface with quality
// refinement (TetGen 1.5: Si, "TetGen, a Delaunay-based quality tetrahedral mesh generator",
// ACM TOMS 41(2), 2015), through its library interface: -p (the surface is kept as the boundary),
// -q (radius-edge ratio and dihedral bounds), -a (volume bounds, global or per tet), -r (refine a
// mesh made before). The only file that drives TetGen; the surface must have passed
// CheckSurface first (TetGen crashes on some that do not). TetGen is AGPL-3.0.
#ifndef art_TetGenMesher_h
#define art_TetGenMesher_h

#include "AdaptiveRTMeshingModule.h"
#include "SurfaceCheck.h"

#include <vector>

namespace art
{
struct TetGenSettings
{
  double RadiusEdge = 1.414; ///< -q: largest circumradius over shortest edge
  double MinDihedral = 10;   ///< -q: smallest dihedral angle, degrees
  double MaxVolume = -1;     ///< -a: largest tet volume (<= 0: none)
};

struct TetGenMesh
{
  std::vector<double> Points; ///< x y z per point
  std::vector<int> Tets;      ///< 4 per tet, positively oriented
  long long NumberOfTets() const { return static_cast<long long>(Tets.size() / 4); }
};

/// Tetrahedralises the solid `surface` bounds. Throws art::Error (without a file) when TetGen
/// fails, with what it said.
ADAPTIVERTMESHING_EXPORT TetGenMesh MeshSurface(const TriangleSurface& surface, const TetGenSettings& settings);

/// Refines `mesh` (a TetGenMesh) so that tet t is at most maxVolume[t] (<= 0: unbounded), keeping
/// its boundary and the quality bounds.
ADAPTIVERTMESHING_EXPORT TetGenMesh RefineMesh(
  const TetGenMesh& mesh, const std::vector<double>& maxVolume, const TetGenSettings& settings);

/// Volume of every tet, and their sum.
ADAPTIVERTMESHING_EXPORT std::vector<double> TetVolumes(const TetGenMesh& mesh, double* total = nullptr);
} // namespace art

#endif
