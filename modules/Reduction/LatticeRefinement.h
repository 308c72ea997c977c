// LatticeRefinement: the multilevel least-squares reduction on the bisection lattice (Grosso,
// Luerig & Ertl, Vis '97): coarse Kuhn mesh -> L2 fit -> per-tet error -> refine the worst
// (newest-vertex bisection, or EdgeSplitRefiner's edge splits) -> re-fit warm-started -> ...
// until each tet budget (emitted on the way, nested) and the error bound are met. With
// RelocateVertices each emitted level is a relocated copy (VertexRelocator), refitted.
#ifndef art_LatticeRefinement_h
#define art_LatticeRefinement_h

#include "BisectionMesh.h"
#include "EdgeSplitRefiner.h"
#include "LeastSquaresFit.h"
#include "OpacityImportance.h"
#include "ReductionPlan.h"
#include "TetReducer.h"

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace art
{
class Progress;

class LatticeRefinement
{
public:
  LatticeRefinement(const TetReducer& reducer, const VoxelVolume& volume, const ReductionPlan& plan,
    Progress* progress, std::function<void(const ReducedMesh&)> onLevel);
  /// The levels reached (and those not, flagged), coarsest first.
  std::vector<ReducedMesh> Run();

private:
  void StartProgress();
  void AdvanceTo(double f);
  std::function<void(double)> During(double size);
  void FirstFit();
  void Reweigh(const LeastSquaresFit::Done& done);
  VoxelErrorReport& OutputErrors();
  ReducedMesh RelocatedLevel();
  void Emit(long long budget, bool reached, int level);
  void EmitUnreached(int level);
  double LevelError(bool& met);
  std::vector<int> Candidates() const;
  void Refine(const std::vector<int>& cand, long long next);
  void Refit();
  void ReportLevel(double global);
  double GrowthTowards(long long nt, long long goal) const;

  const TetReducer& Reducer;
  const ReducerOptions& Opt;
  const VoxelVolume& Volume;
  const ReductionPlan& Plan;
  Progress* Prog;
  std::function<void(const ReducedMesh&)> OnLevel;

  BisectionMesh Mesh;
  int N0 = 0;
  std::unique_ptr<OpacityImportance> Importance;
  const OpacityImportance* OpacityCap = nullptr;
  std::unique_ptr<LeastSquaresFit> Fit;
  std::vector<double> X; ///< the fit at the vertices
  int Iterations = 0;
  std::vector<int> Touched; ///< tets the last refinement made or replaced
  std::vector<double> Priority;
  std::vector<EdgeSplitMoments> EdgeMoments;
  /// The output values of the lattice mesh and their errors, kept from an error check at this
  /// level for the level it emits (two voxel passes otherwise done again).
  std::optional<std::pair<std::vector<double>, VoxelErrorReport>> Checked;
  std::vector<ReducedMesh> Out;
  size_t NextBudget = 0;

  double Reported = 0, FirstError = -1, StartShare = 0, Units = 1, UnitsDone = 0;
};
} // namespace art

#endif
