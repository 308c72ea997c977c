// ExitFallback: the walk's stability fix for rays the side products cannot place strictly inside
// one exit face: through an edge or a vertex (a zero product), in a face plane, or numerically
// lost. A proper exit (weights >= 0, not all zero) beats any other, among proper ones the most
// interior wins, and with none the least-violating face is taken with its weights clamped into
// it: the centroid nudge of Grosso, Luerig & Ertl 1997 (sec. 5), as a fallback only. Because each
// product is computed alike on both sides of a face, the choice never jumps a gap or leaks.
#ifndef art_ExitFallback_h
#define art_ExitFallback_h

#include <algorithm>
#include <cstdint>

#if defined(__GNUC__)
#define ART_COLD __attribute__((noinline, cold))
#else
#define ART_COLD
#endif

namespace art
{
/// The exit face for entry-edge products e and apex products p (FaceWalk.h's numbering: the face
/// opposite entry corner k has the corner weights -e[k] for the apex, p[k+1] and -p[k+2] for the
/// entry corners k+2 and k+1). Returns k and its weights clamped to >= 0 in w (apex first);
/// counts a face taken without a proper crossing in `nudges`.
ART_COLD inline int FallbackExit(const double e[3], const double p[3], double w[3], std::uint64_t& nudges)
{
  auto face = [&](int k, double f[3]) {
    f[0] = -e[k], f[1] = p[(k + 1) % 3], f[2] = -p[(k + 2) % 3];
  };
  int x = 3;
  double bestLo = -1e300;
  bool proper = false;
  for (int k = 0; k < 3; ++k)
  {
    double f[3];
    face(k, f);
    const double lo = std::min(f[0], std::min(f[1], f[2]));
    const bool ok = lo >= 0 && f[0] + f[1] + f[2] > 0;
    if ((ok && !proper) || (ok == proper && lo > bestLo))
    {
      proper = ok;
      bestLo = lo;
      x = k;
    }
  }
  nudges += proper ? 0 : 1;
  x = x < 3 ? x : 0; // every product NaN (coordinates near 1e150): any face, never past the tables
  face(x, w);
  for (int k = 0; k < 3; ++k)
  {
    w[k] = std::max(w[k], 0.0);
  }
  return x;
}
} // namespace art

#endif
