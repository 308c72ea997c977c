#include "TriBoxOverlap.h"

#include <algorithm>
#include <cmath>

namespace art
{
namespace
{
// Separating-axis test on the axis (0, ay, az) in the frame (i, j) = the other two axes: the
// cross product of a box axis with a triangle edge has a zero component along that box axis,
// so only two terms of each projection are left (exactly as the full dot product gives them).
inline bool Separated(double ay, double az, const double* v0, const double* v1, const double* v2, int i,
  int j, const double* h)
{
  if (!(ay * ay + az * az > 0))
  {
    return false; // a zero axis separates nothing
  }
  const double p0 = ay * v0[i] + az * v0[j], p1 = ay * v1[i] + az * v1[j], p2 = ay * v2[i] + az * v2[j];
  const double mn = std::min(p0, std::min(p1, p2)), mx = std::max(p0, std::max(p1, p2));
  const double rad = h[i] * std::fabs(ay) + h[j] * std::fabs(az);
  return mn > rad || mx < -rad;
}
} // namespace

bool TriBoxOverlap(const Vec3& center, const Vec3& half, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const double v0[3] = { a.x - center.x, a.y - center.y, a.z - center.z };
  const double v1[3] = { b.x - center.x, b.y - center.y, b.z - center.z };
  const double v2[3] = { c.x - center.x, c.y - center.y, c.z - center.z };
  const double h[3] = { half.x, half.y, half.z };
  // 1. The triangle's plane first: the voxels a triangle's box covers are mostly off its plane.
  const double e[3][3] = { { v1[0] - v0[0], v1[1] - v0[1], v1[2] - v0[2] },
    { v2[0] - v1[0], v2[1] - v1[1], v2[2] - v1[2] }, { v0[0] - v2[0], v0[1] - v2[1], v0[2] - v2[2] } };
  {
    const double n[3] = { e[0][1] * e[1][2] - e[0][2] * e[1][1], e[0][2] * e[1][0] - e[0][0] * e[1][2],
      e[0][0] * e[1][1] - e[0][1] * e[1][0] };
    const double d = n[0] * v0[0] + n[1] * v0[1] + n[2] * v0[2];
    const double rad = h[0] * std::fabs(n[0]) + h[1] * std::fabs(n[1]) + h[2] * std::fabs(n[2]);
    if (d > rad || d < -rad)
    {
      return false;
    }
  }
  // 2. The box's own axes (the triangle's bounding box against the box).
  for (int k = 0; k < 3; ++k)
  {
    const double mn = std::min(v0[k], std::min(v1[k], v2[k])), mx = std::max(v0[k], std::max(v1[k], v2[k]));
    if (mn > h[k] || mx < -h[k])
    {
      return false;
    }
  }
  // 3. Nine edge x axis cross products: x cross e = (0, -e.z, e.y), y cross e = (e.z, 0, -e.x),
  // z cross e = (-e.y, e.x, 0).
  for (const double* ed : e)
  {
    if (Separated(-ed[2], ed[1], v0, v1, v2, 1, 2, h) || Separated(ed[2], -ed[0], v0, v1, v2, 0, 2, h) ||
      Separated(-ed[1], ed[0], v0, v1, v2, 0, 1, h))
    {
      return false;
    }
  }
  return true;
}
} // namespace art
