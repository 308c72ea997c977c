// ExactIntegrator: the exact segment rule. Emission-absorption along one straight segment on which
// the scalar is linear (inside a tetrahedron): the segment is split at the transfer function's
// control points; on each piece colour c and extinction tau are linear in distance, and
//   C = int_0^l c(s) tau(s) exp(-int_0^s tau) ds = c0 - c1 T + (c1 - c0)/l int_0^l exp(-E(s)) ds
// (integration by parts; Williams & Max 1992 give the same integral through erf). The remaining
// integral J of exp(-quadratic) is smooth: Gauss-Lobatto quadrature (LobattoPiece.h) gives it
// and the piece's transmittance within 2.4e-9 (absolute) up to a largest optical slope of 6;
// thicker pieces take the closed form (erfcx for rising, Dawson's integral for falling
// extinction). No table over the transfer function, unlike VTK's pre-integration.
// IntegrateLinearPiece is the same piece to round-off relative to what it emits, for thin and
// thick pieces alike (series and quadrature in expm1 form): the rule of ExactIntegrator::Precise.
#ifndef art_ExactIntegrator_h
#define art_ExactIntegrator_h

#include "AdaptiveRTTetRayCastModule.h"
#include "LobattoPiece.h"
#include "SegmentRule.h"
#include "TrapezoidRule.h"

namespace art
{
/// Dawson's integral F(x) = exp(-x^2) int_0^x exp(t^2) dt, to about 1e-15 relative.
ADAPTIVERTTETRAYCAST_EXPORT double Dawson(double x);
/// The scaled complementary error function exp(x^2) erfc(x) for x >= 0, to about 1e-15 relative.
ADAPTIVERTTETRAYCAST_EXPORT double Erfcx(double x);

/// One piece with linear colour and extinction, to round-off relative to what it emits:
/// premultiplied colour C and transmittance T.
ADAPTIVERTTETRAYCAST_EXPORT void IntegrateLinearPiece(const double c0[3], const double c1[3],
  double tau0, double tau1, double length, double C[3], double& T);

/// The rule's piece (LobattoPiece.h, the closed form past its range): within 2.4e-9 of
/// IntegrateLinearPiece in C and T, absolute.
ADAPTIVERTTETRAYCAST_EXPORT void IntegrateLinearPieceFast(const double c0[3], const double c1[3],
  double tau0, double tau1, double length, double C[3], double& T);

/// Split at the transfer function's control points, each piece by LobattoPiece (the closed form
/// past its range). A segment inside one interval is integrated inline; one across control
/// points goes out of line.
class ADAPTIVERTTETRAYCAST_EXPORT ExactIntegrator : public SegmentRule<ExactIntegrator>
{
public:
  explicit ExactIntegrator(const TransferFunction& tf) : SegmentRule(tf) {}
  /// The same rule with every piece to round-off (IntegrateLinearPiece): for references.
  static ExactIntegrator Precise(const TransferFunction& tf)
  {
    ExactIntegrator e(tf);
    e.Exact = true;
    return e;
  }

private:
  friend class SegmentRule<ExactIntegrator>;
#if defined(__GNUC__)
  __attribute__((always_inline))
#endif
  void IntegrateSpan(double s0, double s1, int i0, int i1, bool carried, double length, RayAccum& acc) const
  {
    if (!(i0 == i1 && !Exact && OnePiece(s0, s1, i1, carried, length, acc)))
    {
      Span(s0, s1, i0, i1, carried, length, acc);
    }
  }
#if defined(__GNUC__)
  __attribute__((always_inline))
#endif
  bool OnePiece(double s0, double s1, int i, bool carried, double l, RayAccum& acc) const
  {
    double ca[3], ta, cb[3], tb;
    if (carried)
    {
      ca[0] = acc.lastRgb[0], ca[1] = acc.lastRgb[1], ca[2] = acc.lastRgb[2], ta = acc.lastTau;
    }
    else
    {
      TF.EvaluateIn(i, s0, ca, ta);
    }
    TF.EvaluateIn(i, s1, cb, tb);
    const double A = ta * l, B = 0.5 * (tb - ta) * l;
    double J, T;
    if (!(A + B > 0.0) || !lobatto::Piece(A, B, (ta > tb ? ta : tb) * l, J, T))
    {
      return false;
    }
    // C = c0 (1 - J) + c1 (J - T): absolute errors of 1e-16 where a thin piece emits little.
    const double a = 1.0 - J, b = (1.0 - T) - a;
    for (int k = 0; k < 3; ++k)
    {
      const double C = ca[k] * a + cb[k] * b;
      acc.rgb[k] += acc.T * (C > 0.0 ? C : 0.0);
    }
    acc.T *= T;
    acc.lastS = s1, acc.lastI = i, acc.lastKnown = true;
    acc.lastRgb[0] = cb[0], acc.lastRgb[1] = cb[1], acc.lastRgb[2] = cb[2], acc.lastTau = tb;
    return true;
  }
  /// The general case, out of line: split at the control points.
  void Span(double s0, double s1, int i0, int i1, bool carried, double length, RayAccum& acc) const;

  bool Exact = false;
};
} // namespace art

#endif
