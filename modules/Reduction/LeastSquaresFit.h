// LeastSquaresFit: the best piecewise-linear approximation of the voxel samples on a tet mesh in
// the discrete L2 sense (Grosso, Luerig & Ertl, Vis '97, section 3): M c = b with
// M_ij = sum_v phi_i(x_v) phi_j(x_v), b_i = sum_v phi_i(x_v) f_v, solved by Jacobi-preconditioned CG.
#ifndef art_LeastSquaresFit_h
#define art_LeastSquaresFit_h

#include "AdaptiveRTReductionModule.h"
#include "BisectionMesh.h"
#include "VoxelVolume.h"

#include <vector>

namespace art
{
/// What the fit needs from the voxels one tet owns, gathered once per tet.
struct TetMoments
{
  double M[10] = {};  ///< packed upper triangle of sum lambda_a lambda_b
  double Bf[4] = {};  ///< sum lambda_a (f - F0)
  double Volume = 0;   ///< in voxel units, for the continuous mass regulariser
  double F0 = 0, G = 0; ///< reference value (first voxel) and sum (f - F0)^2, against round-off
  int Count = 0;        ///< voxel centres owned
  bool Regularize = false; ///< too few voxels to pin its corners: add the anchor term
};

class ADAPTIVERTREDUCTION_EXPORT LeastSquaresFit
{
public:
  /// `regularization` weights, on tets holding too few voxel centres, a continuous-mass term
  /// alpha * int_T (u - u_prev)^2 that anchors them to the previous (coarser) fit. Unlike a
  /// gradient penalty it does not bias a linear field, and it vanishes where the fit is good.
  LeastSquaresFit(const VoxelVolume& volume, double regularization = 0.5);

  /// Re-gathers the moments of the listed tets (new or replaced); sizes to the mesh.
  void UpdateMoments(const BisectionMesh& mesh, const std::vector<int>& tets);
  /// Solves for vertex values `x` (warm start: its current content, resized with parents' mean).
  /// Returns CG iterations; stops at ||r|| <= tolerance ||b||.
  int Solve(const BisectionMesh& mesh, std::vector<double>& x, double tolerance, int maxIterations = 2000);
  /// Per-tet sum of squared errors from the cached moments (no voxel pass).
  void SquaredErrors(const BisectionMesh& mesh, const std::vector<double>& x, std::vector<double>& sse) const;
  /// Exact per-tet RMS and max |f - fit| over the voxels each tet owns (one pass over voxels).
  void VoxelErrors(const BisectionMesh& mesh, const std::vector<double>& x, std::vector<double>& rms,
    std::vector<double>& maxErr, double& globalRms, double& globalMax) const;

  const TetMoments& Moments(int t) const { return Mom[t]; }
  static int PackedIndex(int a, int b);

private:
  TetMoments Gather(const BisectionMesh& mesh, int t) const;

  const VoxelVolume& Volume;
  double Regularization;
  std::vector<TetMoments> Mom;
};
} // namespace art

#endif
