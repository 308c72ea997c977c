#include "ExactIntegrator.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

// The integrator's cost is chains of dependent multiply-adds (series and quadrature): where the
// CPU has fused multiply-add its entry points get a clone that uses it, chosen at load time, and
// one for x86-64-v3 (AVX2 too: the exponential's integer steps in one register, not two halves).
// Only here: the walkers need unfused products (see CMakeLists.txt).
#if defined(__GNUC__) && defined(__x86_64__) && defined(__linux__)
#define ART_FMA_CLONES __attribute__((target_clones("arch=x86-64-v3", "fma", "default")))
#else
#define ART_FMA_CLONES
#endif
#if defined(__GNUC__)
#define ART_ALWAYS_INLINE __attribute__((always_inline))
#else
#define ART_ALWAYS_INLINE
#endif
#define ART_INLINE inline ART_ALWAYS_INLINE

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

// Dawson's integral F and erfcx(x) = exp(x^2) erfc(x) by Taylor series about x_k = k/16 on [0, 8],
// 17 terms for |h| <= 1/32 (1e-15 relative, checked against mpmath). Both satisfy y' = 2 sx y + b:
// F' = 1 - 2xF (s = -1, b = 1), erfcx' = 2x erfcx - 2/sqrt(pi) (s = 1), so the coefficients follow
// (n+1) c_{n+1} = 2 s (x_k c_n + c_{n-1}). F's node values are stepped out from F(0) = 0 in long
// double (stable forwards); erfcx's come from expl and erfcl.
struct TaylorTable
{
  static constexpr int PerUnit = 16, Nodes = 8 * PerUnit + 1, Terms = 17, Steps = 40;
  double c[Nodes][Terms];
  template <class NodeValue>
  TaylorTable(int sign, long double b, NodeValue&& y)
  {
    long double F = 0;
    for (int k = 0; k < Nodes; ++k)
    {
      const long double xk = static_cast<long double>(k) / PerUnit;
      long double t[Steps];
      t[0] = y(xk, F);
      t[1] = 2 * sign * xk * t[0] + b;
      for (int n = 1; n + 1 < Steps; ++n)
      {
        t[n + 1] = 2 * sign * (xk * t[n] + t[n - 1]) / (n + 1);
      }
      for (int n = 0; n < Terms; ++n)
      {
        c[k][n] = static_cast<double>(t[n]);
      }
      long double next = 0; // the series one step on: the next node's value for a stepped table
      for (int n = Steps - 1; n >= 0; --n)
      {
        next = next / PerUnit + t[n];
      }
      F = next;
    }
  }
  ART_INLINE double operator()(double x) const
  {
    const int k = static_cast<int>(x * PerUnit + 0.5);
    const double h = x - static_cast<double>(k) / PerUnit;
    const double* ck = c[k];
    double v = 0.0;
    for (int n = Terms - 1; n >= 0; --n)
    {
      v = v * h + ck[n];
    }
    return v;
  }
};

// Asymptotic series 1 + sum_n (sign)^n (2n-1)!! / (2x^2)^n; 13 terms are below 1e-15 from x = 8.
ART_INLINE double AsymptoticSum(double x, double sign)
{
  const double r = 0.5 / (x * x);
  double sum = 1.0, term = 1.0;
  for (int n = 1; n <= 13; ++n)
  {
    term *= sign * (2 * n - 1) * r;
    sum += term;
  }
  return sum;
}

// expm1(y) for -0.5 <= y <= 0 by its Taylor series: 14 terms are within 3e-16 relative there, 8
// within 1e-16 for |y| <= 0.05. Thin pieces need 4-7 of these; inline polynomials cost a fraction
// of libm calls.
template <int Terms>
ART_INLINE double Expm1Small(double y)
{
  constexpr double c[14] = { 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720, 1.0 / 5040, 1.0 / 40320,
    1.0 / 362880, 1.0 / 3628800, 1.0 / 39916800, 1.0 / 479001600, 1.0 / 6227020800, 1.0 / 87178291200 };
  double p = c[Terms - 1];
  for (int k = Terms - 2; k >= 0; --k)
  {
    p = p * y + c[k];
  }
  return y * p;
}

// Thin piece: C = c0 a + c1 b with a = 1 - J/l = -int expm1(-E) and b = J/l - T = (1 - T) - a,
// both small and positive and neither formed by cancellation; one expm1 per node.
template <int Terms>
ART_INLINE void ThinPiece(const Rule& r, double A, double B, double D, const double c0[3], const double c1[3], double C[3],
  double& T)
{
  double a = 0.0;
  for (int i = 0; i < r.n; ++i)
  {
    a -= r.w[i] * Expm1Small<Terms>(-r.x[i] * (A + B * r.x[i]));
  }
  const double oneMinusT = -Expm1Small<Terms>(-D);
  T = 1.0 - oneMinusT;
  const double b = oneMinusT - a;
  for (int k = 0; k < 3; ++k)
  {
    C[k] = c0[k] * a + c1[k] * b;
  }
}

// The tables, built once on first use; outside the cloned functions below, so each clone does not
// get its own copy.
const TaylorTable& DawsonTable()
{
  static const TaylorTable table(-1, 1.0L, [](long double, long double stepped) { return stepped; });
  return table;
}

const TaylorTable& ErfcxTable()
{
  static const TaylorTable table(1, -1.1283791670955125738961589L,
    [](long double xk, long double) { return std::exp(xk * xk) * std::erfc(xk); });
  return table;
}

ART_INLINE double DawsonAt(double x)
{
  const double ax = std::fabs(x);
  double v;
  if (!(ax < 8.0))
  {
    v = std::isinf(ax) ? 0.0 : AsymptoticSum(ax, 1.0) / (2.0 * ax);
  }
  else
  {
    v = DawsonTable()(ax);
  }
  return x < 0 ? -v : v;
}

ART_INLINE double ErfcxAt(double x)
{
  if (!(x < 8.0))
  {
    return std::isinf(x) ? 0.0 : AsymptoticSum(x, -1.0) / (x * 1.7724538509055160273);
  }
  return ErfcxTable()(x);
}

ART_INLINE void PreciseLinearPiece(const double c0[3], const double c1[3], double tau0, double tau1, double l,
  double C[3], double& T)
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
  // E is quadratic, so the rule must be exact to degree ~2n in x: G3 below slope 1e-4, G4 below
  // 0.01 and G6 up to 0.5 keep the quadrature error under 1e-12 relative; thicker pieces are
  // taken in closed form below.
  if (slope <= 0.05)
  {
    ThinPiece<8>(slope <= 1e-4 ? G3 : (slope <= 0.01 ? G4 : G6), A, B, D, c0, c1, C, T);
    return;
  }
  if (slope <= 0.5)
  {
    ThinPiece<14>(G6, A, B, D, c0, c1, C, T);
    return;
  }
  T = std::exp(-D);
  if (B > 0.0)
  {
    // Thick, rising extinction: J/l = sqrt(pi)/(2 sqrt(B)) [erfcx(x0) - exp(-D) erfcx(x1)]
    // (Williams & Max 1992 in scaled form); erfcx falls, so nothing cancels when D > 0.25.
    const double sb = std::sqrt(B);
    const double x0 = 0.5 * A / sb, x1 = x0 + sb;
    const double J = 0.88622692545275801365 / sb * (ErfcxAt(x0) - T * ErfcxAt(x1));
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
  // Thick, falling extinction: read backwards from the far end the piece's exp(-E) is a rising
  // Gaussian, and J/l = [F(y1) - T F(y0)] / sqrt(-B) with Dawson's integral F,
  // y0 = tau1 l / (2 sqrt(-B)), y1 = y0 + sqrt(-B). T <= exp(-1/4) here, so nothing cancels.
  const double sb = std::sqrt(-B);
  const double y0 = 0.5 * std::max(A + 2.0 * B, 0.0) / sb, y1 = y0 + sb;
  const double J = (DawsonAt(y1) - T * DawsonAt(y0)) / sb;
  for (int k = 0; k < 3; ++k)
  {
    C[k] = std::max(0.0, c0[k] - c1[k] * T + (c1[k] - c0[k]) * J);
  }
}
ART_INLINE void FastLinearPiece(const double c0[3], const double c1[3], double tau0, double tau1, double l,
  double C[3], double& T)
{
  const double A = tau0 * l, B = 0.5 * (tau1 - tau0) * l;
  double J;
  if (!(A + B > 0.0) || !lobatto::Piece(A, B, std::max(tau0, tau1) * l, J, T))
  {
    PreciseLinearPiece(c0, c1, tau0, tau1, l, C, T);
    return;
  }
  const double a = 1.0 - J, b = (1.0 - T) - a;
  for (int k = 0; k < 3; ++k)
  {
    C[k] = std::max(0.0, c0[k] * a + c1[k] * b);
  }
}

// The exact rule over one segment: split at the control points between s0 and s1.
template <bool Precise>
ART_INLINE void SplitSpan(const TransferFunction& TF, double s0, double s1, int i0, int i1, bool carried,
  double length, RayAccum& acc)
{
  const auto& n = TF.Nodes();
  double ca[3], ta, cb[3], tb, C[3], T;
  if (carried)
  {
    ca[0] = acc.lastRgb[0], ca[1] = acc.lastRgb[1], ca[2] = acc.lastRgb[2], ta = acc.lastTau;
  }
  else
  {
    TF.EvaluateIn(i0, s0, ca, ta);
  }
  auto composite = [&](double l) ART_ALWAYS_INLINE {
    // A piece between two transparent control points adds nothing.
    if (ta > 0.0 || tb > 0.0)
    {
      if constexpr (Precise)
      {
        PreciseLinearPiece(ca, cb, ta, tb, l, C, T);
      }
      else
      {
        FastLinearPiece(ca, cb, ta, tb, l, C, T);
      }
      for (int k = 0; k < 3; ++k)
      {
        acc.rgb[k] += acc.T * C[k];
      }
      acc.T *= T;
    }
    ca[0] = cb[0], ca[1] = cb[1], ca[2] = cb[2], ta = tb;
  };
  // Pieces end at the control points strictly between s0 and s1, in the order the ray meets them.
  const double ds = s1 - s0;
  double sa = s0;
  if (i1 > i0)
  {
    for (int i = i0 + 1; i <= i1; ++i)
    {
      if (n[i].s > sa && n[i].s < s1)
      {
        cb[0] = n[i].rgb[0], cb[1] = n[i].rgb[1], cb[2] = n[i].rgb[2], tb = n[i].tau;
        composite(length * (n[i].s - sa) / ds);
        sa = n[i].s;
      }
    }
  }
  else if (i1 < i0)
  {
    for (int i = i0; i > i1; --i)
    {
      if (n[i].s < sa && n[i].s > s1)
      {
        cb[0] = n[i].rgb[0], cb[1] = n[i].rgb[1], cb[2] = n[i].rgb[2], tb = n[i].tau;
        composite(length * (n[i].s - sa) / ds);
        sa = n[i].s;
      }
    }
  }
  TF.EvaluateIn(i1, s1, cb, tb);
  composite(ds == 0.0 ? length : length * (s1 - sa) / ds);
  acc.lastS = s1, acc.lastI = i1, acc.lastKnown = true;
  acc.lastRgb[0] = ca[0], acc.lastRgb[1] = ca[1], acc.lastRgb[2] = ca[2], acc.lastTau = ta;
}
} // namespace

ART_FMA_CLONES void ExactIntegrator::Span(double s0, double s1, int i0, int i1, bool carried, double length,
  RayAccum& acc) const
{
  if (Exact)
  {
    SplitSpan<true>(TF, s0, s1, i0, i1, carried, length, acc);
  }
  else
  {
    SplitSpan<false>(TF, s0, s1, i0, i1, carried, length, acc);
  }
}

void IntegrateLinearPieceFast(const double c0[3], const double c1[3], double tau0, double tau1, double l,
  double C[3], double& T)
{
  FastLinearPiece(c0, c1, tau0, tau1, l, C, T);
}

double Dawson(double x)
{
  return DawsonAt(x);
}

double Erfcx(double x)
{
  return ErfcxAt(x);
}

ART_FMA_CLONES void IntegrateLinearPiece(const double c0[3], const double c1[3], double tau0, double tau1,
  double l, double C[3], double& T)
{
  PreciseLinearPiece(c0, c1, tau0, tau1, l, C, T);
}
} // namespace art
