// TetReducer: voxels to an adaptive tet grid fitted in the least-squares sense (Grosso, Luerig &
// Ertl, Vis '97), to tet budgets (levels emitted on the way) or an error bound. The refinements:
// - Bisection (default, LatticeRefinement): newest-vertex bisection on an exact integer lattice
//   (BisectionMesh): every voxel centre in exactly one tet, deterministic, conforming with a
//   short closure, budgets met to a few tets, near-regular shapes, nested levels whose warm
//   start is exact. Chosen over red-green refinement or a sizing-field mesher for that nesting.
// - EdgeSplit (EdgeSplitRefiner): the edges whose split removes the most error per added tet;
//   still nested and exact on the lattice, with thin tets along sharp surfaces.
// - Anisotropic (AnisotropicAdaptation): MMG3D remeshes the box to the voxels' Hessian metric;
//   tets long along surfaces and thin across them, levels not nested.
// RelocateVertices (VertexRelocator) moves each output's vertices off the lattice onto the
// surfaces they fit, then refits. Figures: tests/benchmarks/reduction_results/README.md.
#ifndef art_TetReducer_h
#define art_TetReducer_h

#include "AdaptiveRTReductionModule.h"
#include "HessianMetric.h"
#include "VoxelVolume.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace art
{
class Progress;

struct ReducerOptions
{
  enum class Metric
  {
    RMS,
    Max
  };
  /// How a selected tet is refined. Bisection: newest-vertex bisection (Maubach), a fixed edge
  /// per tet, isotropic shapes. EdgeSplit (EdgeSplitRefiner): the edges of the refinable tets that
  /// remove the most squared error per added tet when split with their whole star (the new vertex
  /// alone refitted, from voxel moments) are split, best first: tets grow thin across sharp
  /// surfaces; lower error per tet, far flatter tets, about 3 x the time.
  enum class Refinement
  {
    Bisection,
    EdgeSplit,
    Anisotropic
  };
  long long TargetTets = 0;      ///< stop at this many tets (0: not set)
  double TargetError = -1;       ///< stop when the global error is at most this (< 0: not set);
                                 ///< alone, it stops at one tet per voxel at most
  Metric ErrorMetric = Metric::RMS;
  bool ErrorRelative = false;    ///< TargetError is a fraction of the scalar range
  std::vector<long long> Levels; ///< more budgets (tets) emitted on the way, nested
  double RefineFraction = 0;     ///< tet count growth per level; 0: automatic (see above)
  double SolverTolerance = 1e-8; ///< CG stops at ||r|| <= tol ||b||
  double Regularization = 0.5;   ///< smoothness weight on tets holding fewer than 8 voxel centres
  double MinEdgeVoxels = 2.0;    ///< a refinement edge shorter than this (in voxels) is never cut
  Refinement Refine = Refinement::Bisection;
  int CoarseTets = 0;            ///< size of the coarse Kuhn mesh (0: from the smallest budget)
  /// Output values clamped to the range of the voxels under each vertex's tets: no overshoot
  /// beyond the data at sharp edges (maximum-intensity projection shows it as bright facets), at
  /// some cost in L2 error. The fit itself, and so the levels after, are not changed.
  bool ClampToVoxels = false;
  /// Reduce for what a transfer function shows: (scalar, opacity) nodes of its scalar-opacity
  /// function (empty: plain L2). The fit, the refinement choice and an error target then use
  /// OpacityImportance's weighted error: a voxel weighs by the opacity slope it (or its fit) meets.
  std::vector<std::pair<double, double>> ScalarOpacity;
  /// With ScalarOpacity: an output value whose opacity exceeds every opacity the transfer function
  /// gives the voxels under its vertex's tets is clamped to their range. The least-squares fit
  /// overshoots past thin bright structures (a head rest of a few voxels) into ranges no voxel
  /// there has, which render as opaque speckles; overshoot into clearer ranges sharpens surfaces
  /// and is kept (a better image than clamping both ways, ClampToVoxels). The fit and the levels
  /// after are unchanged.
  bool CapOpacity = true;
  /// With ScalarOpacity: iso-surfaces drawn over it. Voxels next to one weigh as much as the
  /// steepest opacity ramp (OpacityImportance::SetIsoValues), so the fit places the surfaces.
  std::vector<double> IsoValues;
  double ImportanceFloor = 0.02; ///< weight of voxels whose neighbourhood meets no opacity change
  int ImportanceRadius = 2;      ///< neighbourhood (2 r + 1)^3 voxels whose scalar range counts
  int ReweighSteps = 3;          ///< weighted fit: extra reweighting steps on the coarse mesh
  /// Each output level's vertices are moved off the lattice to lower their star's error
  /// (VertexRelocator), then the fit is solved again on the moved mesh. The refinement goes on
  /// from the unmoved mesh, so levels are no longer nested. Anisotropic: after the remeshing,
  /// when its tets hold RelocateVoxelsPerTet voxels each or more on average, with a quality
  /// floor of at most 0.05 (its tets are thin by design).
  bool RelocateVertices = false;
  /// On finer anisotropic meshes the fit already passes near every voxel centre, and moves
  /// fitted the centres rather than the field between them (images 0.7-3 dB worse, measured in
  /// tests/benchmarks/tets-results); 0 relocates every mesh.
  double RelocateVoxelsPerTet = 20;
  int RelocateSweeps = 3;           ///< Gauss-Seidel sweeps of the relocation
  double RelocateQualityFloor = 0.2; ///< shape floor a moved tet keeps (VertexRelocator)
  /// Refinement::Anisotropic (AnisotropicAdaptation): the metric MMG adapts each level to, the
  /// power of the transfer function's weight that scales it, whether MMG moves vertices, and
  /// the remeshings a level may take again while its tet count is off the budget by more than
  /// BudgetTolerance.
  MetricOptions Metric;
  double MetricWeightExponent = 0.5;
  bool RemeshMovesVertices = true;
  int AdaptationRetries = 2;
  double BudgetTolerance = 0.05;
};

/// One output level: a tet mesh with the fitted values and its errors against the voxels.
struct ReducedMesh
{
  std::vector<double> Points; ///< x y z per vertex, world coordinates
  std::vector<int> Tets;      ///< 4 vertex ids per tet, positively oriented (VTK_TETRA)
  std::vector<double> Values; ///< the least-squares fit at each vertex
  std::vector<double> TetRms, TetMax; ///< each tet's error against the voxels it owns
  double Rms = 0, Max = 0;    ///< global error over every voxel, data units
  double WeightedRms = 0, WeightedMax = 0; ///< the same for sqrt(w) |f - fit| (= plain when unweighted)
  bool Weighted = false;      ///< reduced with a scalar-opacity importance
  double Range[2] = { 0, 0 }; ///< scalar range of the input
  double SourceSpacing = 1;   ///< the input's geometric mean voxel spacing (over axes of > 1 voxel)
  ScalarStatistics Source;    ///< the input's background, window and labels (VoxelVolume::Statistics)
  double BuildSeconds = 0;    ///< from the start of the run to this level
  long long TargetTets = 0;   ///< the budget this level stands for (0: an error target)
  double TargetError = -1;    ///< the error bound in data units (< 0: none)
  bool TargetReached = true;  ///< false when refinement ran out before the error bound
  int RefinementLevels = 0, SolverIterations = 0;
  std::string ScalarName;
  std::string Refinement = "bisection"; ///< how it was made: bisection, edge or anisotropic
  bool Nested = true; ///< each level's tets are unions of the next level's (not with relocation or anisotropic)
  bool Relocated = false; ///< its vertices were moved by VertexRelocator

  long long NumberOfTets() const { return static_cast<long long>(Tets.size() / 4); }
  long long NumberOfVertices() const { return static_cast<long long>(Points.size() / 3); }
};

class ADAPTIVERTREDUCTION_EXPORT TetReducer
{
public:
  explicit TetReducer(ReducerOptions options = {}) : Opt(std::move(options)) {}
  const ReducerOptions& Options() const { return Opt; }

  /// Runs the reduction; returns one mesh per budget reached (ascending), plus the final mesh
  /// of an error target. `onLevel` (optional) sees each as it is made. Throws art::Error for bad
  /// input or options, and when `progress` is cancelled.
  std::vector<ReducedMesh> Run(const VoxelVolume& volume, Progress* progress = nullptr,
    const std::function<void(const ReducedMesh&)>& onLevel = {}) const;

  /// Bytes a run on `voxels` samples still allocates beyond them, from reduce's peak memory: about
  /// 350 a tet of the largest budget (570 with RelocateVertices, 900 anisotropic) and 28 a voxel
  /// with ScalarOpacity (the opacity weights, their neighbourhood ranges and the fit's
  /// reweighing), 40 more anisotropic (the metric). An error bound alone counts no tets.
  double MemoryNeeded(long long voxels) const;
  /// Throws art::Error naming volume.File, its voxels and the memory needed and available, with
  /// the way out, when MemoryNeeded passes 90% of availableBytes (0: unknown, not checked). Run
  /// calls it with art::AvailableMemoryBytes() before allocating anything: a volume too large
  /// was killed by the system half-way, or thrashed.
  void CheckMemory(const VoxelVolume& volume, double availableBytes) const;
  /// Under an error bound alone (no budget to check up front, up to a tet per voxel), Run calls
  /// this before each refinement from `tets` to `next` tets: throws art::Error naming volume.File
  /// and the way out (a --tets budget, a larger bound) when `next` tets (the arrays grow by copy)
  /// would need more than 90% of availableBytes (0: unknown, not checked).
  void CheckGrowth(const VoxelVolume& volume, long long tets, long long next, double availableBytes) const;

  /// Coarse box counts per axis for about `tets` Kuhn tets, shaped to the volume's aspect.
  static void CoarseGrid(const VoxelVolume& volume, long long tets, int cubes[3]);

private:
  ReducerOptions Opt;
};

/// The budgets of `levels` that `meshes` (a Run's output, the final mesh last) holds no level
/// for, once each in the order asked: an error target stopped the refinement before them.
ADAPTIVERTREDUCTION_EXPORT std::vector<long long> UnreachedLevels(
  const std::vector<long long>& levels, const std::vector<ReducedMesh>& meshes);
} // namespace art

#endif
