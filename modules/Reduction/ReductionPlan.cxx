#include "ReductionPlan.h"

#include "Error.h"

#include <algorithm>
#include <string>

namespace art
{
ReductionPlan ReductionPlan::For(const ReducerOptions& opt, const VoxelVolume& volume)
{
  if (volume.Dims[0] < 2 || volume.Dims[1] < 2 || volume.Dims[2] < 2)
  {
    throw Error("a 2-D or empty image cannot be reduced to tetrahedra");
  }
  ReductionPlan p;
  p.HaveError = opt.TargetError >= 0;
  p.Budgets = opt.Levels;
  if (opt.TargetTets > 0)
  {
    p.Budgets.push_back(opt.TargetTets);
  }
  for (long long b : p.Budgets)
  {
    if (b < 6)
    {
      throw Error("a tet budget must be at least 6 (one box), got " + std::to_string(b));
    }
  }
  std::sort(p.Budgets.begin(), p.Budgets.end());
  p.Budgets.erase(std::unique(p.Budgets.begin(), p.Budgets.end()), p.Budgets.end());
  if (p.Budgets.empty() && !p.HaveError)
  {
    throw Error("set a target tet count or a maximum error");
  }
  const long long nvox = volume.NumberOfVoxels();
  const long long cells = (volume.Dims[0] - 1LL) * (volume.Dims[1] - 1) * (volume.Dims[2] - 1);
  p.Cap = std::min(5 * cells,
    opt.TargetTets > 0 ? opt.TargetTets
                       : (p.HaveError ? std::max<long long>(nvox, p.Budgets.empty() ? 0 : p.Budgets.back()) : p.Budgets.back()));
  p.ErrorBound =
    p.HaveError ? opt.TargetError * (opt.ErrorRelative ? (volume.Range[1] - volume.Range[0]) : 1.0) : -1.0;
  p.MaxMetric = opt.ErrorMetric == ReducerOptions::Metric::Max;
  return p;
}
} // namespace art
