// SurfaceTetrahedralizer: a closed surface to a quality tet mesh of the solid it bounds, to a tet
// budget or a volume bound (TetGenMesher, after CheckSurface). With a volume, the points carry its
// values, fitted to the voxels inside the mesh in the least-squares sense (LeastSquaresFit, Grosso,
// Luerig & Ertl, Vis '97, section 3, on the mesh placed in the volume's frame), and the tets where
// the fit misses the voxels most are refined (TetGen -r, a per-tet volume bound of a quarter of
// theirs) until the budget is met.
#ifndef art_SurfaceTetrahedralizer_h
#define art_SurfaceTetrahedralizer_h

#include "AdaptiveRTMeshingModule.h"
#include "SurfaceCheck.h"
#include "TetGenMesher.h"
#include "TetReducer.h"
#include "VoxelVolume.h"

#include <string>
#include <utility>
#include <vector>

namespace art
{
class Progress;

struct SurfaceMeshOptions
{
  long long TargetTets = 0;      ///< about this many tets (0: not set)
  double MaxVolume = -1;         ///< no tet larger (<= 0: not set)
  const VoxelVolume* Volume = nullptr; ///< values to fit (null: the mesh carries none)
  double RefineFraction = 0.2;   ///< share of the tets refined per round, those of most error first
  int MaxRounds = 16;
  double BudgetTolerance = 0.1;  ///< a count within this fraction of TargetTets meets it
  TetGenSettings TetGen;
};

struct SurfaceMeshResult
{
  ReducedMesh Mesh;           ///< points as the surface's; Values empty without a volume
  SurfaceReport Surface;
  double MeshVolume = 0;      ///< sum of the tets' volumes
  long long CoveredVoxels = 0; ///< the volume's voxels inside the mesh (the fit's)
  std::vector<std::pair<long long, double>> Rounds; ///< (tets, RMS) of each meshing (RMS NaN without values)
};

/// Checks `surface` (CheckSurface) and meshes it; throws art::Error naming `file` with
/// SurfaceReport::Problem for a surface TetGen must not see, or when TetGen fails.
ADAPTIVERTMESHING_EXPORT SurfaceMeshResult TetrahedralizeSurface(TriangleSurface surface,
  const SurfaceMeshOptions& options, const std::string& file = {}, Progress* progress = nullptr);
} // namespace art

#endif
