// ExactIntegrator: emission-absorption along one straight segment on which the scalar is linear
// (inside a tetrahedron). The segment is split at the transfer function's control points; on each
// piece colour c and extinction tau are linear in distance, and
//   C = int_0^l c(s) tau(s) exp(-int_0^s tau) ds = c0 - c1 T + (c1 - c0)/l int_0^l exp(-E(s)) ds
// (integration by parts; Williams & Max 1992 give the same integral through erf). The remaining
// integral of exp(-quadratic) is taken in closed form for thick pieces (erfcx for rising, Dawson's
// integral for falling extinction) and by Gauss-Legendre in an expm1 form for thin ones, so it is
// accurate to round-off for very thin and very thick cells alike (no table over the transfer
// function, unlike VTK's pre-integration). TrapezoidRule is the seed paper's rule
// (Grosso, Luerig & Ertl 1997): transfer function sampled at the two ends only.
#ifndef art_ExactIntegrator_h
#define art_ExactIntegrator_h

#include "AdaptiveRTTetRayCastModule.h"
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
  double lastRgb[3] = { 0, 0, 0 };
  double lastTau = 0;
  int lastI = -1; ///< its transfer-function interval (TransferFunction::Locate)
};

/// Dawson's integral F(x) = exp(-x^2) int_0^x exp(t^2) dt, to about 1e-15 relative.
ADAPTIVERTTETRAYCAST_EXPORT double Dawson(double x);
/// The scaled complementary error function exp(x^2) erfc(x) for x >= 0, to about 1e-15 relative.
ADAPTIVERTTETRAYCAST_EXPORT double Erfcx(double x);

/// One piece with linear colour and extinction: premultiplied colour C and transmittance T.
ADAPTIVERTTETRAYCAST_EXPORT void IntegrateLinearPiece(const double c0[3], const double c1[3],
  double tau0, double tau1, double length, double C[3], double& T);

/// What both segment rules share: the transparency test inline (most segments of a typical
/// transfer function end at it), the integration out of line in Rule::IntegrateSpan.
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
    if (length > 0.0 && !TF.Transparent(s0, s1))
    {
      static_cast<const Rule&>(*this).IntegrateSpan(s0, s1, length, acc);
    }
  }

protected:
  const TransferFunction& TF;
};

/// Split at the transfer function's control points, each piece in closed form (IntegrateLinearPiece).
class ADAPTIVERTTETRAYCAST_EXPORT ExactIntegrator : public SegmentRule<ExactIntegrator>
{
public:
  using SegmentRule::SegmentRule;

private:
  friend class SegmentRule<ExactIntegrator>;
  void IntegrateSpan(double s0, double s1, double length, RayAccum& acc) const;
};

/// The seed paper's rule: alpha = 1 - exp(-l (tau0 + tau1) / 2), colour (c0 + c1) / 2 premultiplied by alpha.
class ADAPTIVERTTETRAYCAST_EXPORT TrapezoidRule : public SegmentRule<TrapezoidRule>
{
public:
  using SegmentRule::SegmentRule;

private:
  friend class SegmentRule<TrapezoidRule>;
  void IntegrateSpan(double s0, double s1, double length, RayAccum& acc) const;
};
} // namespace art

#endif
