// LeastSquaresFit: the best piecewise-linear approximation of the voxel samples on a tet mesh in
// the discrete L2 sense (Grosso, Luerig & Ertl, Vis '97, section 3): M c = b with
// M_ij = sum_v phi_i(x_v) phi_j(x_v), b_i = sum_v phi_i(x_v) f_v, solved by Jacobi-preconditioned CG.
// With per-voxel weights w_v (OpacityImportance) every sum carries w_v: a weighted L2 fit.
#ifndef art_LeastSquaresFit_h
#define art_LeastSquaresFit_h

#include "AdaptiveRTReductionModule.h"
#include "BisectionMesh.h"
#include "OpacityImportance.h"
#include "VoxelVolume.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace art
{
/// What the fit needs from the voxels one tet owns, gathered once per tet.
struct TetMoments
{
  double M[10] = {};  ///< packed upper triangle of sum w lambda_a lambda_b
  double Bf[4] = {};  ///< sum w lambda_a (f - F0)
  double Volume = 0;   ///< in voxel units, for the continuous mass regulariser
  double F0 = 0, G = 0; ///< reference value (first voxel) and sum w (f - F0)^2, against round-off
  double MeanWeight = 1; ///< mean voxel weight, scales the regulariser to the weighted fit
  int Count = 0;        ///< voxel centres owned
  bool Regularize = false; ///< too few voxels to pin its corners: add the anchor term
  /// Weighted: every voxel weighed its flat weight (OpacityImportance::Flat) when gathered, and
  /// will again at any fit whose corner values stay inside (FlatLo, FlatHi), the intersection of
  /// its voxels' flat intervals; the moments then do not change (Reweigh keeps them).
  bool AllFlat = false;
  double FlatLo = 0, FlatHi = 0;
  uint32_t Version = UINT32_MAX; ///< the tet's BisectionMesh::Version when gathered
};

/// Errors over the voxels, plain and weighted (OpacityImportance::Error2; plain without weights).
struct VoxelErrorReport
{
  std::vector<double> TetRms, TetMax, TetWeightedMax, TetWeightedSse;
  double Rms = 0, Max = 0;                 ///< over every voxel, data units
  double WeightedRms = 0, WeightedMax = 0; ///< sqrt(mean Error2), sqrt(max Error2)
  long long Voxels = 0;                    ///< voxels the means are over (a mask's, inside the mesh)
};

/// For edge choice, per edge e = (a, b) of a tet (BisectionMesh::EdgeCorners) and per position
/// t = 1/4, 1/2, 3/4 from a, over the voxels the tet owns: with phi = min(lambda_b / t,
/// lambda_a / (1 - t)), the hat of the new vertex once e is split there, P = sum w (f - F0) phi,
/// R_c = sum w lambda_c phi and Q = sum w phi^2. They do not depend on the fit (gathered once per
/// tet, as TetMoments): at corner values x the correlation of the residual with the hat is
/// S = P - sum_c (x_c - F0) R_c, and, summed over e's star, S^2 / Q is the squared error the split
/// removes when the new vertex alone takes its best value.
struct EdgeSplitMoments
{
  static constexpr int Positions = 3; ///< the new vertex at 1/4, 1/2 or 3/4 of the edge
  double F0 = 0;
  double P[Positions][6] = {}, Q[Positions][6] = {};
  double R[Positions][6][4] = {};
  /// S of edge e with the vertex at (q + 1) / 4 from its first corner, at the corner values c.
  double S(int q, int e, const double c[4]) const
  {
    return P[q][e] - (c[0] - F0) * R[q][e][0] - (c[1] - F0) * R[q][e][1] - (c[2] - F0) * R[q][e][2] -
      (c[3] - F0) * R[q][e][3];
  }
};

class ADAPTIVERTREDUCTION_EXPORT LeastSquaresFit
{
public:
  /// Told the fraction of a gathering done, on the calling thread, between slices of the tets
  /// (a pass over a large volume takes seconds; VTK's progress must come from the driver thread).
  using Done = std::function<void(double)>;

  /// `regularization` weights, on tets holding too few voxel centres, a continuous-mass term
  /// alpha * int_T (u - u_prev)^2 that anchors them to the previous (coarser) fit. Unlike a
  /// gradient penalty it does not bias a linear field, and it vanishes where the fit is good.
  /// `importance` (optional, prepared, kept by reference) weighs each voxel by
  /// OpacityImportance::Weight at the current fit (`fit` of UpdateMoments), errors by Error2.
  LeastSquaresFit(const VoxelVolume& volume, double regularization = 0.5,
    const OpacityImportance* importance = nullptr);

  /// Only voxels i with (*mask)[i] != 0 count, in every sum and error (a region of the volume,
  /// RegionMask); null, the default: every voxel. Kept by reference; set before gathering.
  void SetMask(const std::vector<uint8_t>* mask) { Mask = mask; }

  /// Re-gathers the moments of the listed tets (new or replaced); sizes to the mesh. With an
  /// importance, `fit` (vertex values, Extend-ed to the mesh) is the point the weights are taken at.
  void UpdateMoments(const BisectionMesh& mesh, const std::vector<int>& tets, const std::vector<double>* fit = nullptr,
    const Done& done = {});
  /// With an importance: brings every tet's moments to the weights at `fit` (vertex values,
  /// Extend-ed), as UpdateMoments of all tets would, bit for bit, but gathers only the tets that
  /// are new or replaced or whose voxels' weights can have changed. Returns the tets gathered.
  long long Reweigh(const BisectionMesh& mesh, const std::vector<double>& fit, const Done& done = {});
  /// New vertices take their parents' values interpolated at their place on the edge: the
  /// previous fit, exactly, on the refined mesh.
  static void Extend(const BisectionMesh& mesh, std::vector<double>& x);
  /// Solves for vertex values `x` (warm start: its current content, Extend-ed).
  /// Returns CG iterations; stops at ||r|| <= tolerance ||b||.
  int Solve(const BisectionMesh& mesh, std::vector<double>& x, double tolerance, int maxIterations = 2000);
  /// Per-tet (weighted) sum of squared errors from the cached moments (no voxel pass).
  void SquaredErrors(const BisectionMesh& mesh, const std::vector<double>& x, std::vector<double>& sse) const;
  /// Exact per-tet RMS and max |f - fit| over the voxels each tet owns, and the global plain and
  /// weighted errors (one pass over the voxels).
  VoxelErrorReport VoxelErrors(const BisectionMesh& mesh, const std::vector<double>& x) const;

  /// Per vertex, the smallest and largest voxel value among the voxels its tets own (the
  /// support of its hat function); +inf / -inf for a vertex whose tets own none. One voxel pass.
  void VertexVoxelRange(const BisectionMesh& mesh, std::vector<double>& lo, std::vector<double>& hi) const;

  /// EdgeSplitMoments of the listed tets into out[t] (sized to the mesh). With an importance,
  /// `fit` (vertex values, Extend-ed) is where the weights are taken, as in UpdateMoments.
  void EdgeMoments(const BisectionMesh& mesh, const std::vector<int>& tets, std::vector<EdgeSplitMoments>& out,
    const std::vector<double>* fit = nullptr) const;

  const TetMoments& Moments(int t) const { return Mom[t]; }
  static int PackedIndex(int a, int b);

private:
  TetMoments Gather(const BisectionMesh& mesh, int t, const std::vector<double>* fit) const;
  /// Gathers the listed tets in parallel, in slices when `done` is set.
  void GatherAll(const BisectionMesh& mesh, const std::vector<int>& tets, const std::vector<double>* fit, const Done& done);

  const VoxelVolume& Volume;
  double Regularization;
  const OpacityImportance* Imp;
  const std::vector<uint8_t>* Mask = nullptr;
  std::vector<TetMoments> Mom;
};
} // namespace art

#endif
