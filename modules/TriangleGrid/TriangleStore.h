// TriangleStore: the one triangle store of the ray tracing machine (Dmitriev, "Efficiency issues
// on Ray Tracing Machine", section 2, the TrgInfo record): per triangle 16 bytes (three vertex
// indices and the index of the plane it shares with other triangles), the vertices once, in
// float. Coplanar triangles share one plane record, so one ray/plane distance culls them all.
// Records keep the input's order (zero-area triangles dropped), so the lowest record of a tie is
// the lowest input index; OriginalIndex maps a record back to its input (the polydata cell id).
// Points are kept in double only when some coordinate is not exactly a float.
#ifndef art_TriangleStore_h
#define art_TriangleStore_h

#include "AdaptiveRTTriangleGridModule.h"
#include "Box3.h"
#include "OriginalIndexMap.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

class vtkPolyData;

namespace art
{
/// One triangle, 16 bytes: vertex indices and its shared plane.
struct TriangleRecord
{
  static constexpr std::uint32_t NoPlane = 0xffffffffu; ///< the triangle has a plane of its own
  std::uint32_t v[3];  ///< vertex indices into the store's points
  std::uint32_t plane; ///< index into Planes(), or NoPlane
};
static_assert(sizeof(TriangleRecord) == 16, "four records per cache line");

/// A plane n.x = d shared by several coplanar triangles (n unit, largest component positive).
/// Float is enough: it only culls, with a margin far above its rounding.
struct PlaneRecord
{
  float n[3];
  float d;
};

/// Axis-aligned box of a record's float vertices.
struct TriangleBox
{
  float lo[3], hi[3];
};

class ADAPTIVERTTRIANGLEGRID_EXPORT TriangleStore
{
public:
  TriangleStore() = default;
  /// Triangles index `points`, taken relative to `origin` (see OriginFor); zero-area ones and ones
  /// with a bad index are dropped.
  TriangleStore(std::vector<Vec3> points, const std::vector<std::array<long long, 3>>& triangles,
    const Vec3& origin = Vec3());
  /// Triangulates polygons and strips of `pd` (vertices and lines are ignored), its points taken
  /// relative to `origin`; OriginalIndex gives the polydata cell id of each record. Throws
  /// art::Error on null input.
  static TriangleStore FromPolyData(vtkPolyData* pd, const Vec3& origin = Vec3());
  /// Where to take a scene's coordinates from: its centre when that lies more than one diagonal
  /// from the origin (survey or CAD coordinates, whose triangles the store's floats would round to
  /// a fraction of |centre|, not of the scene), else the origin itself (so scenes around the origin
  /// keep their exact coordinates).
  static Vec3 OriginFor(const Box3& bounds);

  size_t Size() const { return Records.size(); }
  Box3 Bounds() const { return Box; }
  long long OriginalIndex(size_t record) const { return Original.At(record); }
  size_t DroppedCount() const { return Dropped; }

  const TriangleRecord& Record(size_t i) const { return Records[i]; }
  const TriangleRecord* Data() const { return Records.data(); }
  /// The planes shared by two or more triangles.
  const std::vector<PlaneRecord>& Planes() const { return PlaneList; }
  /// Distinct planes over all triangles (shared ones counted once, plus one per other triangle).
  size_t PlaneCount() const { return PlaneList.size() + Alone; }

  size_t PointCount() const { return Xyz.size() / 3; }
  /// Point i in double (store coordinates): the exact input less the origin.
  Vec3 Point(size_t i) const
  {
    return Exact.empty() ? Vec3(Xyz[3 * i], Xyz[3 * i + 1], Xyz[3 * i + 2]) : Exact[i];
  }
  /// The float vertices the rays are traced against, x y z per point (one float of padding after
  /// the last, so a 16-byte load of any point stays inside).
  const float* Vertices() const { return Xyz.data(); }
  /// Vertex k of a record, in float (as traced).
  Vec3 Vertex(size_t record, int k) const
  {
    const float* p = Xyz.data() + 3 * size_t(Records[record].v[k]);
    return { p[0], p[1], p[2] };
  }
  TriangleBox RecordBox(size_t record) const;
  /// True when every point is exactly a float: the double points are not kept.
  bool PointsAreFloats() const { return Exact.empty(); }
  /// Bytes held (records, planes, points, index map).
  size_t MemoryBytes() const;

private:
  void Build(std::vector<Vec3> points, const std::vector<std::array<long long, 3>>& triangles,
    const std::vector<long long>& original, const Vec3& origin);
  void FindPlanes(const std::vector<std::array<double, 4>>& planes);

  std::vector<float> Xyz;
  std::vector<Vec3> Exact;
  std::vector<TriangleRecord> Records;
  std::vector<PlaneRecord> PlaneList;
  OriginalIndexMap Original;
  Box3 Box;
  size_t Dropped = 0, Alone = 0;
};

inline TriangleBox TriangleStore::RecordBox(size_t record) const
{
  const TriangleRecord& r = Records[record];
  const float *a = Xyz.data() + 3 * size_t(r.v[0]), *b = Xyz.data() + 3 * size_t(r.v[1]),
              *c = Xyz.data() + 3 * size_t(r.v[2]);
  TriangleBox box;
  for (int k = 0; k < 3; ++k)
  {
    box.lo[k] = std::min(a[k], std::min(b[k], c[k]));
    box.hi[k] = std::max(a[k], std::max(b[k], c[k]));
  }
  return box;
}
} // namespace art

#endif
