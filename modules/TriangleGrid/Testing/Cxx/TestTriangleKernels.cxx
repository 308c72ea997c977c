// The batch triangle tests (TriangleKernels.h): every kernel the processor has gives, bit for bit,
// what the one-triangle watertight test gives, on random triangles (shared vertices, slivers,
// degenerate and edge-on ones) and rays aimed at their vertices and edges; and every accelerator
// answers the same with each kernel.
#include "Accelerator.h"
#include "TriangleKernels.h"
#include "TriangleTestUtil.h"
#include "WatertightTest.h"

#include <gtest/gtest.h>

#include <cstring>

namespace
{
/// The kernels this processor runs (the scalar one first).
std::vector<const art::TriangleKernel*> Kernels()
{
  std::vector<const art::TriangleKernel*> k{ &art::TriangleKernelScalar() };
  const art::TriangleKernel& wide = art::TriangleKernelFor(art::TriangleTestIsa::AVX2);
  if (&wide != k.back())
  {
    k.push_back(&wide);
  }
  return k;
}

/// 400 triangles over 150 points in a unit box: many share vertices; a few are degenerate.
std::shared_ptr<art::TriangleStore> RandomSoup(std::mt19937_64& g)
{
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<art::Vec3> pts(150);
  for (auto& p : pts)
  {
    p = art::Vec3(u(g), u(g), u(g));
  }
  pts[1] = pts[0] + art::Vec3(1e-7, 0, 0); // a sliver
  std::uniform_int_distribution<long long> pick(0, 149);
  std::vector<std::array<long long, 3>> tris;
  for (int i = 0; i < 400; ++i)
  {
    tris.push_back({ pick(g), pick(g), pick(g) });
  }
  tris.push_back({ 0, 1, 2 });
  tris.push_back({ 3, 3, 4 }); // degenerate: dropped by the store or rejected by det == 0
  return std::make_shared<art::TriangleStore>(pts, tris);
}

/// Rays at random points, at vertices and at edge midpoints of the soup, some parallel to an axis,
/// and rays leaving a vertex (hits at exactly t = tmin = 0).
std::vector<art::Ray> RaysAt(const art::TriangleStore& s, std::mt19937_64& g)
{
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<art::Ray> rays;
  const float* xyz = s.Vertices();
  auto vertex = [&](std::uint32_t i) { return art::Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); };
  for (size_t i = 0; i < 3000; ++i)
  {
    art::Ray r;
    r.org = art::Vec3(3 * u(g), 3 * u(g), 3 * u(g));
    const art::TriangleRecord& t = s.Record(i % s.Size());
    const art::Vec3 target = i % 3 == 0 ? art::Vec3(u(g), u(g), u(g))
      : i % 3 == 1                      ? vertex(t.v[i % 2])
                                        : 0.5 * (vertex(t.v[0]) + vertex(t.v[2]));
    r.dir = i % 17 == 0 ? art::Vec3(1, 0, 0) : target - r.org;
    r.tmin = i % 5 == 0 ? 0.5 : 0.0;
    rays.push_back(r);
    if (i % 4 == 0)
    {
      r.org = vertex(t.v[0]);
      r.dir = art::Vec3(u(g), u(g), u(g));
      r.tmin = 0.0;
      rays.push_back(r);
    }
  }
  return rays;
}

bool SameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}
} // namespace

TEST(TriangleKernels, EveryKernelMatchesTheOneTriangleTestBitForBit)
{
  const auto kernels = Kernels();
  std::printf("kernels:");
  for (const auto* k : kernels)
  {
    std::printf(" %s", k->name);
  }
  std::printf("\n");
  std::mt19937_64 g(11);
  const auto store = RandomSoup(g);
  const auto rays = RaysAt(*store, g);
  const auto* records = reinterpret_cast<const std::uint32_t*>(store->Data());
  const float* xyz = store->Vertices();
  std::uniform_int_distribution<int> size(1, 64);
  std::uniform_int_distribution<std::uint32_t> id(0, static_cast<std::uint32_t>(store->Size() - 1));
  size_t hitsSeen = 0;
  for (const art::Ray& r : rays)
  {
    const art::RayPrep p(r);
    // A batch of random records (repeats allowed, as a mailbox collision gives them).
    std::uint32_t ids[64];
    const int n = size(g);
    for (int k = 0; k < n; ++k)
    {
      ids[k] = id(g);
    }
    // The reference: one triangle at a time, nearest with ties to the lowest record.
    art::NearestSoFar ref{ r.tmax, 0, 0, -1 };
    art::BatchHits refAll;
    int refCount = 0;
    for (int k = 0; k < n; ++k)
    {
      double t, u, v;
      if (art::IntersectTriangle(p.s, xyz, store->Record(ids[k]), r.tmin, r.tmax, t, u, v))
      {
        refAll.t[refCount] = t;
        refAll.u[refCount] = u;
        refAll.v[refCount] = v;
        refAll.record[refCount++] = ids[k];
        if (t < ref.t || ref.record < 0 || (t == ref.t && ids[k] < ref.record))
        {
          ref = art::NearestSoFar{ t, u, v, ids[k] };
        }
      }
    }
    hitsSeen += refCount;
    for (const art::TriangleKernel* kernel : kernels)
    {
      SCOPED_TRACE(kernel->name);
      art::NearestSoFar best{ r.tmax, 0, 0, -1 };
      kernel->closest(p.s, records, xyz, ids, n, r.tmin, best);
      ASSERT_EQ(best.record, ref.record);
      if (ref.record >= 0)
      {
        ASSERT_TRUE(SameBits(best.t, ref.t) && SameBits(best.u, ref.u) && SameBits(best.v, ref.v));
      }
      ASSERT_EQ(kernel->any(p.s, records, xyz, ids, n, r.tmin, r.tmax), refCount > 0);
      art::BatchHits all;
      ASSERT_EQ(kernel->all(p.s, records, xyz, ids, n, r.tmin, r.tmax, all), refCount);
      for (int k = 0; k < refCount; ++k)
      {
        ASSERT_EQ(all.record[k], refAll.record[k]);
        ASSERT_TRUE(SameBits(all.t[k], refAll.t[k]) && SameBits(all.u[k], refAll.u[k]) &&
          SameBits(all.v[k], refAll.v[k]));
      }
    }
  }
  EXPECT_GT(hitsSeen, 1000u); // the rays do hit: the comparison is not of empty answers
}

TEST(TriangleKernels, AcceleratorsAnswerTheSameWithEveryKernel)
{
  std::mt19937_64 g(5);
  const auto store = RandomSoup(g);
  auto rays = RaysAt(*store, g);
  rays.resize(1200);
  for (art::AcceleratorOptions o : arttest::AllKinds())
  {
    o.triangleTest = art::TriangleTestIsa::Scalar;
    const auto ref = art::MakeAccelerator(store, o);
    for (auto isa : { art::TriangleTestIsa::AVX2, art::TriangleTestIsa::Best })
    {
      o.triangleTest = isa;
      const auto acc = art::MakeAccelerator(store, o);
      SCOPED_TRACE(acc->Name() + " " + acc->TriangleTest().name);
      art::Counters c;
      std::vector<art::Hit> h1, h2;
      for (const art::Ray& r : rays)
      {
        art::Hit a, b;
        const bool ha = ref->Closest(r, a, c), hb = acc->Closest(r, b, c);
        ASSERT_EQ(ha, hb);
        if (ha)
        {
          ASSERT_EQ(a.triangle, b.triangle);
          ASSERT_TRUE(SameBits(a.t, b.t) && SameBits(a.u, b.u) && SameBits(a.v, b.v));
        }
        ASSERT_EQ(ref->Any(r, c), acc->Any(r, c));
        ref->All(r, h1, c);
        acc->All(r, h2, c);
        ASSERT_EQ(h1.size(), h2.size());
        for (size_t k = 0; k < h1.size(); ++k)
        {
          ASSERT_EQ(h1[k].triangle, h2[k].triangle);
          ASSERT_TRUE(SameBits(h1[k].t, h2[k].t));
        }
      }
    }
  }
}
