// ValueMagnitude: values the renderers and the reducer can compute with. Least-squares fits and
// errors square the values (past 1e150 the squares overflow to inf, below 1e-150 they vanish), and
// transfer functions scale by the range's inverse (a denormal range gives inf, and a crash).
#ifndef art_ValueMagnitude_h
#define art_ValueMagnitude_h

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace art
{
/// Throws art::Error naming `file` when the scalar range [lo, hi] (finite) reaches past 1e150 in
/// magnitude, or is not all zero and stays below 1e-150, with the way out (rescale the values).
inline void RequireComputableRange(double lo, double hi, const std::string& file)
{
  const double top = std::max(std::fabs(lo), std::fabs(hi));
  if (!(top > 1e150) && !(top > 0.0 && top < 1e-150))
  {
    return;
  }
  char msg[320];
  std::snprintf(msg, sizeof msg,
    "the scalars' range %.6g .. %.6g %s: rendering and reducing compute with squares of the values, "
    "which %s; rescale them first (e.g. vtkImageShiftScale, ParaView's Calculator, or numpy)",
    lo, hi, top > 1e150 ? "reaches beyond 1e150 in magnitude" : "lies below 1e-150 in magnitude",
    top > 1e150 ? "overflow to infinity" : "vanish to 0");
  throw Error(msg, file);
}
} // namespace art

#endif
