// Every accelerator agrees with brute force on real scenes: same hit/miss, same distance (1e-5
// relative) and the same all-hits lists. On am_underworks (2,653 triangles) brute force is the
// reference for all 100k rays. On bunny (99,785 triangles) brute force on 100k rays would be 1e10
// tests, so brute force checks the uniform grid on 1,500 rays, and the uniform grid is then the
// reference for the other accelerators on 100k rays (said in the test names).
#include "Accelerator.h"
#include "DataLoader.h"
#include "ParallelTiles.h"
#include "TriangleTestUtil.h"

#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace
{
std::shared_ptr<art::TriangleStore> Load(const std::string& path)
{
  return std::make_shared<art::TriangleStore>(art::TriangleStore::FromPolyData(art::LoadSurface(path)));
}

bool Exists(const std::string& p)
{
  return std::ifstream(p).good();
}

// Rays from a sphere around the scene towards random points of its box (most hit, some miss),
// plus rays from inside the box in random directions.
std::vector<art::Ray> RandomRays(const art::Box3& b, size_t n, unsigned seed)
{
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<art::Ray> rays(n);
  const double R = b.Diagonal();
  for (size_t i = 0; i < n; ++i)
  {
    const art::Vec3 target(b.lo.x + u(g) * (b.hi.x - b.lo.x), b.lo.y + u(g) * (b.hi.y - b.lo.y),
      b.lo.z + u(g) * (b.hi.z - b.lo.z));
    art::Ray& r = rays[i];
    if (i % 4 == 3)
    {
      r.org = target;
      r.dir = arttest::RandomUnit(g);
    }
    else
    {
      r.org = b.Center() + arttest::RandomUnit(g) * R;
      r.dir = target - r.org;
    }
  }
  return rays;
}

bool Near(double a, double b)
{
  return std::fabs(a - b) <= 1e-5 * std::max(std::fabs(a), std::fabs(b));
}

// The reference answers, computed once: closest hits of every ray, all-hits of every `allStride`-th.
struct Reference
{
  std::vector<art::Hit> closest;
  std::vector<std::vector<art::Hit>> all;
  size_t allStride = 1;
};

Reference MakeReference(const art::Accelerator& ref, const std::vector<art::Ray>& rays, size_t allStride)
{
  Reference R;
  R.allStride = allStride;
  ref.ClosestBatch(rays, R.closest);
  R.all.resize((rays.size() + allStride - 1) / allStride);
  art::ForEachRange(static_cast<long long>(R.all.size()), 64, [&](long long b, long long e, art::Counters& c) {
    for (long long i = b; i < e; ++i)
    {
      ref.All(rays[i * allStride], R.all[i], c);
    }
  });
  return R;
}

// Compares `acc` with the reference: hit/miss, distance, any-hit, all-hits lists.
void Compare(const Reference& R, const std::string& refName, const art::Accelerator& acc, const std::vector<art::Ray>& rays)
{
  std::vector<art::Hit> ha;
  acc.ClosestBatch(rays, ha);
  std::vector<unsigned char> occ;
  acc.AnyBatch(rays, occ);
  size_t hitMiss = 0, dist = 0, anyBad = 0, lists = 0, hits = 0;
  std::vector<art::Hit> la;
  for (size_t i = 0; i < rays.size(); ++i)
  {
    const bool h1 = R.closest[i].triangle >= 0, h2 = ha[i].triangle >= 0;
    hits += h1;
    hitMiss += h1 != h2;
    dist += h1 && h2 && !Near(R.closest[i].t, ha[i].t);
    anyBad += (occ[i] != 0) != h1;
    if (i % R.allStride == 0)
    {
      art::Counters c;
      const auto& lr = R.all[i / R.allStride];
      acc.All(rays[i], la, c);
      bool same = lr.size() == la.size();
      for (size_t k = 0; same && k < lr.size(); ++k)
      {
        same = Near(lr[k].t, la[k].t);
      }
      lists += !same;
    }
  }
  EXPECT_GT(hits, rays.size() / 4) << "the rays should mostly hit";
  EXPECT_EQ(hitMiss, 0u) << acc.Name() << " vs " << refName;
  EXPECT_EQ(dist, 0u) << acc.Name() << " vs " << refName;
  EXPECT_EQ(anyBad, 0u) << acc.Name() << " vs " << refName;
  EXPECT_EQ(lists, 0u) << acc.Name() << " vs " << refName;
}
} // namespace

TEST(TriangleGridAgreement, UnderworksAllAcceleratorsMatchBruteForce100kRays)
{
  const std::string path = std::string(ART_SOURCE_DIR) + "/data/am_underworks.ply";
  auto store = Load(path);
  ASSERT_EQ(store->Size() + store->DroppedCount(), 2653u); // 3 of them have zero area
  const auto rays = RandomRays(store->Bounds(), 100000, 1);
  art::AcceleratorOptions bo;
  bo.kind = art::AcceleratorKind::BruteForce;
  auto brute = art::MakeAccelerator(store, bo);
  const Reference R = MakeReference(*brute, rays, 4); // all-hits lists on 25k of the rays
  for (const auto& o : arttest::AllKinds())
  {
    if (o.kind != art::AcceleratorKind::BruteForce)
    {
      Compare(R, brute->Name(), *art::MakeAccelerator(store, o), rays);
    }
  }
}

TEST(TriangleGridAgreement, BunnyUniformGridMatchesBruteForce1500Rays)
{
  const std::string path = std::string(ART_SHARED_DATA) + "/bunny.ply";
  if (!Exists(path))
  {
    GTEST_SKIP() << "no " << path;
  }
  auto store = Load(path);
  ASSERT_EQ(store->Size(), 99785u);
  const auto rays = RandomRays(store->Bounds(), 1500, 2);
  art::AcceleratorOptions bo, uo;
  bo.kind = art::AcceleratorKind::BruteForce;
  uo.kind = art::AcceleratorKind::UniformGrid;
  auto brute = art::MakeAccelerator(store, bo);
  Compare(MakeReference(*brute, rays, 3), brute->Name(), *art::MakeAccelerator(store, uo), rays);
}

TEST(TriangleGridAgreement, BunnyAcceleratorsMatchUniformGrid100kRays)
{
  const std::string path = std::string(ART_SHARED_DATA) + "/bunny.ply";
  if (!Exists(path))
  {
    GTEST_SKIP() << "no " << path;
  }
  auto store = Load(path);
  const auto rays = RandomRays(store->Bounds(), 100000, 3);
  art::AcceleratorOptions uo;
  uo.kind = art::AcceleratorKind::UniformGrid;
  auto grid = art::MakeAccelerator(store, uo);
  const Reference R = MakeReference(*grid, rays, 1);
  for (const auto& o : arttest::AllKinds())
  {
    if (o.kind != art::AcceleratorKind::BruteForce && o.kind != art::AcceleratorKind::UniformGrid)
    {
      Compare(R, grid->Name(), *art::MakeAccelerator(store, o), rays);
    }
  }
}
