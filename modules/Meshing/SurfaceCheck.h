// SurfaceCheck: whether a triangle surface bounds a solid TetGen can mesh, checked before TetGen
// sees it (TetGen crashes or loops on some surfaces that do not). Points at the same place are
// merged first (STL gives every triangle its own); then every edge must be shared by exactly two
// triangles (none open, none shared by three or more), no triangle may be degenerate, and no two
// triangles may cross or touch other than along the edges and corners they share. The crossing
// test is exact (Shewchuk's orient3d, as TetGen ships it) over the pairs that share a cell of a
// uniform grid (Moeller's triangle-triangle cases, coplanar ones in the triangles' plane).
#ifndef art_SurfaceCheck_h
#define art_SurfaceCheck_h

#include "AdaptiveRTMeshingModule.h"

#include <array>
#include <string>
#include <vector>

namespace art
{
struct TriangleSurface
{
  std::vector<double> Points;              ///< x y z per point
  std::vector<std::array<int, 3>> Triangles;
};

struct SurfaceReport
{
  long long Triangles = 0, Points = 0;
  long long MergedPoints = 0;      ///< points at the place of another one, merged
  long long RepeatedCorners = 0;   ///< triangles naming a point twice once merged (dropped)
  long long Degenerate = 0;        ///< triangles of three distinct, collinear points
  long long OpenEdges = 0;         ///< edges of one triangle only
  long long NonManifoldEdges = 0;  ///< edges of three or more triangles
  long long Intersections = 0;     ///< pairs of triangles that cross or touch
  std::array<long long, 2> FirstIntersection = { { -1, -1 } }; ///< triangle ids of the first pair
  double Volume = 0;               ///< enclosed volume (divergence theorem, |signed|), when closed
  bool Closed() const { return OpenEdges == 0 && NonManifoldEdges == 0 && Degenerate == 0; }
  bool Valid() const { return Closed() && Intersections == 0 && Triangles >= 4; }
  /// "" when Valid, else what is wrong in one line (for "adaptivert: FILE: ...").
  std::string Problem() const;
};

/// Merges coincident points and drops triangles that name a point twice (in place), then checks.
/// The intersection test runs only on a closed surface.
ADAPTIVERTMESHING_EXPORT SurfaceReport CheckSurface(TriangleSurface& surface);
} // namespace art

#endif
