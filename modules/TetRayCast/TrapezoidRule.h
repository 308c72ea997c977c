// TrapezoidRule: the seed paper's segment rule (Grosso, Luerig & Ertl 1997, sec. 5): the transfer
// function sampled at the segment's two ends only, alpha = 1 - exp(-l (tau0 + tau1) / 2) and the
// colour (c0 + c1) / 2 premultiplied by alpha. Cheap, and off wherever the transfer function bends
// inside a cell (ExactIntegrator splits there).
#ifndef art_TrapezoidRule_h
#define art_TrapezoidRule_h

#include "AdaptiveRTTetRayCastModule.h"
#include "SegmentRule.h"

namespace art
{
class ADAPTIVERTTETRAYCAST_EXPORT TrapezoidRule : public SegmentRule<TrapezoidRule>
{
public:
  using SegmentRule::SegmentRule;

private:
  friend class SegmentRule<TrapezoidRule>;
  void IntegrateSpan(double s0, double s1, int i0, int i1, bool carried, double length, RayAccum& acc) const;
};
} // namespace art

#endif
