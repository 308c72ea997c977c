// TriBoxOverlap: exact triangle/axis-aligned box overlap by the separating axis theorem
// (T. Akenine-Moller, "Fast 3D Triangle-Box Overlap Testing", JGT 6(1), 2001). Used to insert
// triangles into voxels so that a triangle lying in a shared face goes to both voxels.
#ifndef art_TriBoxOverlap_h
#define art_TriBoxOverlap_h

#include "AdaptiveRTTriangleGridModule.h"
#include "Vec3.h"

namespace art
{
/// True when the closed box [center - half, center + half] and the triangle intersect.
ADAPTIVERTTRIANGLEGRID_EXPORT bool TriBoxOverlap(const Vec3& center, const Vec3& half, const Vec3& a,
  const Vec3& b, const Vec3& c);
} // namespace art

#endif
