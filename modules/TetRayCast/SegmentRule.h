// SegmentRule: what the segment rules share (emission-absorption along a straight segment on which
// the scalar is linear, Max 1995): front-to-back accumulation, early ray termination, and the
// transparency test inline. A segment whose scalar stays in transfer-function intervals without
// extinction neither absorbs nor emits; the others go to the rule's IntegrateSpan out of line.
// The transfer function's interval and values at a segment's end carry over to the next segment,
// which starts there.
#ifndef art_SegmentRule_h
#define art_SegmentRule_h

#include "TransferFunction.h"

#include <limits>

namespace art
{
/// Front-to-back accumulation along one ray: premultiplied colour and transmittance.
struct RayAccum
{
  double rgb[3] = { 0, 0, 0 };
  double T = 1.0;
  double Alpha() const { return 1.0 - T; }
  // The transfer function at the last segment's end: the next segment starts there.
  double lastS = std::numeric_limits<double>::quiet_NaN();
  int lastI = -1;          ///< its interval (TransferFunction::Locate)
  bool lastKnown = false;  ///< lastRgb and lastTau hold its values
  double lastRgb[3] = { 0, 0, 0 };
  double lastTau = 0;
};

/// Early ray termination: a ray stops once its opacity reaches `ert` (>= 1: never).
inline bool EarlyTerminated(const RayAccum& acc, double ert)
{
  return acc.Alpha() >= ert;
}

template <class Rule>
class SegmentRule
{
public:
  explicit SegmentRule(const TransferFunction& tf) : TF(tf) {}
  /// Composites the segment (scalar s0 -> s1 over `length` world units) behind `acc`.
#if defined(__GNUC__)
  __attribute__((always_inline))
#endif
  void Integrate(double s0, double s1, double length, RayAccum& acc) const
  {
    if (!(length > 0.0))
    {
      return;
    }
    const bool carried = s0 == acc.lastS;
    const int i0 = carried ? acc.lastI : TF.Locate(s0), i1 = TF.LocateFrom(s1, i0);
    if (TF.TransparentIntervals(i0, i1))
    {
      acc.lastS = s1, acc.lastI = i1, acc.lastKnown = false;
      return;
    }
    static_cast<const Rule&>(*this).IntegrateSpan(s0, s1, i0, i1, carried && acc.lastKnown, length, acc);
  }

protected:
  const TransferFunction& TF;
};
} // namespace art

#endif
