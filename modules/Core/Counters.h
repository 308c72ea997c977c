// Counters: per-query work counts. Counting work, not only seconds, gives figures that repeat on
// a noisy machine (docs/benchmarks.md). Each thread keeps its own and they are summed.
#ifndef art_Counters_h
#define art_Counters_h

#include <cstdint>

namespace art
{
struct Counters
{
  std::uint64_t rays = 0;            ///< rays cast (primary + secondary)
  std::uint64_t hits = 0;            ///< rays that hit something
  std::uint64_t voxelsVisited = 0;   ///< grid / octree cells entered
  std::uint64_t trianglesTested = 0; ///< ray-triangle tests performed
  std::uint64_t tetsCrossed = 0;     ///< tetrahedra sampled along rays
  std::uint64_t entrySearches = 0;   ///< entrance-cell searches (tet caster)

  Counters& operator+=(const Counters& o)
  {
    rays += o.rays;
    hits += o.hits;
    voxelsVisited += o.voxelsVisited;
    trianglesTested += o.trianglesTested;
    tetsCrossed += o.tetsCrossed;
    entrySearches += o.entrySearches;
    return *this;
  }
  double PerRay(std::uint64_t v) const { return rays ? double(v) / double(rays) : 0.0; }
};
} // namespace art

#endif
