// ReductionPlan: what a reducer run is asked for, checked once for every refinement: the tet
// budgets (ascending, each at least one box), the error bound in data units, and the tets the
// refinement may go up to.
#ifndef art_ReductionPlan_h
#define art_ReductionPlan_h

#include "TetReducer.h"
#include "VoxelVolume.h"

#include <chrono>
#include <vector>

namespace art
{
struct ReductionPlan
{
  std::vector<long long> Budgets; ///< the levels and the target, ascending, without repeats
  bool HaveError = false;         ///< an error bound is set
  double ErrorBound = -1;         ///< in data units (< 0: none)
  bool MaxMetric = false;         ///< the bound is on the max error, not the RMS
  /// Refinement stops here: the target, else (an error bound alone) one tet per voxel, and
  /// never past the full-resolution tetrahedrisation (5 tets per voxel cell).
  long long Cap = 0;
  std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();

  /// Throws art::Error for a 2-D volume, a budget under 6 tets, or neither budget nor bound.
  static ReductionPlan For(const ReducerOptions& opt, const VoxelVolume& volume);
  /// Seconds since the run started.
  double Elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - Start).count(); }
};
} // namespace art

#endif
