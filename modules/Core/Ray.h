// Ray: origin, direction and the parameter interval [tmin, tmax] a query may report hits in.
// The direction need not be unit length; t is measured in units of |dir|.
#ifndef art_Ray_h
#define art_Ray_h

#include "Vec3.h"

#include <limits>

namespace art
{
struct Ray
{
  Vec3 org;
  Vec3 dir;
  double tmin = 0.0;
  double tmax = std::numeric_limits<double>::infinity();

  Vec3 At(double t) const { return org + dir * t; }
  // A zero or non-finite direction has no hits; engines check this first instead of crashing.
  bool IsValid() const { return IsFinite(org) && IsFinite(dir) && Dot(dir, dir) > 0.0; }
};
} // namespace art

#endif
