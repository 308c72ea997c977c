// TetReducer: the multilevel least-squares reducer from voxels to an adaptive tet grid (Grosso,
// Luerig & Ertl, Vis '97): coarse Kuhn mesh -> L2 fit -> per-tet error -> bisect the worst ->
// re-fit warm-started -> ... until a tet budget or an error bound; nested levels on the way.
//
// Refinement choice: newest-vertex bisection (BisectionMesh), not red-green, TetGen or CGAL.
// It is exact on an integer lattice (each voxel centre in exactly one tet; deterministic), stays
// conforming with a short closure, adds one tet per bisection (a budget is met to a few tets),
// keeps shapes in a few similarity classes (min dihedral 42.6 deg on the full CT at 200k tets),
// and the old fit is exactly representable on the refined mesh, so the warm start is exact.
// Measured (adaptivert bench reduction, CT head, paper's levels 0.01%..1%): RMS error 0.75-0.83 x
// uniform downsampling at equal vertices on the full 256x256x108 CT (0.81-0.89 x on the 128
// default). VTK's quadric decimation leaves a third or more of the voxel centres uncovered; on
// those it covers, at its own tet count, ours is 1.33-1.57 x its RMS: its freely placed,
// anisotropic tets suit CT edges better than isotropic bisection. TetGen/CGAL sizing-field
// refinement was not built: no exact nesting. RefineFraction 0.05-0.5, MinEdgeVoxels 1-3,
// Regularization 0.05-3, the coarse mesh size and a bisection-gain priority move these ratios by
// at most a few percent (reduction_results/README.md). Automatic growth: bisection grows by half
// a level while the mesh is under a quarter of the next budget, then by a fifth (opacity-weighted,
// each level is a voxel pass: full CT to 200k tets 20.7 -> 17.6 s on one thread, rendered PSNR
// 23.47 -> 23.61 dB; growing by half all the way lost 1.2 dB on a 512 x 512 x 215 CT at 500k tets);
// edge splits by a fifth throughout (by half, their RMS at 200k tets rose 18%). Weighted levels
// re-gather only the tets whose voxels can weigh differently at the new fit
// (LeastSquaresFit::Reweigh, exact): full CT to 200k tets 17.6 -> 11.3 s on one thread, a
// 512 x 512 x 215 CT to 500k tets 155 -> 61 s on two, for 8 more bytes a voxel.
// Option Refinement::EdgeSplit splits, best first, the edges whose split (star and all, at the
// midpoint or a quarter point) removes the most squared error per added tet: still nested,
// conforming and exact on the lattice, and anisotropic. Full CT: RMS 0.90-0.96 x bisection's at
// the six levels, 0.79 x at 200k tets, but min dihedral near 0 deg and about 3 x the time, so it
// is not the default (figures in that README).
// Option RelocateVertices (VertexRelocator) moves each output's vertices off the lattice onto the
// surfaces they fit, then refits: full CT 17-30% lower RMS at the paper's levels (0.53-0.67 x
// uniform), but 4-5 x the time and min dihedral ~9 deg, so it is not the default either.
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
  /// and is kept. Measured (128 CT, ct-skin-bone, 500 x 500 against the voxel reference): PSNR
  /// 23.01 / 24.82 / 26.16 -> 23.08 / 25.05 / 29.20 dB at 10k / 50k / 250k tets; clamping both
  /// ways (ClampToVoxels) gave 21.4 / 23.3 / 28.3 dB. The fit and the levels after are unchanged.
  bool CapOpacity = true;
  /// With ScalarOpacity: iso-surfaces drawn over it. Voxels next to one weigh as much as the
  /// steepest opacity ramp (OpacityImportance::SetIsoValues), so the fit places the surfaces.
  std::vector<double> IsoValues;
  double ImportanceFloor = 0.02; ///< weight of voxels whose neighbourhood meets no opacity change
  int ImportanceRadius = 2;      ///< neighbourhood (2 r + 1)^3 voxels whose scalar range counts
  int ReweighSteps = 3;          ///< weighted fit: extra reweighting steps on the coarse mesh
  /// Each output level's vertices are moved off the lattice to lower their star's error
  /// (VertexRelocator), then the fit is solved again on the moved mesh. The refinement goes on
  /// from the unmoved mesh, so levels are no longer nested.
  bool RelocateVertices = false;
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

  /// Bytes a run on `voxels` samples still allocates beyond them, from peak memory measured on
  /// reduce (200^3 and 300^3 CTs, 80k and 800k tets): about 350 a tet of the largest budget (570
  /// with RelocateVertices) and, with ScalarOpacity, 28 a voxel (the opacity weights, their
  /// neighbourhood ranges and the fit's reweighing). An error bound alone counts no tets.
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
