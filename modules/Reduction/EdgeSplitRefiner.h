// EdgeSplitRefiner: one refinement level of error-driven free edge splitting. The edges of the
// tets worth refining are ranked by the squared error their split removes per added tet (the new
// vertex alone refitted over the edge's star, a one-vertex estimate as in greedy insertion,
// Garland & Heckbert '95), and split with their whole star, best first, at the midpoint or at a
// quarter point, whichever removes more (issue #4).
#ifndef art_EdgeSplitRefiner_h
#define art_EdgeSplitRefiner_h

#include "AdaptiveRTReductionModule.h"
#include "BisectionMesh.h"
#include "LeastSquaresFit.h"

#include <cstdint>
#include <vector>

namespace art
{
class ADAPTIVERTREDUCTION_EXPORT EdgeSplitRefiner
{
public:
  /// True when some edge of t is at least sqrt(minEdge2) voxels long and can be halved on the lattice
  /// (an edge may be split at a quarter point only when it can be halved too).
  static bool CanRefine(const BisectionMesh& mesh, int t, double minEdge2);

  /// Squared error removed per added tet by splitting (a, b): (sum S)^2 / sum Q over the edge's
  /// star (EdgeSplitMoments at the fit x), divided by the star's size, the tets the split adds; the
  /// best of the lattice positions 1/4, 1/2, 3/4 from a, returned in `quarters` (optional); quarter
  /// points only on edges at least twice sqrt(minEdge2) long, so that no piece is shorter than a
  /// midpoint split's at the edge-length limit. Tets
  /// replaced since `version` was taken (or new) have stale moments and are left out; `fresh`
  /// (optional) tells whether none was.
  static double Gain(const BisectionMesh& mesh, int a, int b, const std::vector<uint32_t>& version,
    const std::vector<EdgeSplitMoments>& moments, const std::vector<double>& x, double minEdge2,
    std::vector<int>& star, bool* fresh = nullptr, int* quarters = nullptr);

  /// Splits the edges of the tets `candidates` (each CanRefine) best Gain first (ties by vertex
  /// ids: deterministic) until the mesh has `target` tets; an edge whose star was cut earlier in
  /// the level waits for the next one. `version[t]` are the slots' versions at the level's start
  /// (its size is the tet count then). Replaced and new slots are appended to `touched`.
  static void RefineLevel(BisectionMesh& mesh, const std::vector<int>& candidates,
    const std::vector<uint32_t>& version, const std::vector<EdgeSplitMoments>& moments,
    const std::vector<double>& x, double minEdge2, long long target, std::vector<int>& touched);
};
} // namespace art

#endif
