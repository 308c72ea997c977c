// WholeBoxComparison: the tets the whole-box reducer (TetReducer, plain L2, bisection) needs for
// the error a region reduction reached inside its region, the figure that says what modelling
// only the region saves. The region's voxels are scored on each level of one whole-box run
// (budgets a factor 1.4 apart) and the run stops at the first level whose RMS over them is at
// most the target; the count is interpolated between the last two levels in log-log (a P1 fit's
// error falls about as N^(-2/3) between them).
#ifndef art_WholeBoxComparison_h
#define art_WholeBoxComparison_h

#include "AdaptiveRTReductionModule.h"
#include "TetReducer.h"
#include "VoxelVolume.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace art
{
class Progress;

struct WholeBoxFigures
{
  long long Tets = 0;       ///< interpolated: the whole-box tets of equal error inside the region
  bool Reached = false;     ///< false: not by MaxTets (Tets is then the last level's)
  double Seconds = 0;
  std::vector<std::pair<long long, double>> Levels; ///< (tets, RMS inside the region) of each level
};

/// RMS and max of |f - fit| over the voxels with inside[i] != 0 that `mesh` (a TetReducer level of
/// `volume`: its vertices on the lattice) covers, and how many those are.
struct MaskedError
{
  double Rms = 0, Max = 0;
  long long Voxels = 0;
};
ADAPTIVERTREDUCTION_EXPORT MaskedError ErrorInside(
  const VoxelVolume& volume, const std::vector<uint8_t>& inside, const ReducedMesh& mesh);

/// Runs the whole-box reduction of `volume` from `startTets` up to `maxTets` until its RMS over the
/// voxels with inside[i] != 0 is at most `targetRms`. `progress` (optional) sees the run's
/// fraction and may cancel it.
ADAPTIVERTREDUCTION_EXPORT WholeBoxFigures WholeBoxForRegionError(const VoxelVolume& volume,
  const std::vector<uint8_t>& inside, double targetRms, long long startTets, long long maxTets,
  Progress* progress = nullptr);
} // namespace art

#endif
