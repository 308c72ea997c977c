#include "LatticeRefinement.h"

#include "AvailableMemory.h"
#include "Error.h"
#include "Progress.h"
#include "ReducedLevel.h"
#include "VertexRelocator.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace art
{
LatticeRefinement::LatticeRefinement(const TetReducer& reducer, const VoxelVolume& volume, const ReductionPlan& plan,
  Progress* progress, std::function<void(const ReducedMesh&)> onLevel)
  : Reducer(reducer)
  , Opt(reducer.Options())
  , Volume(volume)
  , Plan(plan)
  , Prog(progress)
  , OnLevel(std::move(onLevel))
{
  int cubes[3];
  const long long smallest = Plan.Budgets.empty() ? volume.NumberOfVoxels() / 2000 : Plan.Budgets.front();
  TetReducer::CoarseGrid(volume, Opt.CoarseTets > 0 ? Opt.CoarseTets : std::max<long long>(6, smallest / 4), cubes);
  Mesh.InitKuhn(volume.Dims, cubes);
  N0 = Mesh.NumberOfTets();
}

void LatticeRefinement::AdvanceTo(double f)
{
  if (Prog && f > Reported)
  {
    Prog->Advance(f - Reported);
    Reported = f;
  }
}

std::function<void(double)> LatticeRefinement::During(double size)
{
  return [this, size, from = UnitsDone](double f) { AdvanceTo(StartShare * (from + size * f) / Units); };
}

void LatticeRefinement::StartProgress()
{
  // The stage starts before the weights and the first fit, which take seconds on a large volume.
  if (Prog)
  {
    Prog->Begin("reduce", 1.0);
  }
  // The first fit's passes over every voxel come first, then the refinement up to 95%; the last
  // 5% (End) is the output's values and their errors over every voxel. Units of the first fit:
  // the first gather 2, and when weighted the weights' set-up 1 and each reweighing step 1 (it
  // gathers only the tets whose weights can change). Their share of the bar is their count
  // against half a unit per level to come (levels gather only the tets they change).
  const bool weighing = !Opt.ScalarOpacity.empty();
  const int reweighs = weighing ? std::max(0, Opt.ReweighSteps) : 0;
  Units = 2.0 + (weighing ? 1.0 + reweighs : 0.0);
  const double levelsToGo = std::max(1.0,
    std::log(std::max(2.0, double(Plan.Cap) / N0)) / std::log(1.0 + (Opt.RefineFraction > 0 ? Opt.RefineFraction : 0.2)));
  StartShare = 0.95 * Units / (Units + 0.5 * levelsToGo);
}

void LatticeRefinement::Reweigh(const LeastSquaresFit::Done& done)
{
  // The weighted fit is iteratively reweighted: the weights are taken at the current fit, so
  // every tet's moments are brought to it before each solve. Only tets whose voxels can weigh
  // differently are re-gathered (Reweigh: exact); stale weights render worse.
  LeastSquaresFit::Extend(Mesh, X);
  Fit->Reweigh(Mesh, X, done);
  Iterations += Fit->Solve(Mesh, X, Opt.SolverTolerance);
}

void LatticeRefinement::FirstFit()
{
  if (!Opt.ScalarOpacity.empty())
  {
    Importance = std::make_unique<OpacityImportance>(Opt.ScalarOpacity);
    Importance->SetIsoValues(Opt.IsoValues);
    Importance->Prepare(Volume, Opt.ImportanceFloor, Opt.ImportanceRadius, During(1.0));
    UnitsDone += 1.0;
  }
  OpacityCap = Opt.CapOpacity ? Importance.get() : nullptr;
  Fit = std::make_unique<LeastSquaresFit>(Volume, Opt.Regularization, Importance.get());
  Touched.resize(static_cast<size_t>(N0));
  std::iota(Touched.begin(), Touched.end(), 0);
  Fit->UpdateMoments(Mesh, Touched, nullptr, During(2.0));
  UnitsDone += 2.0;
  Iterations = Fit->Solve(Mesh, X, Opt.SolverTolerance);
  const int reweighs = Importance ? std::max(0, Opt.ReweighSteps) : 0;
  for (int k = 0; k < reweighs; ++k)
  {
    Reweigh(During(1.0));
    UnitsDone += 1.0;
  }
  AdvanceTo(StartShare);
}

VoxelErrorReport& LatticeRefinement::OutputErrors()
{
  std::vector<double> y = OutputValues(Mesh, *Fit, X, Opt.ClampToVoxels, OpacityCap);
  VoxelErrorReport e = Fit->VoxelErrors(Mesh, y);
  Checked.emplace(std::move(y), std::move(e));
  return Checked->second;
}

ReducedMesh LatticeRefinement::RelocatedLevel()
{
  // On a copy: the next level refines the lattice mesh, not the moved one.
  BisectionMesh moved = Mesh;
  std::vector<double> y = X;
  LeastSquaresFit::Extend(moved, y);
  RelocationOptions ro;
  ro.Sweeps = Opt.RelocateSweeps;
  ro.QualityFloor = Opt.RelocateQualityFloor;
  ro.MeasureSse = false;
  VertexRelocator::Relocate(moved, Volume, y, ro, Importance.get(), Prog);
  if (Prog)
  {
    // The refit after relocation is a stage of its own, from 0%: back to "reduce 95%" after
    // "relocate 100%" read as the reduction starting over.
    Prog->Begin("refit", 1.0 - Reported);
  }
  LeastSquaresFit refit(Volume, Opt.Regularization, Importance.get());
  std::vector<int> every(static_cast<size_t>(moved.NumberOfTets()));
  std::iota(every.begin(), every.end(), 0);
  refit.UpdateMoments(moved, every, &y);
  refit.Solve(moved, y, Opt.SolverTolerance);
  y = OutputValues(moved, refit, std::move(y), Opt.ClampToVoxels, OpacityCap);
  return Snapshot(Volume, moved, y, refit.VoxelErrors(moved, y));
}

void LatticeRefinement::Emit(long long budget, bool reached, int level)
{
  ReducedMesh m;
  if (Opt.RelocateVertices)
  {
    m = RelocatedLevel();
  }
  else
  {
    if (!Checked)
    {
      OutputErrors();
    }
    m = Snapshot(Volume, Mesh, Checked->first, std::move(Checked->second));
    Checked.reset();
  }
  m.TargetTets = budget;
  m.TargetError = Plan.ErrorBound;
  m.TargetReached = reached;
  m.RefinementLevels = level;
  m.SolverIterations = Iterations;
  m.BuildSeconds = Plan.Elapsed();
  m.Weighted = Importance != nullptr;
  m.Refinement = Opt.Refine == ReducerOptions::Refinement::EdgeSplit ? "edge" : "bisection";
  m.Nested = !Opt.RelocateVertices;
  m.Relocated = Opt.RelocateVertices;
  if (OnLevel)
  {
    OnLevel(m);
  }
  Out.push_back(std::move(m));
}

void LatticeRefinement::EmitUnreached(int level)
{
  // The refinement stops short: every budget left and the error bound are emitted as not reached.
  for (; NextBudget < Plan.Budgets.size(); ++NextBudget)
  {
    Emit(Plan.Budgets[NextBudget], false, level);
  }
  if (Plan.HaveError && (Out.empty() || Out.back().NumberOfTets() != Mesh.NumberOfTets()))
  {
    Emit(0, false, level);
  }
}

double LatticeRefinement::LevelError(bool& met)
{
  // The error that decides, and each tet's share of it (Priority): cached moments give the
  // squared error per tet for free; the max needs a pass over the voxels. An error bound holds
  // for the values output, clamped or capped (a few percent above the fit's).
  const double nvox = static_cast<double>(Volume.NumberOfVoxels());
  const bool clamped = Opt.ClampToVoxels || OpacityCap;
  double global;
  if (Plan.MaxMetric && Plan.HaveError)
  {
    VoxelErrorReport& e = OutputErrors();
    Priority = e.TetWeightedMax;
    global = e.WeightedMax;
  }
  else if (Importance)
  {
    // Weighted squared errors from the moments, whose weights were gathered at this level's
    // starting fit. An error bound that looks met is confirmed at the solved fit, since the
    // weight follows the fit (a stray into an opacity ramp counts).
    Fit->SquaredErrors(Mesh, X, Priority);
    global = std::sqrt(std::accumulate(Priority.begin(), Priority.end(), 0.0) / nvox);
    if (Plan.HaveError && global <= Plan.ErrorBound)
    {
      Reweigh({});
      VoxelErrorReport& e = OutputErrors();
      Priority = e.TetWeightedSse;
      global = e.WeightedRms;
    }
  }
  else
  {
    Fit->SquaredErrors(Mesh, X, Priority);
    global = std::sqrt(std::accumulate(Priority.begin(), Priority.end(), 0.0) / nvox);
    if (Plan.HaveError && global <= Plan.ErrorBound && clamped)
    {
      VoxelErrorReport& e = OutputErrors();
      Priority = e.TetWeightedSse;
      global = e.WeightedRms;
    }
  }
  met = Plan.HaveError && global <= Plan.ErrorBound;
  return global;
}

std::vector<int> LatticeRefinement::Candidates() const
{
  // The tets worth refining, worst first: above round-off (or the max bound) and still cuttable.
  const int nt = Mesh.NumberOfTets();
  const double range = std::max(Volume.Range[1] - Volume.Range[0], 1e-300);
  const double minEdge2 = Opt.MinEdgeVoxels * Opt.MinEdgeVoxels;
  const bool edgeSplit = Opt.Refine == ReducerOptions::Refinement::EdgeSplit;
  std::vector<int> cand;
  for (int t = 0; t < nt; ++t)
  {
    const TetMoments& mt = Fit->Moments(t);
    const double roundOff = std::max(1e-24 * range * range * std::max(1, mt.Count), 1e-10 * mt.G);
    const double threshold = (Plan.MaxMetric && Plan.HaveError) ? std::max(Plan.ErrorBound, 1e-12 * range) : roundOff;
    if (Priority[t] > threshold && (edgeSplit ? EdgeSplitRefiner::CanRefine(Mesh, t, minEdge2)
                                              : Mesh.RefinementEdgeLength2(t) >= minEdge2 && Mesh.CanBisect(t)))
    {
      cand.push_back(t);
    }
  }
  std::sort(cand.begin(), cand.end(), [&](int a, int b) {
    return Priority[a] != Priority[b] ? Priority[a] > Priority[b] : a < b;
  });
  return cand;
}

void LatticeRefinement::Refine(const std::vector<int>& cand, long long next)
{
  const int nt = Mesh.NumberOfTets();
  const double minEdge2 = Opt.MinEdgeVoxels * Opt.MinEdgeVoxels;
  const bool edgeSplit = Opt.Refine == ReducerOptions::Refinement::EdgeSplit;
  std::vector<uint32_t> version(static_cast<size_t>(nt));
  for (int t = 0; t < nt; ++t)
  {
    version[t] = Mesh.Version(t);
  }
  if (edgeSplit)
  {
    // Edge moments of the tets the last level made (Touched still lists them); weighted, the
    // weights moved with the fit, so all of them, as Reweigh does.
    if (Importance || EdgeMoments.empty())
    {
      std::vector<int> all(static_cast<size_t>(nt));
      std::iota(all.begin(), all.end(), 0);
      Fit->EdgeMoments(Mesh, all, EdgeMoments, &X);
    }
    else
    {
      Fit->EdgeMoments(Mesh, Touched, EdgeMoments);
    }
  }
  Touched.clear();
  if (edgeSplit)
  {
    EdgeSplitRefiner::RefineLevel(Mesh, cand, version, EdgeMoments, X, minEdge2, next, Touched);
  }
  else
  {
    for (int t : cand)
    {
      if (Mesh.Version(t) != version[t])
      {
        continue; // already cut by the closure of a worse tet
      }
      Mesh.Refine(t, Touched);
      if (Mesh.NumberOfTets() >= next)
      {
        break;
      }
    }
  }
  std::sort(Touched.begin(), Touched.end());
  Touched.erase(std::unique(Touched.begin(), Touched.end()), Touched.end());
}

void LatticeRefinement::Refit()
{
  if (Importance)
  {
    Reweigh({});
  }
  else
  {
    Fit->UpdateMoments(Mesh, Touched);
    Iterations += Fit->Solve(Mesh, X, Opt.SolverTolerance);
  }
}

void LatticeRefinement::ReportLevel(double global)
{
  // Refinement fills the bar from the first fit's share to 95%: by the error's way to its bound
  // under a bound alone, else by the tets' way to the cap (logarithmically).
  double f;
  if (Plan.HaveError && Plan.Budgets.empty())
  {
    FirstError = FirstError < 0 ? global : FirstError;
    if (!(FirstError > Plan.ErrorBound && Plan.ErrorBound > 0))
    {
      return;
    }
    f = std::log(FirstError / global) / std::log(FirstError / Plan.ErrorBound);
  }
  else
  {
    f = std::log(double(Mesh.NumberOfTets()) / N0) / std::log(double(std::max<long long>(Plan.Cap, N0 + 1)) / N0);
  }
  AdvanceTo(std::min(0.95, StartShare + (0.95 - StartShare) * f));
}

double LatticeRefinement::GrowthTowards(long long nt, long long goal) const
{
  // Automatic growth: bisection takes half a level while far from the next budget (cheap levels,
  // each still a voxel pass when weighted) and a fifth over the last factor of 4 before it.
  if (Opt.RefineFraction > 0)
  {
    return Opt.RefineFraction;
  }
  return Opt.Refine == ReducerOptions::Refinement::EdgeSplit || nt * 4 > goal ? 0.2 : 0.5;
}

std::vector<ReducedMesh> LatticeRefinement::Run()
{
  StartProgress();
  FirstFit();
  const std::vector<long long>& budgets = Plan.Budgets;
  for (int level = 0;; ++level)
  {
    if (Prog && Prog->Cancelled())
    {
      throw Error("cancelled");
    }
    Checked.reset(); // the mesh or the fit changed
    const long long nt = Mesh.NumberOfTets();
    while (NextBudget < budgets.size() && nt >= budgets[NextBudget])
    {
      Emit(budgets[NextBudget], true, level);
      ++NextBudget;
    }
    bool met = false;
    const double global = LevelError(met);
    if (met)
    {
      if (Out.empty() || Out.back().NumberOfTets() != nt)
      {
        Emit(0, true, level);
      }
      break;
    }
    if (!Plan.HaveError && NextBudget == budgets.size())
    {
      break;
    }
    if (nt >= Plan.Cap)
    {
      EmitUnreached(level);
      break;
    }
    const long long goal = NextBudget < budgets.size() ? std::min(Plan.Cap, budgets[NextBudget]) : Plan.Cap;
    const long long next = std::min(goal,
      std::max(nt + 1, static_cast<long long>(std::ceil(nt * (1.0 + GrowthTowards(nt, goal))))));
    if (NextBudget == budgets.size())
    {
      Reducer.CheckGrowth(Volume, nt, next, AvailableMemoryBytes()); // an error bound alone: no budget was checked
    }
    const std::vector<int> cand = Candidates();
    if (cand.empty())
    {
      // Nothing left to refine: the field is matched as well as this resolution allows.
      EmitUnreached(level);
      break;
    }
    Refine(cand, next);
    Refit();
    ReportLevel(global);
  }
  if (Prog)
  {
    Prog->End();
  }
  return Out;
}
} // namespace art
