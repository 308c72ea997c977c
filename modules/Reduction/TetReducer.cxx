#include "TetReducer.h"

#include "AnisotropicAdaptation.h"
#include "AvailableMemory.h"
#include "Error.h"
#include "LatticeRefinement.h"
#include "ReductionPlan.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace art
{
void TetReducer::CoarseGrid(const VoxelVolume& volume, long long tets, int cubes[3])
{
  // Boxes about cubic in world units, but never more than twice as many voxels along one axis as
  // along another: bisection stops at edges of MinEdgeVoxels, so a box only one voxel thick along
  // thick slices would stop the other axes at a few times the box's voxels.
  double L[3];
  const double smin = std::min({ std::fabs(volume.Spacing[0]), std::fabs(volume.Spacing[1]), std::fabs(volume.Spacing[2]) });
  for (int a = 0; a < 3; ++a)
  {
    L[a] = std::max(1e-30, (volume.Dims[a] - 1) * std::min(std::fabs(volume.Spacing[a]), 2.0 * smin));
  }
  const double boxes = std::max(1.0, std::min(512.0, tets / 6.0));
  const double h = std::cbrt(L[0] * L[1] * L[2] / boxes);
  for (int a = 0; a < 3; ++a)
  {
    cubes[a] = std::max(1, std::min(volume.Dims[a] - 1, static_cast<int>(std::lround(L[a] / h))));
  }
  // Rounding up may overshoot the budget: shrink the longest axis until it fits.
  while (6LL * cubes[0] * cubes[1] * cubes[2] > std::max<long long>(6, tets))
  {
    int a = 0;
    for (int b = 1; b < 3; ++b)
    {
      if (L[b] / cubes[b] < L[a] / cubes[a] && cubes[b] > 1)
      {
        a = b;
      }
    }
    if (cubes[a] == 1)
    {
      a = static_cast<int>(std::max_element(cubes, cubes + 3) - cubes);
    }
    --cubes[a];
  }
}

namespace
{
// Peak bytes a tet of the mesh costs (measured peaks of reduce on CTs of 200^3 and 300^3 voxels),
// with the relocator's own arrays or without, or MMG's mesh and the fit of an anisotropic one.
double BytesPerTet(const ReducerOptions& o)
{
  if (o.Refine == ReducerOptions::Refinement::Anisotropic)
  {
    return AnisotropicAdaptation::BytesPerTet();
  }
  return o.RelocateVertices ? 570.0 : 350.0;
}
} // namespace

double TetReducer::MemoryNeeded(long long voxels) const
{
  long long tets = Opt.TargetTets;
  for (long long b : Opt.Levels)
  {
    tets = std::max(tets, b);
  }
  // Refinement ends at the full-resolution tets, 5 a voxel cell.
  tets = std::min(tets, 5 * std::max(voxels, 0LL));
  const double perTet = BytesPerTet(Opt);
  const double perVoxel = (Opt.ScalarOpacity.empty() ? 0.0 : 28.0) +
    (Opt.Refine == ReducerOptions::Refinement::Anisotropic ? AnisotropicAdaptation::BytesPerVoxel() : 0.0);
  return perTet * double(tets) + perVoxel * double(voxels);
}

void TetReducer::CheckMemory(const VoxelVolume& volume, double availableBytes) const
{
  const long long voxels = volume.NumberOfVoxels();
  const double need = MemoryNeeded(voxels);
  if (!ExceedsAvailableMemory(need, availableBytes))
  {
    return;
  }
  char msg[600];
  std::snprintf(msg, sizeof msg,
    "reducing this volume of %d x %d x %d = %lld voxels%s needs about %.3g GB more, more than the %.3g GB of "
    "memory available; crop or resample it first (e.g. vtkImageResample, ParaView's Resample To Image or "
    "Extract Subset)%s",
    volume.Dims[0], volume.Dims[1], volume.Dims[2], voxels,
    Opt.ScalarOpacity.empty() ? "" : " weighted by a transfer function's opacity", need / 1e9, availableBytes / 1e9,
    Opt.ScalarOpacity.empty() ? ", or ask for fewer tets"
                              : ", or reduce it without a transfer function (28 bytes a voxel fewer)");
  throw Error(msg, volume.File);
}

void TetReducer::CheckGrowth(const VoxelVolume& volume, long long tets, long long next, double availableBytes) const
{
  // The whole next mesh, not only the tets added: its arrays grow by reallocation, the old copy
  // alive beside the new.
  const double need = BytesPerTet(Opt) * double(std::max(0LL, next));
  if (!ExceedsAvailableMemory(need, availableBytes))
  {
    return;
  }
  char msg[500];
  std::snprintf(msg, sizeof msg,
    "the error bound is not met at %lld tets, and refining to %lld would need about %.3g GB, more than the "
    "%.3g GB of memory available; set a tet budget (--tets N) or a larger error bound, or crop or resample the "
    "volume first",
    tets, next, need / 1e9, availableBytes / 1e9);
  throw Error(msg, volume.File);
}

std::vector<ReducedMesh> TetReducer::Run(const VoxelVolume& volume, Progress* progress,
  const std::function<void(const ReducedMesh&)>& onLevel) const
{
  const ReductionPlan plan = ReductionPlan::For(Opt, volume);
  CheckMemory(volume, AvailableMemoryBytes());
  if (Opt.Refine == ReducerOptions::Refinement::Anisotropic)
  {
    return ReduceAnisotropic(volume, Opt, plan, progress, onLevel);
  }
  return LatticeRefinement(*this, volume, plan, progress, onLevel).Run();
}

std::vector<long long> UnreachedLevels(const std::vector<long long>& levels, const std::vector<ReducedMesh>& meshes)
{
  std::vector<long long> missing;
  for (long long b : levels)
  {
    if (std::none_of(meshes.begin(), meshes.empty() ? meshes.end() : meshes.end() - 1,
          [b](const ReducedMesh& m) { return m.TargetTets == b; }) &&
      std::find(missing.begin(), missing.end(), b) == missing.end())
    {
      missing.push_back(b);
    }
  }
  return missing;
}
} // namespace art
