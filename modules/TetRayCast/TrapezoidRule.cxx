#include "TrapezoidRule.h"

#include <cmath>

namespace art
{
void TrapezoidRule::IntegrateSpan(double s0, double s1, int i0, int i1, bool carried, double length, RayAccum& acc) const
{
  double c0[3], t0, c1[3], t1;
  if (carried)
  {
    c0[0] = acc.lastRgb[0], c0[1] = acc.lastRgb[1], c0[2] = acc.lastRgb[2], t0 = acc.lastTau;
  }
  else
  {
    TF.EvaluateIn(i0, s0, c0, t0);
  }
  TF.EvaluateIn(i1, s1, c1, t1);
  const double alpha = -std::expm1(-0.5 * length * (t0 + t1));
  for (int k = 0; k < 3; ++k)
  {
    acc.rgb[k] += acc.T * alpha * 0.5 * (c0[k] + c1[k]);
  }
  acc.T *= 1.0 - alpha;
  acc.lastS = s1, acc.lastI = i1, acc.lastKnown = true;
  acc.lastRgb[0] = c1[0], acc.lastRgb[1] = c1[1], acc.lastRgb[2] = c1[2], acc.lastTau = t1;
}
} // namespace art
