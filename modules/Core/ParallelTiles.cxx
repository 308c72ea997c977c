#include "ParallelTiles.h"
#include "Progress.h"

#include <vtkSMPThreadLocal.h>
#include <vtkSMPTools.h>

#include <algorithm>

namespace art
{
namespace
{
int ThreadsRequested = 0;
}

int SetThreadCount(int n)
{
  ThreadsRequested = std::max(0, n);
  vtkSMPTools::Initialize(ThreadsRequested);
  return GetThreadCount();
}

int GetThreadCount()
{
  return vtkSMPTools::GetEstimatedNumberOfThreads();
}

Counters ForEachRange(long long n, long long grain,
  const std::function<void(long long, long long, Counters&)>& fn, Progress* progress)
{
  vtkSMPThreadLocal<Counters> local;
  grain = std::max(1LL, grain);
  const long long chunks = (n + grain - 1) / grain;
  vtkSMPTools::For(0, chunks, 1, [&](vtkIdType c0, vtkIdType c1) {
    Counters& cnt = local.Local();
    for (vtkIdType c = c0; c < c1; ++c)
    {
      if (progress && progress->Cancelled())
      {
        return;
      }
      const long long b = c * grain, e = std::min(n, b + grain);
      fn(b, e, cnt);
      if (progress)
      {
        progress->Advance(static_cast<double>(e - b));
      }
    }
  });
  Counters total;
  for (auto it = local.begin(); it != local.end(); ++it)
  {
    total += *it;
  }
  return total;
}

void ForEachRangeInSlices(long long n, long long grain, int slices,
  const std::function<void(long long, long long, Counters&)>& fn, const std::function<void(long long)>& between)
{
  const long long slice = between ? std::max(1LL, (n + slices - 1) / std::max(1, slices)) : std::max(1LL, n);
  for (long long s0 = 0; s0 < n; s0 += slice)
  {
    const long long s1 = std::min(n, s0 + slice);
    ForEachRange(s1 - s0, grain, [&](long long b, long long e, Counters& c) { fn(s0 + b, s0 + e, c); });
    if (between)
    {
      between(s1);
    }
  }
}

Counters ForEachTile(int width, int height, int tileSize,
  const std::function<void(const Tile&, Counters&)>& fn, Progress* progress)
{
  tileSize = std::max(1, tileSize);
  const int tx = (width + tileSize - 1) / tileSize, ty = (height + tileSize - 1) / tileSize;
  return ForEachRange(static_cast<long long>(tx) * ty, 1,
    [&](long long b, long long e, Counters& cnt) {
      for (long long i = b; i < e; ++i)
      {
        Tile t;
        t.index = static_cast<int>(i);
        t.x0 = static_cast<int>(i % tx) * tileSize;
        t.y0 = static_cast<int>(i / tx) * tileSize;
        t.x1 = std::min(width, t.x0 + tileSize);
        t.y1 = std::min(height, t.y0 + tileSize);
        fn(t, cnt);
        if (progress)
        {
          // ForEachRange counts tiles; scale to pixels so callers set totals in pixels.
          progress->Advance(double((t.x1 - t.x0) * (t.y1 - t.y0)) - 1.0);
        }
      }
    },
    progress);
}
} // namespace art
