// Morton: Z-order codes of points in a box (21 bits per axis), for laying out meshes and
// triangles so that neighbours in space are neighbours in memory.
#ifndef art_Morton_h
#define art_Morton_h

#include "Box3.h"

#include <algorithm>
#include <cstdint>

namespace art
{
/// Spreads the low 21 bits of v so that two zero bits follow each one.
inline std::uint64_t MortonSpread(std::uint64_t v)
{
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

/// The Z-order code of p, quantised to 21 bits per axis over `box` (clamped to it).
inline std::uint64_t MortonCode(const Vec3& p, const Box3& box)
{
  const Vec3 size = box.Size();
  std::uint64_t code = 0;
  for (int a = 0; a < 3; ++a)
  {
    const double u = size[a] > 0 ? (p[a] - box.lo[a]) / size[a] : 0.0;
    code |= MortonSpread(static_cast<std::uint64_t>(std::min(std::max(u, 0.0), 1.0) * 2097151.0)) << a;
  }
  return code;
}
} // namespace art

#endif
