// HessianMetric: the anisotropic metric field that tells MMG how long each tet's edges should
// be, from the Hessian of the voxels: the L^p-optimal metric for piecewise-linear approximation
// (Loseille & Alauzet, "Continuous mesh framework", SIAM J. Numer. Anal. 49, 2011, parts I-II):
// M = D det|H|^(-1/(2p+3)) |H|, |H| the Hessian with its eigenvalues made positive, D the scale
// that gives the mesh its complexity (the integral of sqrt(det M), proportional to its vertices). Voxels are smoothed by a Gaussian
// before the Hessian (a CT's one-voxel shells have no second derivative otherwise) and |H| again
// after (a vertex's metric then sees the shell it sits beside). Units: voxel index coordinates.
#ifndef art_HessianMetric_h
#define art_HessianMetric_h

#include "AdaptiveRTReductionModule.h"
#include "VoxelVolume.h"

#include <functional>
#include <vector>

namespace art
{
struct MetricOptions
{
  double Sigma = 1.0;        ///< Gaussian smoothing of the voxels before the Hessian (voxels)
  double TensorSigma = 1.0;  ///< Gaussian smoothing of |H| (voxels; 0: none)
  double Exponent = 4;       ///< p of the L^p norm the metric is optimal for
  double Hmin = 0.7;         ///< shortest edge the metric asks for (voxels)
  double Hmax = 24;          ///< longest edge (voxels)
  double Floor = 1e-4;       ///< least eigenvalue of |H|, as a fraction of the scalar range per voxel^2
};

class ADAPTIVERTREDUCTION_EXPORT HessianMetric
{
public:
  /// Builds |H| over the volume. `weight` (optional, one per voxel) scales |H| voxel by voxel:
  /// where the error counts more (a transfer function's opacity ramps), edges get shorter.
  /// `done` (optional) is told the fraction done, on the calling thread.
  HessianMetric(const VoxelVolume& volume, const MetricOptions& options, const std::vector<float>* weight = nullptr,
    const std::function<void(double)>& done = {});

  /// The metric at p (voxel index coordinates) at scale D, packed m11 m12 m13 m22 m23 m33.
  void At(const double p[3], double scale, double m[6]) const;
  /// |H| at p (trilinear in the smoothed field), packed.
  void HessianAt(const double p[3], double h[6]) const;

  /// |H| at a point, decomposed once for the many scales a calibration tries.
  struct Local
  {
    double Lambda[3];     ///< eigenvalues, floored
    double Vectors[3][3]; ///< unit eigenvectors
  };
  Local Decompose(const double p[3]) const;
  /// sqrt(det M) of the metric at scale D (its vertex density).
  double Density(const Local& l, double scale) const;
  /// The metric at scale D, packed.
  void Compose(const Local& l, double scale, double m[6]) const;

  const MetricOptions& Options() const { return Opt; }
  /// The longest edge the metric asks for from now on (voxels).
  void SetHmax(double hmax) { Opt.Hmax = hmax; }

private:
  void Smooth(std::vector<float>& field, int components, double sigma) const;

  MetricOptions Opt;
  int Dims[3];
  double LambdaFloor = 0;
  std::vector<float> H; ///< 6 per voxel, |H| smoothed
};
} // namespace art

#endif
