// AnisotropicAdaptation: the reducer's anisotropic refinement by metric-based mesh adaptation
// (Alauzet & Loseille, "A decade of progress on anisotropic mesh adaptation for computational
// fluid dynamics", Computer-Aided Design 72, 2016). The voxels' Hessian metric (HessianMetric)
// is sampled at the vertices of a uniform mesh of the box, scaled so that MMG3D (MmgRemesher)
// makes the tets asked for, and remeshed; the least-squares fit (LeastSquaresFit) on the new
// mesh gives the values. The scale is calibrated on each remeshing and carried to the next:
// a level's count misses by more than the tolerance only when the calibration was off, and is
// then remeshed again from the same start. Levels are not nested.
#ifndef art_AnisotropicAdaptation_h
#define art_AnisotropicAdaptation_h

#include "HessianMetric.h"
#include "ReductionPlan.h"
#include "TetReducer.h"
#include "VoxelVolume.h"

#include <functional>
#include <memory>
#include <vector>

namespace art
{
class BisectionMesh;
class LeastSquaresFit;
class OpacityImportance;
class Progress;

/// One remeshing, for the figures.
struct AdaptationRound
{
  long long TargetTets = 0;    ///< the budget it was made for
  long long Tets = 0, Vertices = 0;
  double Complexity = 0;       ///< the metric's complexity asked for
  double Seconds = 0;
};

class AnisotropicAdaptation
{
public:
  /// `importance` (optional, prepared) weighs the metric and the fit as the transfer function
  /// does. `progress` (optional) may cancel between remeshings; `share` maps this run's work
  /// (0..1) onto it.
  AnisotropicAdaptation(const VoxelVolume& volume, const ReducerOptions& options,
    const OpacityImportance* importance, Progress* progress = nullptr,
    std::function<void(double)> share = {});
  ~AnisotropicAdaptation();

  /// A mesh of about `tets` tets (within ReducerOptions::BudgetTolerance unless the
  /// remeshings allowed ran out), fitted: a level with its errors and TargetTets set.
  /// `done` (optional) is told this level's fraction done.
  ReducedMesh Adapt(long long tets, const std::function<void(double)>& done = {});
  /// Every remeshing so far, in order.
  const std::vector<AdaptationRound>& Rounds() const { return History; }

  /// Bytes a run needs beyond the voxels: per voxel (the metric field) and per tet (MMG's
  /// mesh, the fit), measured peaks.
  static double BytesPerVoxel() { return 40.0; }
  static double BytesPerTet() { return 900.0; }


private:
  struct Mesh
  {
    std::vector<double> Points; ///< voxel index coordinates
    std::vector<int> Tets;
  };
  Mesh UniformMesh(double vertices) const;
  double MeshComplexity(const Mesh& m, const std::vector<double>& metric6, const std::vector<double>& volume) const;
  /// Remeshings of `start` until the count is within the tolerance (or the tries run out).
  Mesh Converge(const Mesh& start, long long tets, const std::function<void(double)>& done);
  Mesh Remesh(const Mesh& start, long long tets, double complexity);
  void Calibrate(const AdaptationRound& r);
  double VerticesFor(long long tets) const;
  ReducedMesh Fit(const Mesh& m, long long tets) const;
  /// Relocates the vertices of the fitted `mesh` and refits `x` on `all` its tets; CG iterations.
  int Relocate(BisectionMesh& mesh, LeastSquaresFit& fit, const std::vector<int>& all, std::vector<double>& x) const;

  const VoxelVolume& Volume;
  const ReducerOptions& Opt;
  const OpacityImportance* Importance;
  Progress* Prog;
  std::unique_ptr<HessianMetric> Metric;
  double VerticesPerComplexity = 1.5; ///< vertices MMG makes per unit of complexity (calibrated)
  double BoundaryTets = 15.0;         ///< tets = 6.3 V - BoundaryTets V^(2/3) (calibrated)
  std::vector<AdaptationRound> History;
};

/// TetReducer::Run for Refinement::Anisotropic: each budget of `plan` adapted in turn; an error
/// bound stops at the first level that meets it, or, without a tet target, grows the budget
/// (by the error's ratio to the bound, as a P1 error falls with N^(-2/3)) until it is met.
std::vector<ReducedMesh> ReduceAnisotropic(const VoxelVolume& volume, const ReducerOptions& options,
  const ReductionPlan& plan, Progress* progress, const std::function<void(const ReducedMesh&)>& onLevel);
} // namespace art

#endif
