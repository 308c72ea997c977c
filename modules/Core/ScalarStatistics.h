// ScalarStatistics: what a default transfer function needs to know of a field's samples, as
// ParaView's and 3D Slicer's automatic presets look at it: the range, the background (a value
// most samples share at the bottom of the range: the air around a scan, an MRI's zero), a robust
// window over the rest (percentiles, so a few outliers do not stretch it), and whether the
// samples are labels (few distinct integers, as a segmentation holds).
#ifndef art_ScalarStatistics_h
#define art_ScalarStatistics_h

#include "AdaptiveRTCoreModule.h"

#include <functional>
#include <vector>

namespace art
{
struct ScalarStatistics
{
  double lo = 0, hi = 0;         ///< the samples' range
  bool hasBackground = false;
  double backgroundTop = 0;      ///< the background's upper edge, when there is one
  double windowLow = 0, windowHigh = 0; ///< 1st and 99.5th percentiles of the non-background samples
  bool labels = false;           ///< few distinct integer values
  std::vector<double> labelValues; ///< their values, ascending, when labels
  long long samples = 0;

  /// The fraction of [lo, hi] a background bin may reach up to, and the share of all samples it
  /// must hold.
  static constexpr double BackgroundRangeFraction = 0.02;
  static constexpr double BackgroundShare = 0.10;
  static constexpr int MaxLabels = 64;
};

/// Summarises n samples given by value(i) (NaN skipped). `integers`: the samples are of an
/// integer type (labels are looked for only then).
ADAPTIVERTCORE_EXPORT ScalarStatistics Summarize(
  long long n, const std::function<double(long long)>& value, bool integers);
} // namespace art

#endif
