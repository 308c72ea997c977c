// OrderedHits: an all-hits list made final up to a distance at a time: EndVoxel(t) sorts the hits
// added since (few) and appends those up to t; where a ray crosses an edge or vertex shared by
// several triangles, one hit stands for the surface. The queries use SortAndMergeHits instead,
// the same merge done once, in place, at the end (emitting voxel by voxel cost more than it saved).
#ifndef art_OrderedHits_h
#define art_OrderedHits_h

#include "Accelerator.h"

#include <vector>

namespace art
{
class ADAPTIVERTTRIANGLEGRID_EXPORT OrderedHits
{
public:
  /// Fills `out` (cleared); hits within `tol` in t on triangles sharing a vertex are one surface.
  OrderedHits(const TriangleStore& s, std::vector<Hit>& out, double tol);
  /// A hit found in the current voxel.
  void Add(double t, double u, double v, std::uint32_t record)
  {
    // At or before the last voxel's end: a triangle already met (the mailbox forgot it).
    if (t > Done)
    {
      Hit h;
      h.t = t;
      h.u = u;
      h.v = v;
      h.record = record;
      Out.push_back(h);
    }
  }
  /// The voxel ended at tExit: the hits up to there are final.
  void EndVoxel(double tExit);
  /// Emits the rest and names each hit's input triangle.
  void Finish();

private:
  bool Repeat(const Hit& h) const;

  const TriangleStore& S;
  std::vector<Hit>& Out; ///< [0, Emitted) final, the rest pending
  double Tol;
  size_t Emitted = 0;
  double Done;
};

/// Whether two records share a vertex, by index or by position (polygon soups repeat points).
ADAPTIVERTTRIANGLEGRID_EXPORT bool ShareVertex(const TriangleStore& s, const TriangleRecord& a, const TriangleRecord& b);
} // namespace art

#endif
