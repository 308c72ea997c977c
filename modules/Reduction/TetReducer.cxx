#include "TetReducer.h"

#include "AvailableMemory.h"
#include "BisectionMesh.h"
#include "EdgeSplitRefiner.h"
#include "Error.h"
#include "LeastSquaresFit.h"
#include "MeanSpacing.h"
#include "OpacityImportance.h"
#include "Progress.h"
#include "VertexRelocator.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <cmath>
#include <numeric>
#include <optional>

namespace art
{
void TetReducer::CoarseGrid(const VoxelVolume& volume, long long tets, int cubes[3])
{
  // Boxes about cubic in world units, but never more than twice as many voxels along one axis as
  // along another: bisection stops at edges of MinEdgeVoxels, so a box only one voxel thick along
  // thick slices stops the other axes at a few times the box's voxels. A 30 x 30 x 8 cylinder of
  // 0.4 x 0.4 x 5 mm voxels reduced to 2000 tets had an RMS of 354 (80 at 1 x 1 x 1 mm); 228 now.
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
// The fitted values as output: clamped to the range of the voxels under each vertex's tets,
// all of them (clamp) or those more opaque than those voxels (cap).
std::vector<double> OutputValues(const BisectionMesh& mesh, const LeastSquaresFit& fit,
  std::vector<double> x, bool clamp, const OpacityImportance* cap)
{
  if (clamp || cap)
  {
    std::vector<double> lo, hi;
    fit.VertexVoxelRange(mesh, lo, hi);
    for (std::size_t v = 0; v < lo.size(); ++v)
    {
      // A vertex over no voxel centre (lo > hi) keeps its fitted value.
      const bool over = lo[v] <= hi[v] && (clamp || cap->Opacity(x[v]) > cap->MaxOpacity(lo[v], hi[v]));
      x[v] = over ? std::min(hi[v], std::max(lo[v], x[v])) : x[v];
    }
  }
  return x;
}

// The output values x of `mesh` and their errors e (LeastSquaresFit::VoxelErrors) as a level.
ReducedMesh Snapshot(const VoxelVolume& vol, const BisectionMesh& mesh, const std::vector<double>& x,
  VoxelErrorReport e)
{
  ReducedMesh out;
  out.TetRms = std::move(e.TetRms);
  out.TetMax = std::move(e.TetMax);
  out.Rms = e.Rms;
  out.Max = e.Max;
  out.WeightedRms = e.WeightedRms;
  out.WeightedMax = e.WeightedMax;
  const int nv = mesh.NumberOfVertices(), nt = mesh.NumberOfTets();
  out.Points.resize(3 * static_cast<size_t>(nv));
  const double S = static_cast<double>(BisectionMesh::Scale);
  for (int v = 0; v < nv; ++v)
  {
    const LatticePoint& p = mesh.Vertex(v);
    const double ijk[3] = { p.x / S, p.y / S, p.z / S };
    vol.IndexToWorld(ijk, &out.Points[3 * static_cast<size_t>(v)]);
  }
  out.Values.assign(x.begin(), x.begin() + nv);
  out.Tets.resize(4 * static_cast<size_t>(nt));
  for (int t = 0; t < nt; ++t)
  {
    auto v = mesh.Tet(t);
    const double* p[4];
    for (int a = 0; a < 4; ++a)
    {
      p[a] = &out.Points[3 * static_cast<size_t>(v[a])];
    }
    double e[3][3];
    for (int a = 0; a < 3; ++a)
    {
      for (int d = 0; d < 3; ++d)
      {
        e[a][d] = p[a + 1][d] - p[0][d];
      }
    }
    const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
      e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    if (det < 0)
    {
      std::swap(v[1], v[2]); // VTK_TETRA wants (p1-p0)x(p2-p0).(p3-p0) > 0
    }
    std::copy(v.begin(), v.end(), out.Tets.begin() + 4 * static_cast<size_t>(t));
  }
  out.Range[0] = vol.Range[0];
  out.Range[1] = vol.Range[1];
  out.SourceSpacing = MeanVoxelSpacing(vol.Dims, vol.Spacing); // a preset's unit distance follows it
  out.Source = vol.Statistics;
  out.ScalarName = vol.Name;
  return out;
}

// Peak bytes a tet of the mesh costs (measured with /usr/bin/time -v on the CT resampled to 200^3
// and 300^3, 80k to 800k tets), with the relocator's own arrays or without.
double BytesPerTet(bool relocate)
{
  return relocate ? 570.0 : 350.0;
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
  const double perTet = BytesPerTet(Opt.RelocateVertices);
  const double perVoxel = Opt.ScalarOpacity.empty() ? 0.0 : 28.0;
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
  // alive beside the new (under a 1.2 GB cap, counting only the added tets ran out of memory).
  const double need = BytesPerTet(Opt.RelocateVertices) * double(std::max(0LL, next));
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
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const long long nvox = volume.NumberOfVoxels();
  if (volume.Dims[0] < 2 || volume.Dims[1] < 2 || volume.Dims[2] < 2)
  {
    throw Error("a 2-D or empty image cannot be reduced to tetrahedra");
  }
  const bool haveError = Opt.TargetError >= 0;
  std::vector<long long> budgets = Opt.Levels;
  if (Opt.TargetTets > 0)
  {
    budgets.push_back(Opt.TargetTets);
  }
  for (long long b : budgets)
  {
    if (b < 6)
    {
      throw Error("a tet budget must be at least 6 (one box), got " + std::to_string(b));
    }
  }
  std::sort(budgets.begin(), budgets.end());
  budgets.erase(std::unique(budgets.begin(), budgets.end()), budgets.end());
  if (budgets.empty() && !haveError)
  {
    throw Error("set a target tet count or a maximum error");
  }
  CheckMemory(volume, AvailableMemoryBytes());
  // Without a tet budget the error bound alone decides, up to one tet per voxel (beyond that
  // nothing is reduced any more). A budget is capped at the full-resolution tetrahedrisation
  // (5 tets per voxel cell): refinement cannot go past it, and the progress is measured to it.
  const long long cells = (volume.Dims[0] - 1LL) * (volume.Dims[1] - 1) * (volume.Dims[2] - 1);
  const long long cap = std::min(5 * cells,
    Opt.TargetTets > 0 ? Opt.TargetTets
                       : (haveError ? std::max<long long>(nvox, budgets.empty() ? 0 : budgets.back()) : budgets.back()));
  const double errorBound =
    haveError ? Opt.TargetError * (Opt.ErrorRelative ? (volume.Range[1] - volume.Range[0]) : 1.0) : -1.0;
  const bool maxMetric = Opt.ErrorMetric == ReducerOptions::Metric::Max;
  const double range = std::max(volume.Range[1] - volume.Range[0], 1e-300);

  BisectionMesh mesh;
  int cubes[3];
  const long long smallest = budgets.empty() ? nvox / 2000 : budgets.front();
  CoarseGrid(volume, Opt.CoarseTets > 0 ? Opt.CoarseTets : std::max<long long>(6, smallest / 4), cubes);
  mesh.InitKuhn(volume.Dims, cubes);
  const int n0 = mesh.NumberOfTets();

  // The stage starts before the weights and the first fit: on a 400 x 400 x 300 volume they took 7 s
  // in which no progress was shown.
  if (progress)
  {
    progress->Begin("reduce", 1.0);
  }
  double reported = 0, firstError = -1;
  auto advanceTo = [&](double f) {
    if (progress && f > reported)
    {
      progress->Advance(f - reported);
      reported = f;
    }
  };
  // The first fit's passes over every voxel come first, then the refinement up to 95%; the last
  // 5% (End) is the output's values and their errors over every voxel. Units of the first fit:
  // the first gather 2, and when weighted the weights' set-up 1 and each reweighing step 1
  // (it gathers only the tets whose weights can change). Their share of the bar is their count
  // against half a unit per level to come (levels gather only the tets they change): a
  // 512 x 512 x 400 CT weighted to 200k tets spent 35 s of 69 in them, its bar at 0% throughout.
  const bool weighing = !Opt.ScalarOpacity.empty();
  const int reweighs = weighing ? std::max(0, Opt.ReweighSteps) : 0;
  const double units = 2.0 + (weighing ? 1.0 + reweighs : 0.0);
  const double levelsToGo =
    std::max(1.0, std::log(std::max(2.0, double(cap) / n0)) / std::log(1.0 + (Opt.RefineFraction > 0 ? Opt.RefineFraction : 0.2)));
  const double startShare = 0.95 * units / (units + 0.5 * levelsToGo);
  double unitsDone = 0;
  auto during = [&](double size) {
    return [&, size, from = unitsDone](double f) { advanceTo(startShare * (from + size * f) / units); };
  };
  std::unique_ptr<OpacityImportance> importance;
  if (weighing)
  {
    importance = std::make_unique<OpacityImportance>(Opt.ScalarOpacity);
    importance->SetIsoValues(Opt.IsoValues);
    importance->Prepare(volume, Opt.ImportanceFloor, Opt.ImportanceRadius, during(1.0));
    unitsDone += 1.0;
  }
  const bool weighted = importance != nullptr;
  const OpacityImportance* opacityCap = Opt.CapOpacity ? importance.get() : nullptr;
  LeastSquaresFit fit(volume, Opt.Regularization, importance.get());
  std::vector<int> touched(n0), all;
  std::iota(touched.begin(), touched.end(), 0);
  fit.UpdateMoments(mesh, touched, nullptr, during(2.0));
  unitsDone += 2.0;
  std::vector<double> x;
  int iterations = fit.Solve(mesh, x, Opt.SolverTolerance);
  // The weighted fit is iteratively reweighted: the weights are taken at the current fit, so
  // every tet's moments are brought to it before each solve. Only tets whose voxels can weigh
  // differently are re-gathered (Reweigh: exact); gathering only the tets a refinement touched
  // was measured 0.2-0.3 dB worse in the rendered image at 100k-250k tets (stale weights).
  auto reweigh = [&](const LeastSquaresFit::Done& done) {
    LeastSquaresFit::Extend(mesh, x);
    fit.Reweigh(mesh, x, done);
    iterations += fit.Solve(mesh, x, Opt.SolverTolerance);
  };
  for (int k = 0; k < reweighs; ++k)
  {
    reweigh(during(1.0));
    unitsDone += 1.0;
  }
  advanceTo(startShare);

  // Refinement fills the bar from the first fit's share to 95%.
  auto report = [&](double f) { advanceTo(std::min(0.95, startShare + (0.95 - startShare) * f)); };

  // The output values of the lattice mesh and their errors, kept from an error check at this
  // level for the level it emits (two voxel passes otherwise done again).
  std::optional<std::pair<std::vector<double>, VoxelErrorReport>> checked;
  auto outputErrors = [&]() -> VoxelErrorReport& {
    std::vector<double> y = OutputValues(mesh, fit, x, Opt.ClampToVoxels, opacityCap);
    VoxelErrorReport e = fit.VoxelErrors(mesh, y);
    checked.emplace(std::move(y), std::move(e));
    return checked->second;
  };
  std::vector<ReducedMesh> out;
  auto emit = [&](long long budget, bool reached, int level) {
    ReducedMesh m;
    if (Opt.RelocateVertices)
    {
      // On a copy: the next level refines the lattice mesh, not the moved one.
      BisectionMesh moved = mesh;
      std::vector<double> y = x;
      LeastSquaresFit::Extend(moved, y);
      RelocationOptions ro;
      ro.Sweeps = Opt.RelocateSweeps;
      ro.QualityFloor = Opt.RelocateQualityFloor;
      ro.MeasureSse = false;
      VertexRelocator::Relocate(moved, volume, y, ro, importance.get(), progress);
      if (progress)
      {
        // Back to the reduction's own stage, where it was (not from 0%).
        progress->Begin("reduce", 1.0 - reported, reported, 1.0);
      }
      LeastSquaresFit refit(volume, Opt.Regularization, importance.get());
      std::vector<int> every(static_cast<size_t>(moved.NumberOfTets()));
      std::iota(every.begin(), every.end(), 0);
      refit.UpdateMoments(moved, every, &y);
      refit.Solve(moved, y, Opt.SolverTolerance);
      y = OutputValues(moved, refit, std::move(y), Opt.ClampToVoxels, opacityCap);
      m = Snapshot(volume, moved, y, refit.VoxelErrors(moved, y));
    }
    else
    {
      if (!checked)
      {
        outputErrors();
      }
      m = Snapshot(volume, mesh, checked->first, std::move(checked->second));
      checked.reset();
    }
    m.TargetTets = budget;
    m.TargetError = errorBound;
    m.TargetReached = reached;
    m.RefinementLevels = level;
    m.SolverIterations = iterations;
    m.BuildSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    m.Weighted = weighted;
    if (onLevel)
    {
      onLevel(m);
    }
    out.push_back(std::move(m));
  };

  size_t bi = 0;
  // The refinement stops short: every budget left and the error bound are emitted as not reached.
  auto unreached = [&](int level) {
    for (; bi < budgets.size(); ++bi)
    {
      emit(budgets[bi], false, level);
    }
    if (haveError && (out.empty() || out.back().NumberOfTets() != mesh.NumberOfTets()))
    {
      emit(0, false, level);
    }
  };
  std::vector<double> priority;
  const bool edgeSplit = Opt.Refine == ReducerOptions::Refinement::EdgeSplit;
  // Automatic growth: bisection takes half a level while far from the next budget (cheap levels,
  // each still a voxel pass when weighted) and a fifth over the last factor of 4 before it.
  auto growthTowards = [&](long long nt, long long goal) {
    if (Opt.RefineFraction > 0)
    {
      return Opt.RefineFraction;
    }
    return edgeSplit || nt * 4 > goal ? 0.2 : 0.5;
  };
  std::vector<EdgeSplitMoments> edgeMoments;
  for (int level = 0;; ++level)
  {
    if (progress && progress->Cancelled())
    {
      throw Error("cancelled");
    }
    checked.reset(); // the mesh or the fit changed
    const long long nt = mesh.NumberOfTets();
    while (bi < budgets.size() && nt >= budgets[bi])
    {
      emit(budgets[bi], true, level);
      ++bi;
    }
    // The error that decides: cached moments give the squared error per tet for free; the
    // max needs a pass over the voxels.
    // An error bound holds for the values output, clamped or capped (a few percent above the fit's).
    const bool clamped = Opt.ClampToVoxels || opacityCap;
    double global;
    if (maxMetric && haveError)
    {
      VoxelErrorReport& e = outputErrors();
      priority = e.TetWeightedMax;
      global = e.WeightedMax;
    }
    else if (weighted)
    {
      // Weighted squared errors from the moments, whose weights were gathered at this level's
      // starting fit (a second voxel pass per level for the weights at the solved fit changed
      // the image by under 0.1 dB). An error bound that looks met is confirmed at the solved fit,
      // since the weight follows the fit (a stray into an opacity ramp counts).
      fit.SquaredErrors(mesh, x, priority);
      global = std::sqrt(std::accumulate(priority.begin(), priority.end(), 0.0) / nvox);
      if (haveError && global <= errorBound)
      {
        reweigh({});
        VoxelErrorReport& e = outputErrors();
        priority = e.TetWeightedSse;
        global = e.WeightedRms;
      }
    }
    else
    {
      fit.SquaredErrors(mesh, x, priority);
      global = std::sqrt(std::accumulate(priority.begin(), priority.end(), 0.0) / nvox);
      if (haveError && global <= errorBound && clamped)
      {
        VoxelErrorReport& e = outputErrors();
        priority = e.TetWeightedSse;
        global = e.WeightedRms;
      }
    }
    if (haveError && global <= errorBound)
    {
      if (out.empty() || out.back().NumberOfTets() != nt)
      {
        emit(0, true, level);
      }
      break;
    }
    if (!haveError && bi == budgets.size())
    {
      break;
    }
    if (nt >= cap)
    {
      unreached(level);
      break;
    }
    const long long goal = bi < budgets.size() ? std::min(cap, budgets[bi]) : cap;
    const long long next = std::min(goal,
      std::max(nt + 1, static_cast<long long>(std::ceil(nt * (1.0 + growthTowards(nt, goal))))));
    if (bi == budgets.size())
    {
      CheckGrowth(volume, nt, next, AvailableMemoryBytes()); // an error bound alone: no budget was checked
    }

    std::vector<int> cand;
    const double minEdge2 = Opt.MinEdgeVoxels * Opt.MinEdgeVoxels;
    for (int t = 0; t < nt; ++t)
    {
      // Squared errors at round-off level are not worth a tet.
      const TetMoments& mt = fit.Moments(t);
      const double roundOff = std::max(1e-24 * range * range * std::max(1, mt.Count), 1e-10 * mt.G);
      const double threshold = (maxMetric && haveError) ? std::max(errorBound, 1e-12 * range) : roundOff;
      if (priority[t] > threshold && (edgeSplit ? EdgeSplitRefiner::CanRefine(mesh, t, minEdge2)
                                                 : mesh.RefinementEdgeLength2(t) >= minEdge2 && mesh.CanBisect(t)))
      {
        cand.push_back(t);
      }
    }
    if (cand.empty())
    {
      // Nothing left to refine: the field is matched as well as this resolution allows.
      unreached(level);
      break;
    }
    std::sort(cand.begin(), cand.end(), [&](int a, int b) {
      return priority[a] != priority[b] ? priority[a] > priority[b] : a < b;
    });
    std::vector<uint32_t> version(nt);
    for (int t = 0; t < nt; ++t)
    {
      version[t] = mesh.Version(t);
    }
    if (edgeSplit)
    {
      // Edge moments of the tets the last level made (`touched` still lists them); weighted, the
      // weights moved with the fit, so all of them, as reweigh does.
      if (weighted || edgeMoments.empty())
      {
        all.resize(static_cast<size_t>(nt));
        std::iota(all.begin(), all.end(), 0);
        fit.EdgeMoments(mesh, all, edgeMoments, &x);
      }
      else
      {
        fit.EdgeMoments(mesh, touched, edgeMoments);
      }
    }
    touched.clear();
    if (edgeSplit)
    {
      EdgeSplitRefiner::RefineLevel(mesh, cand, version, edgeMoments, x, minEdge2, next, touched);
    }
    else
    {
      for (int t : cand)
      {
        if (mesh.Version(t) != version[t])
        {
          continue; // already cut by the closure of a worse tet
        }
        mesh.Refine(t, touched);
        if (mesh.NumberOfTets() >= next)
        {
          break;
        }
      }
    }
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    if (weighted)
    {
      reweigh({});
    }
    else
    {
      fit.UpdateMoments(mesh, touched);
      iterations += fit.Solve(mesh, x, Opt.SolverTolerance);
    }

    if (haveError && budgets.empty())
    {
      firstError = firstError < 0 ? global : firstError;
      if (firstError > errorBound && errorBound > 0)
      {
        report(std::log(firstError / global) / std::log(firstError / errorBound));
      }
    }
    else
    {
      report(std::log(double(mesh.NumberOfTets()) / n0) / std::log(double(std::max<long long>(cap, n0 + 1)) / n0));
    }
  }
  if (progress)
  {
    progress->End();
  }
  return out;
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
