#include "ParallelTiles.h"
#include "Progress.h"

#include <gtest/gtest.h>

#include <mutex>
#include <vector>

namespace
{
// Fills every pixel with a value that depends on the order of pixels inside its tile, the way a
// coherent ray caster reuses state along a tile's scan lines.
std::vector<double> Render(int threads, art::Counters& cnt)
{
  art::SetThreadCount(threads);
  const int w = 97, h = 61;
  std::vector<double> img(w * h, -1.0);
  cnt = art::ForEachTile(w, h, 16, [&](const art::Tile& t, art::Counters& c) {
    double state = t.index;
    for (int y = t.y0; y < t.y1; ++y)
    {
      for (int x = t.x0; x < t.x1; ++x)
      {
        state = state * 0.5 + x * 0.25 + y;
        img[y * w + x] = state;
        ++c.rays;
      }
    }
  });
  return img;
}
}

TEST(ParallelTiles, IdenticalResultsForOneAndTwoThreads)
{
  art::Counters c1, c2;
  const auto a = Render(1, c1);
  const auto b = Render(2, c2);
  EXPECT_EQ(a, b);
  EXPECT_EQ(c1.rays, 97u * 61u);
  EXPECT_EQ(c2.rays, 97u * 61u);
  for (double v : a)
  {
    ASSERT_GE(v, 0.0); // every pixel written
  }
  art::SetThreadCount(0);
}

TEST(ParallelTiles, ProgressIsMonotoneAndEndsAtOne)
{
  std::mutex m;
  std::vector<double> seen;
  art::Progress p([&](double f, const std::string&) {
    std::lock_guard<std::mutex> g(m);
    seen.push_back(f);
  });
  p.Begin("render", 200.0 * 100.0);
  art::ForEachTile(200, 100, 8, [](const art::Tile&, art::Counters&) {}, &p);
  p.End();
  ASSERT_FALSE(seen.empty());
  EXPECT_DOUBLE_EQ(seen.front(), 0.0);
  EXPECT_NEAR(seen.back(), 1.0, 1e-12);
  for (size_t i = 1; i < seen.size(); ++i)
  {
    EXPECT_GE(seen[i], seen[i - 1]);
  }
}

TEST(ParallelTiles, CancelStopsEarly)
{
  art::Progress p;
  p.Begin("work", 1000);
  p.Cancel();
  int done = 0;
  art::ForEachRange(1000, 1, [&](long long, long long, art::Counters&) { ++done; }, &p);
  EXPECT_EQ(done, 0);
}
