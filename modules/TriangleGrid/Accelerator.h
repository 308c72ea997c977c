// Accelerator: the one query interface of the ray tracing machine (Dmitriev, "Efficiency issues on
// Ray Tracing Machine"): closest hit, any hit (shadows) and all hits along a segment (light through
// transparent surfaces), over brute force, a uniform grid, the recursive grid and the octree.
#ifndef art_Accelerator_h
#define art_Accelerator_h

#include "AdaptiveRTTriangleGridModule.h"
#include "Box3.h"
#include "Counters.h"
#include "Ray.h"
#include "TriangleKernels.h"
#include "TriangleStore.h"

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace art
{
class Progress;

struct Hit
{
  double t = std::numeric_limits<double>::infinity();
  long long triangle = -1; ///< input-order index (TriangleStore::OriginalIndex)
  double u = 0, v = 0;     ///< barycentric weights of the triangle's 2nd and 3rd vertex
  long long record = -1;   ///< record index in the store (for shading: Store().Record(record))
};

/// The answer of a nearest-point query.
struct NearestPoint
{
  double dist2 = std::numeric_limits<double>::infinity(); ///< squared distance to `point`
  Vec3 point;              ///< the closest point (store coordinates)
  long long triangle = -1; ///< input-order index (TriangleStore::OriginalIndex)
  long long record = -1;   ///< record index in the store
  double u = 0, v = 0;     ///< point = p0 + u (p1 - p0) + v (p2 - p0) on the record's vertices
  bool inside = false;     ///< the query point projects inside the triangle (face region)
};

enum class AcceleratorKind
{
  BruteForce,
  UniformGrid,
  RecursiveGrid,
  Octree
};

struct AcceleratorOptions
{
  AcceleratorKind kind = AcceleratorKind::RecursiveGrid;
  int voxelThreshold = 0; ///< R: VOX_NTRG_THR, O: VX_THRESHOLD; 0 = default
  int subdivisions = 0;   ///< R: N_SUB_VOXELS per axis; 0 = default
  bool topLevelGrid = true; ///< R: false starts from one voxel holding the whole scene
  int planeWeight = 0;    ///< O: PLANE_WEIGHT; 0 = default
  double cellsPerTriangle = 0; ///< uniform grid density; 0 = default
  TriangleTestIsa triangleTest = TriangleTestIsa::Best; ///< the batch triangle test (same answers)
};

class ADAPTIVERTTRIANGLEGRID_EXPORT Accelerator
{
public:
  virtual ~Accelerator() = default;
  /// Nearest hit with t in [r.tmin, r.tmax]. A NaN or zero direction hits nothing.
  virtual bool Closest(const Ray& r, Hit& hit, Counters& c) const = 0;
  /// True when anything is hit in [r.tmin, r.tmax] (stops at the first).
  virtual bool Any(const Ray& r, Counters& c) const = 0;
  /// Every hit in [r.tmin, r.tmax], sorted by t; where the ray crosses an edge or vertex shared
  /// by several triangles the surface is reported once.
  virtual void All(const Ray& r, std::vector<Hit>& hits, Counters& c) const = 0;
  /// The point of the surface nearest x (store coordinates) closer than sqrt(maxDist2), exact in
  /// double on the store's points; a best-first walk of the structure's voxels bounded by the best
  /// distance so far. Of equally near triangles the lowest input index wins. False when none is
  /// closer than that (or x is not finite).
  virtual bool ClosestPoint(const Vec3& x, double maxDist2, NearestPoint& out, Counters& c) const = 0;
  /// Input-order ids of every triangle that intersects the closed box, sorted, unique.
  virtual void InBox(const Box3& box, std::vector<long long>& ids, Counters& c) const = 0;
  /// Bytes of the acceleration structure, not counting the store.
  virtual size_t MemoryBytes() const = 0;
  /// "uniform grid 64x60x48", "R[16,4]", "O[4,15]" ...
  virtual std::string Name() const = 0;

  /// Input-order ids of every triangle in the voxels the ray passes within [tmin, tmax], sorted, unique.
  virtual void Candidates(const Ray& r, std::vector<long long>& ids, Counters& c) const = 0;
  /// Boxes of the non-empty voxels down to `level` (a voxel deeper is shown as its ancestor).
  virtual void VoxelBoxes(int level, std::vector<Box3>& boxes) const { boxes.assign(1, S->Bounds()); }

  /// Closest hits of many rays in parallel (art::ForEachRange); hits[i] belongs to rays[i].
  Counters ClosestBatch(const std::vector<Ray>& rays, std::vector<Hit>& hits) const;
  /// Nearest points of many query points in parallel (no radius); out[i] belongs to xs[i].
  Counters ClosestPointBatch(const std::vector<Vec3>& xs, std::vector<NearestPoint>& out) const;
  /// Any-hit of many rays in parallel; occluded[i] is 1 when rays[i] hits something.
  Counters AnyBatch(const std::vector<Ray>& rays, std::vector<unsigned char>& occluded) const;

  const TriangleStore& Store() const { return *S; }
  std::shared_ptr<const TriangleStore> StorePtr() const { return S; }

  /// The batch triangle test (the widest the processor has unless asked otherwise); every one
  /// gives the same answers.
  const TriangleKernel& TriangleTest() const { return *Kernel; }
  void SetTriangleTest(TriangleTestIsa isa) { Kernel = &TriangleKernelFor(isa, S->Size(), S->PointCount()); }

protected:
  explicit Accelerator(std::shared_ptr<const TriangleStore> s)
    : S(std::move(s))
    , Kernel(&TriangleKernelFor(TriangleTestIsa::Best, S->Size(), S->PointCount()))
  {
  }
  std::shared_ptr<const TriangleStore> S;
  const TriangleKernel* Kernel;
};

ADAPTIVERTTRIANGLEGRID_EXPORT std::unique_ptr<Accelerator> MakeAccelerator(
  std::shared_ptr<const TriangleStore> store, const AcceleratorOptions& options = {});

/// Sorts hits by t (then record) and removes repeats: the same record twice, and hits closer than
/// `tol` in t on triangles that share a vertex (a ray through a shared edge or vertex).
ADAPTIVERTTRIANGLEGRID_EXPORT void SortAndMergeHits(const TriangleStore& s, std::vector<Hit>& hits, double tol);

/// Every record, those sharing a plane grouped by plane (in record order within it), then the
/// others: the order the structures keep in their voxels, so one plane test culls a whole run.
ADAPTIVERTTRIANGLEGRID_EXPORT std::vector<std::uint32_t> PlaneOrder(const TriangleStore& s);

/// "brute", "uniform", "recursive", "octree" -> kind; throws art::Error otherwise.
ADAPTIVERTTRIANGLEGRID_EXPORT AcceleratorKind AcceleratorKindFromName(const std::string& name);
} // namespace art

#endif
