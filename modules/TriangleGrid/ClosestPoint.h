// ClosestPoint: the exact closest point of a triangle to a point (Ericson, "Real-Time Collision
// Detection", section 5.1.5: the Voronoi regions of the vertices, edges and face), in double, and
// the point/box distance that bounds the accelerators' nearest-point searches.
#ifndef art_ClosestPoint_h
#define art_ClosestPoint_h

#include "Box3.h"

#include <cfloat>
#include <cmath>

namespace art
{
/// The point of triangle (a, b, c) nearest p, as q = a + u (b - a) + v (c - a) (u, v: the weights of
/// b and c). Returns true when q lies in the face region (p projects inside the triangle), false when
/// it lies on an edge or vertex.
inline bool ClosestPointOnTriangle(
  const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, Vec3& q, double& u, double& v)
{
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
  if (d1 <= 0 && d2 <= 0)
  {
    u = v = 0;
    q = a;
    return false;
  }
  const Vec3 bp = p - b;
  const double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
  if (d3 >= 0 && d4 <= d3)
  {
    u = 1, v = 0;
    q = b;
    return false;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0)
  {
    u = d1 / (d1 - d3), v = 0;
    q = a + ab * u;
    return false;
  }
  const Vec3 cp = p - c;
  const double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
  if (d6 >= 0 && d5 <= d6)
  {
    u = 0, v = 1;
    q = c;
    return false;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0)
  {
    u = 0, v = d2 / (d2 - d6);
    q = a + ac * v;
    return false;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
  {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    u = 1 - w, v = w;
    q = b + (c - b) * w;
    return false;
  }
  const double denom = 1 / (va + vb + vc);
  u = vb * denom;
  v = vc * denom;
  q = a + ab * u + ac * v;
  return true;
}

/// Squared distance from p to the closed box [lo, hi] (0 inside).
inline double BoxDistance2(const double lo[3], const double hi[3], const Vec3& p)
{
  double d2 = 0;
  for (int a = 0; a < 3; ++a)
  {
    const double e = p[a] < lo[a] ? lo[a] - p[a] : (p[a] > hi[a] ? p[a] - hi[a] : 0.0);
    d2 += e * e;
  }
  return d2;
}

/// How far the store's double triangles may stick out of the voxels built around their float
/// copies: a few float roundings of the largest coordinate. Nearest-point searches widen their
/// pruning radius by it so no triangle is skipped for a rounding.
inline double FloatSlack(const Box3& bounds)
{
  double m = 0;
  for (int a = 0; a < 3; ++a)
  {
    m = std::fmax(m, std::fmax(std::fabs(bounds.lo[a]), std::fabs(bounds.hi[a])));
  }
  return 4 * FLT_EPSILON * m;
}
} // namespace art

#endif
