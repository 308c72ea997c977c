// LobattoPiece: the exact rule's integral over one piece with linear extinction, inline. Over the
// piece, x in [0, 1], the optical depth is E(x) = A x + B x^2 and the rule needs
// J = int_0^1 exp(-E(x)) dx and T = exp(-E(1)). exp(-E) is smooth, so Gauss-Lobatto quadrature,
// whose last node is x = 1, gives both from one vector of exponentials: 5 nodes (3 inside) within
// 2.4e-9 of J up to a largest slope max(tau0, tau1) l of 0.4, 9 nodes (7 inside) within 6e-10 up
// to 6 (checked against mpmath). The exponential is inline: Cody & Waite's reduction and a
// Taylor polynomial to r^10, 2e-13 relative. Written with GCC vectors of four doubles, so a build
// for wider registers takes the four exponentials at once.
#ifndef art_LobattoPiece_h
#define art_LobattoPiece_h

#include <cstdint>
#include <cstring>

#if defined(__GNUC__)
#define ART_PIECE_INLINE inline __attribute__((always_inline))
#else
#define ART_PIECE_INLINE inline
#endif

namespace art
{
namespace lobatto
{
using V4 = double __attribute__((vector_size(32)));
using V4i = std::int64_t __attribute__((vector_size(32)));

/// y <- exp(-y) for 0 <= y <= 700 (V: double or V4, VI the same-sized integers). In place: a
/// vector passed or returned by value would have an ABI of its own for each build.
template <class V, class VI>
ART_PIECE_INLINE void ExpMinus(V& y)
{
  constexpr double log2e = 1.4426950408889634074, ln2hi = 0.693147180369123816490, ln2lo = 1.90821492927058770002e-10;
  constexpr double magic = 6755399441055744.0;           // 1.5 * 2^52: adding it rounds to an integer
  constexpr std::int64_t magicBits = 0x4338000000000000; // its bits
  const V t = y * log2e + magic;
  const V k = t - magic;                   // round(y / ln 2)
  const V r = (k * ln2hi - y) + k * ln2lo; // e^-y = 2^-k e^r, |r| <= ln 2 / 2
  V p = r * (1.0 / 3628800) + 1.0 / 362880;
  p = p * r + 1.0 / 40320, p = p * r + 1.0 / 5040, p = p * r + 1.0 / 720, p = p * r + 1.0 / 120;
  p = p * r + 1.0 / 24, p = p * r + 1.0 / 6, p = p * r + 0.5, p = p * r + 1.0, p = p * r + 1.0;
  VI ti;
  std::memcpy(&ti, &t, sizeof t);
  const VI e = (1023 - (ti - magicBits)) << 52; // the bits of 2^-k
  V scale;
  std::memcpy(&scale, &e, sizeof e);
  y = p * scale;
}

/// J and T of the piece with E(x) = A x + B x^2 (A >= 0, A + 2B >= 0) and largest slope
/// max(A, A + 2B) <= 6; false (nothing set) for a steeper piece.
ART_PIECE_INLINE bool Piece(double A, double B, double slope, double& J, double& T)
{
  if (slope <= 0.4)
  {
    const V4 x = { 0.172673164646011428101, 0.5, 0.827326835353988571899, 1.0 };
    const V4 w = { 0.272222222222222222222, 0.355555555555555555556, 0.272222222222222222222, 0.05 };
    V4 f = x * (A + B * x);
    ExpMinus<V4, V4i>(f);
    const V4 wf = w * f;
    J = (0.05 + wf[0]) + (wf[1] + (wf[2] + wf[3]));
    T = f[3];
    return true;
  }
  if (slope <= 6.0)
  {
    const V4 x0 = { 0.0501210022942699213438, 0.161406860244631123277, 0.318441268086910920645, 0.5 };
    const V4 x1 = { 0.681558731913089079355, 0.838593139755368876723, 0.949878997705730078656, 1.0 };
    const V4 w0 = { 0.0827476807804027625232, 0.13726935625008086764, 0.173214255486523172558, 0.18575963718820861678 };
    const V4 w1 = { 0.173214255486523172558, 0.13726935625008086764, 0.0827476807804027625232, 0.0138888888888888888889 };
    V4 f0 = x0 * (A + B * x0), f1 = x1 * (A + B * x1);
    ExpMinus<V4, V4i>(f0);
    ExpMinus<V4, V4i>(f1);
    const V4 wf = w0 * f0 + w1 * f1;
    J = (0.0138888888888888888889 + wf[0]) + (wf[1] + (wf[2] + wf[3]));
    T = f1[3];
    return true;
  }
  return false;
}
} // namespace lobatto
} // namespace art

#endif
