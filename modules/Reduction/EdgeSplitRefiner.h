// EdgeSplitRefiner: one refinement level of error-driven free edge bisection. The edges of the
// tets worth refining are ranked by the squared error their split removes per added tet (the
// midpoint alone refitted over the edge's star, a greedy one-vertex estimate as in greedy
// insertion, Garland & Heckbert '95) and halved with their whole star, best first (issue #4).
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
  /// True when some edge of t is at least sqrt(minEdge2) voxels long and can be halved on the lattice.
  static bool CanRefine(const BisectionMesh& mesh, int t, double minEdge2);

  /// Squared error removed per added tet by halving (a, b): (sum S)^2 / sum Q over the edge's star
  /// (EdgeSplitMoments at the fit x), divided by the star's size, the tets the split adds. Tets
  /// replaced since `version` was taken (or new) have stale moments and are left out; `fresh`
  /// (optional) tells whether none was.
  static double Gain(const BisectionMesh& mesh, int a, int b, const std::vector<uint32_t>& version,
    const std::vector<EdgeSplitMoments>& moments, const std::vector<double>& x, std::vector<int>& star,
    bool* fresh = nullptr);

  /// Halves the edges of the tets `candidates` (each CanRefine) best Gain first (ties by vertex
  /// ids: deterministic) until the mesh has `target` tets; an edge whose star was cut earlier in
  /// the level waits for the next one. `version[t]` are the slots' versions at the level's start
  /// (its size is the tet count then). Replaced and new slots are appended to `touched`.
  static void RefineLevel(BisectionMesh& mesh, const std::vector<int>& candidates,
    const std::vector<uint32_t>& version, const std::vector<EdgeSplitMoments>& moments,
    const std::vector<double>& x, double minEdge2, long long target, std::vector<int>& touched);
};
} // namespace art

#endif
