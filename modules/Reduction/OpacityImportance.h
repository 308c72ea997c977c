// OpacityImportance: per-voxel weights for a reduction that serves a transfer function ("model no
// more than the scene needs"; the weighted L2 norm of the seed's error estimate, Grosso et al. Vis '97
// section 4, with the opacity's sensitivity as the weight). A scalar error ds changes opacity by
// about alpha'(s) ds, so a voxel weighs (max |alpha'| over its neighbourhood's scalar range)^2.
#ifndef art_OpacityImportance_h
#define art_OpacityImportance_h

#include "AdaptiveRTReductionModule.h"
#include "VoxelVolume.h"

#include <algorithm>
#include <functional>
#include <utility>
#include <vector>

namespace art
{
class ADAPTIVERTREDUCTION_EXPORT OpacityImportance
{
public:
  /// (scalar, opacity) nodes, piecewise linear between them and clamped outside, as VTK's
  /// vtkPiecewiseFunction. Throws art::Error when empty, not finite, with a negative opacity, or
  /// when the scalars do not strictly increase.
  explicit OpacityImportance(std::vector<std::pair<double, double>> nodes);

  /// Iso-surfaces drawn over the transfer function: a voxel whose neighbourhood's range holds one
  /// of these values weighs as much as the steepest opacity ramp (the surface moves by the fit's
  /// error over the gradient there, as sharply as an opacity step shows it). Before Prepare.
  void SetIsoValues(std::vector<double> values);

  /// Largest |d alpha / ds| over the scalar interval [lo, hi] (0 where the opacity is flat); an
  /// iso-value inside counts as the steepest slope.
  double MaxSlope(double lo, double hi) const;
  /// Opacity at s.
  double Opacity(double s) const;
  /// Largest opacity over the scalar interval [lo, hi].
  double MaxOpacity(double lo, double hi) const;

  /// Gathers each voxel's neighbourhood scalar range: min..max over its (2 radius + 1)^3 voxels.
  /// `floor` in (0, 1] is the least weight (keeps the fit's matrix SPD, abandons no region).
  /// `done` (optional) is told the fraction done after each of its four voxel passes, on the
  /// calling thread.
  void Prepare(const VoxelVolume& volume, double floor, int radius = 2, const std::function<void(double)>& done = {});

  /// Weight of voxel i (sample f) in [floor, 1]: floor + (1 - floor) (g / g_max)^2, g the largest
  /// opacity slope over its neighbourhood's scalar range widened to hold `fit` (Prepare first): a
  /// fit that strays into an opacity ramp (a ghost shell in empty space) weighs as much as the ramp.
  double Weight(long long i, double f, double fit) const
  {
    if (Flat(i, f, fit))
    {
      return W0[i];
    }
    const double lo = std::min<double>(std::min<double>(Lo[i], f), fit);
    const double hi = std::max<double>(std::max<double>(Hi[i], f), fit);
    return Scaled(MaxSlope(lo, hi));
  }
  /// Does voxel i (sample f) weigh W0 at this fit? True while the fit stays in (FlatLo, FlatHi):
  /// its neighbourhood's range widened up to the nearest opacity segment steeper than the
  /// range's own slope (air stays flat up to the skin's ramp, whatever the fit does in between).
  bool Flat(long long i, double f, double fit) const
  {
    return fit > PL[i] && fit < PH[i] && f > PL[i] && f < PH[i];
  }
  double FlatLo(long long i) const { return PL[i]; }
  double FlatHi(long long i) const { return PH[i]; }

  /// The error that counts at voxel i (sample f, approximation u), squared: w (u - f)^2 with
  /// w = Weight(i, f, u), the weight of a majorise-minimise (iteratively reweighted) fit.
  double Error2(long long i, double f, double u) const
  {
    const double e = u - f;
    return Weight(i, f, u) * e * e;
  }

  const std::vector<std::pair<double, double>>& Nodes() const { return N; }
  double Floor() const { return Fl; }

private:
  double Scaled(double g) const
  {
    const double r = GMax > 0 ? g / GMax : 1.0;
    return Fl + (1.0 - Fl) * r * r;
  }

  std::vector<std::pair<double, double>> N;
  std::vector<double> Iso; ///< sorted
  double GIso = 0;         ///< the slope an iso-value counts as (Prepare)
  std::vector<float> Lo, Hi;
  std::vector<float> W0; ///< Weight with the fit inside [Lo, Hi] (float, as Lo and Hi: 4 bytes a voxel)
  std::vector<float> PL, PH; ///< Flat's open interval, rounded inwards
  double Fl = 1, GMax = 0;
};
} // namespace art

#endif
