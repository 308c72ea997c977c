// Box3: axis-aligned box with the slab test (Kay & Kajiya), written so that rays parallel to an
// axis (direction components +0 or -0, giving infinite reciprocals) are handled exactly.
#ifndef art_Box3_h
#define art_Box3_h

#include "Ray.h"

#include <algorithm>
#include <limits>

namespace art
{
struct Box3
{
  Vec3 lo{ std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity() };
  Vec3 hi{ -std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
    -std::numeric_limits<double>::infinity() };

  Box3() = default;
  Box3(const Vec3& a, const Vec3& b) : lo(Min(a, b)), hi(Max(a, b)) {}
  // From VTK's bounds order (xmin, xmax, ymin, ymax, zmin, zmax).
  static Box3 FromBounds(const double b[6]) { return Box3({ b[0], b[2], b[4] }, { b[1], b[3], b[5] }); }

  bool Empty() const { return !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z); }
  void Expand(const Vec3& p) { lo = Min(lo, p); hi = Max(hi, p); }
  void Expand(const Box3& b) { lo = Min(lo, b.lo); hi = Max(hi, b.hi); }
  Vec3 Size() const { return hi - lo; }
  Vec3 Center() const { return (lo + hi) * 0.5; }
  double Diagonal() const { return Empty() ? 0.0 : Length(hi - lo); }
  bool Contains(const Vec3& p) const
  {
    return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }

  /// Clips the ray's [tmin, tmax] to the box. Returns false when the ray misses.
  /// A zero direction component keeps the whole interval if the origin lies within that slab.
  bool Clip(const Ray& r, double& t0, double& t1) const
  {
    t0 = r.tmin;
    t1 = r.tmax;
    for (int a = 0; a < 3; ++a)
    {
      const double d = r.dir[a], o = r.org[a];
      if (d == 0.0)
      {
        if (o < lo[a] || o > hi[a])
        {
          return false;
        }
        continue;
      }
      const double inv = 1.0 / d;
      double ta = (lo[a] - o) * inv, tb = (hi[a] - o) * inv;
      if (ta > tb)
      {
        std::swap(ta, tb);
      }
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      if (!(t0 <= t1))
      {
        return false;
      }
    }
    return true;
  }
};
} // namespace art

#endif
