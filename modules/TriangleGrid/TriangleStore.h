// TriangleStore: the one triangle store of the ray tracing machine (Dmitriev, "Efficiency issues
// on Ray Tracing Machine", section 2): array-of-structs records, one cache line each, sorted by
// plane so coplanar triangles are neighbours and share one plane record.
#ifndef art_TriangleStore_h
#define art_TriangleStore_h

#include "AdaptiveRTTriangleGridModule.h"
#include "Box3.h"

#include <array>
#include <cstdint>
#include <vector>

class vtkPolyData;

namespace art
{
/// One triangle, 64 bytes. Positions are copied in (float) so a test touches one cache line;
/// the indices name the input points.
struct TriangleRecord
{
  enum : std::uint32_t
  {
    SharedPlane = 1u << 0, ///< the next record lies in the same plane
    AxisPlane = 1u << 1    ///< the plane is perpendicular to an axis
  };
  float p[3][3];          ///< vertex positions
  std::uint32_t v[3];     ///< vertex indices into Points()
  std::uint32_t plane;    ///< index into Planes()
  std::uint32_t flags;    ///< SharedPlane, AxisPlane, dominant normal axis in bits 2-3
  std::uint32_t pad[2];
};
static_assert(sizeof(TriangleRecord) == 64, "one cache line");

/// A plane n.x = d shared by every coplanar triangle (n unit, largest component positive).
struct PlaneRecord
{
  double n[3];
  double d;
};

/// Box of a record in float (kept beside the records: it is needed to build, not to trace).
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
  long long OriginalIndex(size_t record) const { return Original[record]; }
  size_t DroppedCount() const { return Dropped; }

  const TriangleRecord& Record(size_t i) const { return Records[i]; }
  const TriangleRecord* Data() const { return Records.data(); }
  const TriangleBox& RecordBox(size_t i) const { return Boxes[i]; }
  const std::vector<PlaneRecord>& Planes() const { return PlaneList; }
  const std::vector<Vec3>& Points() const { return Pts; }
  Vec3 Vertex(size_t record, int k) const
  {
    const float* p = Records[record].p[k];
    return { p[0], p[1], p[2] };
  }
  /// Bytes held (records, boxes, planes, points, index map).
  size_t MemoryBytes() const;

private:
  void Build(std::vector<Vec3> points, const std::vector<std::array<long long, 3>>& triangles,
    const std::vector<long long>& original, const Vec3& origin);

  std::vector<Vec3> Pts;
  std::vector<TriangleRecord> Records;
  std::vector<TriangleBox> Boxes;
  std::vector<PlaneRecord> PlaneList;
  std::vector<long long> Original;
  Box3 Box;
  size_t Dropped = 0;
};
} // namespace art

#endif
