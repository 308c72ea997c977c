// ParallelTiles: the one place engines get threads. Splits an image (or any index range) into
// fixed tiles and runs them over vtkSMPTools. Tiles never depend on the thread count, and each
// tile is processed by exactly one thread in a fixed order inside it, so results are identical
// for 1 thread or many; per-thread Counters are summed at the end.
#ifndef art_ParallelTiles_h
#define art_ParallelTiles_h

#include "AdaptiveRTCoreModule.h"
#include "Counters.h"

#include <functional>

namespace art
{
class Progress;

struct Tile
{
  int x0, y0, x1, y1; ///< pixel range [x0, x1) x [y0, y1)
  int index;          ///< tile number in row-major order
};

/// Sets the number of worker threads for every engine (0 = all cores). Returns the count in use.
ADAPTIVERTCORE_EXPORT int SetThreadCount(int n);
ADAPTIVERTCORE_EXPORT int GetThreadCount();

/// Runs fn over tiles of tileSize x tileSize covering width x height, in parallel.
/// Returns the sum of the per-thread counters. Progress (optional) advances one unit per pixel.
ADAPTIVERTCORE_EXPORT Counters ForEachTile(int width, int height, int tileSize,
  const std::function<void(const Tile&, Counters&)>& fn, Progress* progress = nullptr);

/// Runs fn(begin, end, counters) over [0, n) in chunks of `grain`, in parallel.
ADAPTIVERTCORE_EXPORT Counters ForEachRange(long long n, long long grain,
  const std::function<void(long long, long long, Counters&)>& fn, Progress* progress = nullptr);

/// ForEachRange over [0, n) in `slices` consecutive slices, calling between(end) on the calling
/// thread after each: progress and cancellation of a long pass from the driver thread, where
/// VTK's observers must run. One slice (no pause) without `between`.
ADAPTIVERTCORE_EXPORT void ForEachRangeInSlices(long long n, long long grain, int slices,
  const std::function<void(long long, long long, Counters&)>& fn, const std::function<void(long long)>& between);
} // namespace art

#endif
