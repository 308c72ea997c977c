#include "ExactIntegrator.h"

#include <algorithm>
#include <cmath>

namespace art
{
namespace
{
// Gauss-Legendre nodes and weights on [0, 1].
struct Rule
{
  int n;
  double x[6], w[6];
};
constexpr Rule G3{ 3, { 0.1127016653792583, 0.5, 0.8872983346207417 },
  { 0.2777777777777778, 0.4444444444444444, 0.2777777777777778 } };
constexpr Rule G4{ 4, { 0.0694318442029737, 0.3300094782075719, 0.6699905217924281, 0.9305681557970263 },
  { 0.1739274225687269, 0.3260725774312731, 0.3260725774312731, 0.1739274225687269 } };
constexpr Rule G6{ 6,
  { 0.0337652428984240, 0.1693953067668677, 0.3806904069584015, 0.6193095930415985,
    0.8306046932331323, 0.9662347571015760 },
  { 0.0856622461895852, 0.1803807865240693, 0.2339569672863455, 0.2339569672863455,
    0.1803807865240693, 0.0856622461895852 } };
// erfcx(x) = exp(x^2) erfc(x) for x >= 0: direct below 25 (erfc is accurate to its last bits
// and exp(x^2) does not overflow there), the asymptotic series above (relative error < 1e-13).
double Erfcx(double x)
{
  if (x < 25.0)
  {
    return std::exp(x * x) * std::erfc(x);
  }
  const double r = 1.0 / (x * x);
  return (1.0 - r * (0.5 - r * (0.75 - r * (1.875 - r * 6.5625)))) / (x * 1.7724538509055160273);
}
} // namespace

void IntegrateLinearPiece(const double c0[3], const double c1[3], double tau0, double tau1,
  double l, double C[3], double& T)
{
  // Optical depth E(x) = A x + B x^2 over x in [0, 1] (x = s / l); E' = tau(x) l >= 0.
  const double A = tau0 * l, B = 0.5 * (tau1 - tau0) * l;
  const double D = A + B;
  if (!(D > 0.0))
  {
    C[0] = C[1] = C[2] = 0.0;
    T = 1.0;
    return;
  }
  const double slope = std::max(tau0, tau1) * l; // largest E' on [0, 1]
  // E is quadratic, so the rule must be exact to degree ~2n in x: G4 below slope 0.01, G6 below
  // 0.5 and pieces of slope <= 0.5 above keep the quadrature error under 1e-12 relative.
  if (slope <= 0.5)
  {
    // Thin: C = c0 a + c1 b with a = 1 - J/l = -int expm1(-E) and b = J/l - T = (1 - T) - a,
    // both small and positive and neither formed by cancellation; one expm1 per node.
    const Rule& r = slope <= 1e-4 ? G3 : (slope <= 0.01 ? G4 : G6);
    double a = 0.0;
    for (int i = 0; i < r.n; ++i)
    {
      a -= r.w[i] * std::expm1(-r.x[i] * (A + B * r.x[i]));
    }
    const double oneMinusT = -std::expm1(-D);
    T = 1.0 - oneMinusT;
    const double b = oneMinusT - a;
    for (int k = 0; k < 3; ++k)
    {
      C[k] = c0[k] * a + c1[k] * b;
    }
    return;
  }
  T = std::exp(-D);
  if (B > 0.0)
  {
    // Thick, rising extinction: J/l = sqrt(pi)/(2 sqrt(B)) [erfcx(x0) - exp(-D) erfcx(x1)]
    // (Williams & Max 1992 in scaled form); erfcx falls, so nothing cancels when D > 0.25.
    const double sb = std::sqrt(B);
    const double x0 = 0.5 * A / sb, x1 = x0 + sb;
    const double J = 0.88622692545275801365 / sb * (Erfcx(x0) - T * Erfcx(x1));
    for (int k = 0; k < 3; ++k)
    {
      C[k] = std::max(0.0, c0[k] - c1[k] * T + (c1[k] - c0[k]) * J);
    }
    return;
  }
  if (B == 0.0)
  {
    const double J = -std::expm1(-A) / A;
    for (int k = 0; k < 3; ++k)
    {
      C[k] = std::max(0.0, c0[k] - c1[k] * T + (c1[k] - c0[k]) * J);
    }
    return;
  }
  // Thick, falling extinction: J/l = int_0^1 exp(-E) on sub-pieces of slope <= 0.5; stop once exp(-E) < 1e-20.
  const int m = static_cast<int>(std::ceil(2.0 * slope));
  const double h = 1.0 / m;
  double J = 0.0;
  for (int p = 0; p < m; ++p)
  {
    const double x0 = p * h;
    if (x0 * (A + B * x0) > 46.0)
    {
      break;
    }
    double sum = 0.0;
    for (int i = 0; i < G6.n; ++i)
    {
      const double x = x0 + h * G6.x[i];
      sum += G6.w[i] * std::exp(-x * (A + B * x));
    }
    J += h * sum;
  }
  for (int k = 0; k < 3; ++k)
  {
    C[k] = std::max(0.0, c0[k] - c1[k] * T + (c1[k] - c0[k]) * J);
  }
}

void ExactIntegrator::Integrate(double s0, double s1, double length, RayAccum& acc) const
{
  if (!(length > 0.0))
  {
    return;
  }
  const auto& n = TF.Nodes();
  const int last = static_cast<int>(n.size()) - 1;
  double ca[3], ta, cb[3], tb, C[3], T;
  if (s0 == acc.lastS)
  {
    ca[0] = acc.lastRgb[0], ca[1] = acc.lastRgb[1], ca[2] = acc.lastRgb[2], ta = acc.lastTau;
  }
  else
  {
    TF.Evaluate(s0, ca, ta);
  }
  auto remember = [&] {
    acc.lastS = s1;
    acc.lastRgb[0] = ca[0], acc.lastRgb[1] = ca[1], acc.lastRgb[2] = ca[2], acc.lastTau = ta;
  };
  auto piece = [&](double sb, double l) {
    TF.Evaluate(sb, cb, tb);
    IntegrateLinearPiece(ca, cb, ta, tb, l, C, T);
    for (int k = 0; k < 3; ++k)
    {
      acc.rgb[k] += acc.T * C[k];
      ca[k] = cb[k];
    }
    acc.T *= T;
    ta = tb;
  };
  const double ds = s1 - s0;
  if (ds == 0.0)
  {
    piece(s1, length);
    remember();
    return;
  }
  // Control points strictly between s0 and s1, in the order the ray meets them.
  double sa = s0;
  if (ds > 0)
  {
    for (int i = std::max(0, TF.Locate(s0) + 1); i <= last && n[i].s < s1; ++i)
    {
      if (n[i].s > sa)
      {
        piece(n[i].s, length * (n[i].s - sa) / ds);
        sa = n[i].s;
      }
    }
  }
  else
  {
    for (int i = std::min(last, TF.Locate(s0)); i >= 0 && n[i].s > s1; --i)
    {
      if (n[i].s < sa)
      {
        piece(n[i].s, length * (n[i].s - sa) / ds);
        sa = n[i].s;
      }
    }
  }
  piece(s1, length * (s1 - sa) / ds);
  remember();
}

void TrapezoidRule::Integrate(double s0, double s1, double length, RayAccum& acc) const
{
  if (!(length > 0.0))
  {
    return;
  }
  double c0[3], t0, c1[3], t1;
  TF.Evaluate(s0, c0, t0);
  TF.Evaluate(s1, c1, t1);
  const double alpha = -std::expm1(-0.5 * length * (t0 + t1));
  for (int k = 0; k < 3; ++k)
  {
    acc.rgb[k] += acc.T * alpha * 0.5 * (c0[k] + c1[k]);
  }
  acc.T *= 1.0 - alpha;
}
} // namespace art
