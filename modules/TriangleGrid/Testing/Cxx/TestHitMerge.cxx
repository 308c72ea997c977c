// SortAndMergeHits, which the all-hits queries use, against OrderedHits fed the same hits one
// voxel at a time; and All reusing the caller's vector from ray to ray.
#include "Accelerator.h"
#include "OrderedHits.h"
#include "TriangleTestUtil.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace
{
// Hits on the box's triangles in clusters: several hits at one t (a ray through a shared vertex
// or edge), the same record twice (a triangle met in two voxels), and near but distinct t.
std::vector<art::Hit> ClusteredHits(const art::TriangleStore& s, std::mt19937& rng)
{
  std::uniform_int_distribution<int> rec(0, static_cast<int>(s.Size()) - 1), many(1, 4);
  std::uniform_real_distribution<double> tpick(0.0, 10.0);
  std::vector<art::Hit> hits;
  const int clusters = many(rng) + 2;
  for (int k = 0; k < clusters; ++k)
  {
    const double t = tpick(rng);
    const int n = many(rng);
    const int base = rec(rng);
    for (int i = 0; i < n; ++i)
    {
      art::Hit h;
      h.t = t + (i % 2 ? 1e-9 : 0.0);
      h.u = 0.25 * i;
      h.v = 0.125;
      // Neighbours in record order often share a vertex; a repeat of base is the same triangle.
      h.record = i == 3 ? base : (base + i) % static_cast<int>(s.Size());
      hits.push_back(h);
    }
  }
  std::shuffle(hits.begin(), hits.end(), rng);
  return hits;
}
} // namespace

TEST(HitMerge, InPlaceMergeEqualsOrderedHits)
{
  auto s = arttest::BoxMesh({ 0, 0, 0 }, { 1, 1, 1 }, 3);
  std::mt19937 rng(7);
  const double tol = 1e-7;
  size_t merged = 0, dropped = 0;
  for (int trial = 0; trial < 2000; ++trial)
  {
    std::vector<art::Hit> hits = ClusteredHits(*s, rng);
    const size_t before = hits.size();
    // The reference: sorted, then through OrderedHits as one voxel.
    std::vector<art::Hit> sorted = hits;
    std::sort(sorted.begin(), sorted.end(), [](const art::Hit& a, const art::Hit& b) {
      return a.t < b.t || (a.t == b.t && a.record < b.record);
    });
    std::vector<art::Hit> ref;
    art::OrderedHits oh(*s, ref, tol);
    for (const art::Hit& h : sorted)
    {
      oh.Add(h.t, h.u, h.v, static_cast<std::uint32_t>(h.record));
    }
    oh.Finish();

    art::SortAndMergeHits(*s, hits, tol);
    ASSERT_EQ(hits.size(), ref.size()) << "trial " << trial;
    for (size_t i = 0; i < ref.size(); ++i)
    {
      EXPECT_EQ(hits[i].t, ref[i].t);
      EXPECT_EQ(hits[i].u, ref[i].u);
      EXPECT_EQ(hits[i].v, ref[i].v);
      EXPECT_EQ(hits[i].record, ref[i].record);
      EXPECT_EQ(hits[i].triangle, ref[i].triangle);
      EXPECT_EQ(hits[i].triangle, s->OriginalIndex(static_cast<size_t>(hits[i].record)));
    }
    merged += hits.size();
    dropped += before - hits.size();
  }
  // The clusters must exercise both outcomes: kept hits and merged repeats.
  EXPECT_GT(merged, 1000u);
  EXPECT_GT(dropped, 1000u);
}

TEST(HitMerge, AllKeepsTheCallersVector)
{
  // A ray through a 4 x 4 x 4 box's two faces: two hits, the same on every call, and the second
  // call fills the vector it was given without growing it anew.
  auto s = arttest::BoxMesh({ 0, 0, 0 }, { 1, 1, 1 }, 4);
  for (const art::AcceleratorOptions& o : arttest::AllKinds())
  {
    auto acc = art::MakeAccelerator(s, o);
    art::Ray r;
    r.org = { 0.3, 0.4, -1 };
    r.dir = { 0.01, 0.02, 1 };
    art::Counters c;
    std::vector<art::Hit> hits;
    acc->All(r, hits, c);
    ASSERT_EQ(hits.size(), 2u) << acc->Name();
    const std::vector<art::Hit> first = hits;
    const art::Hit* data = hits.data();
    const size_t capacity = hits.capacity();
    acc->All(r, hits, c);
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_EQ(hits.data(), data) << acc->Name();
    EXPECT_EQ(hits.capacity(), capacity);
    for (size_t i = 0; i < 2; ++i)
    {
      EXPECT_EQ(hits[i].t, first[i].t);
      EXPECT_EQ(hits[i].record, first[i].record);
    }
    EXPECT_LT(hits[0].t, hits[1].t);
  }
}
