#include "TriBoxOverlap.h"

#include <algorithm>
#include <cmath>

namespace art
{
namespace
{
// Separating-axis test on axis `ax` (cross product of a box axis and a triangle edge): projects the
// two triangle vertices that can differ and the box's radius.
inline bool Separated(const Vec3& ax, const Vec3& v0, const Vec3& v1, const Vec3& v2, const Vec3& h)
{
  const double p0 = Dot(ax, v0), p1 = Dot(ax, v1), p2 = Dot(ax, v2);
  const double mn = std::min({ p0, p1, p2 }), mx = std::max({ p0, p1, p2 });
  const double rad = h.x * std::fabs(ax.x) + h.y * std::fabs(ax.y) + h.z * std::fabs(ax.z);
  return mn > rad || mx < -rad;
}
} // namespace

bool TriBoxOverlap(const Vec3& center, const Vec3& h, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 v0 = a - center, v1 = b - center, v2 = c - center;
  // 1. The box's own axes (the triangle's bounding box against the box).
  for (int k = 0; k < 3; ++k)
  {
    const double mn = std::min({ v0[k], v1[k], v2[k] }), mx = std::max({ v0[k], v1[k], v2[k] });
    if (mn > h[k] || mx < -h[k])
    {
      return false;
    }
  }
  // 2. The triangle's plane.
  const Vec3 e0 = v1 - v0, e1 = v2 - v1, e2 = v0 - v2;
  const Vec3 n = Cross(e0, e1);
  {
    const double d = Dot(n, v0);
    const double rad = h.x * std::fabs(n.x) + h.y * std::fabs(n.y) + h.z * std::fabs(n.z);
    if (d > rad || d < -rad)
    {
      return false;
    }
  }
  // 3. Nine edge x axis cross products (a zero axis separates nothing and is skipped by the test).
  const Vec3 axes[3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  const Vec3 edges[3] = { e0, e1, e2 };
  for (const Vec3& e : edges)
  {
    for (const Vec3& u : axes)
    {
      const Vec3 ax = Cross(u, e);
      if (Dot(ax, ax) > 0 && Separated(ax, v0, v1, v2, h))
      {
        return false;
      }
    }
  }
  return true;
}
} // namespace art
