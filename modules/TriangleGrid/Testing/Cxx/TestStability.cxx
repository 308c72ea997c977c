// Stability cases of the issue, one named test each, over every accelerator kind.
#include "Accelerator.h"
#include "RecursiveGrid.h"
#include "TriangleTestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
using arttest::AllKinds;

struct Fixture
{
  std::shared_ptr<art::TriangleStore> store;
  std::vector<std::unique_ptr<art::Accelerator>> accs;
  explicit Fixture(std::shared_ptr<art::TriangleStore> s) : store(std::move(s))
  {
    for (const auto& o : AllKinds())
    {
      accs.push_back(art::MakeAccelerator(store, o));
    }
  }
};

art::Ray MakeRay(art::Vec3 o, art::Vec3 d)
{
  art::Ray r;
  r.org = o;
  r.dir = d;
  return r;
}

// Every accelerator answers `r` like brute force: same hit/miss, same t, same all-hits list.
void ExpectSameAsBrute(const Fixture& f, const art::Ray& r, const char* what)
{
  art::Counters c;
  art::Hit ref;
  const bool refHit = f.accs[0]->Closest(r, ref, c);
  std::vector<art::Hit> refAll, all;
  f.accs[0]->All(r, refAll, c);
  EXPECT_EQ(f.accs[0]->Any(r, c), refHit) << what;
  for (size_t k = 1; k < f.accs.size(); ++k)
  {
    art::Hit h;
    const bool hit = f.accs[k]->Closest(r, h, c);
    ASSERT_EQ(hit, refHit) << what << " " << f.accs[k]->Name();
    if (hit)
    {
      EXPECT_EQ(h.t, ref.t) << what << " " << f.accs[k]->Name();
    }
    EXPECT_EQ(f.accs[k]->Any(r, c), refHit) << what << " " << f.accs[k]->Name();
    f.accs[k]->All(r, all, c);
    ASSERT_EQ(all.size(), refAll.size()) << what << " " << f.accs[k]->Name();
    for (size_t i = 0; i < all.size(); ++i)
    {
      EXPECT_EQ(all[i].t, refAll[i].t) << what << " " << f.accs[k]->Name();
    }
  }
}
} // namespace

// Rays along +-x, +-y, +-z through a closed box: exact distances, one entry and one exit.
TEST(TriangleGridStability, AxisParallelRays)
{
  Fixture f(arttest::BoxMesh({ -1, -2, -3 }, { 1, 2, 3 }, 5));
  const art::Vec3 lo(-1, -2, -3), hi(1, 2, 3);
  for (const auto& acc : f.accs)
  {
    for (int a = 0; a < 3; ++a)
    {
      for (int s = 0; s < 2; ++s)
      {
        art::Vec3 o(0.1, -0.3, 0.7), d(0, 0, 0);
        d[a] = s ? 1.0 : -1.0;
        o[a] = s ? lo[a] - 10 : hi[a] + 10;
        art::Counters c;
        art::Hit h;
        ASSERT_TRUE(acc->Closest(MakeRay(o, d), h, c)) << acc->Name();
        EXPECT_NEAR(h.t, 10.0, 1e-9) << acc->Name();
        std::vector<art::Hit> all;
        acc->All(MakeRay(o, d), all, c);
        ASSERT_EQ(all.size(), 2u) << acc->Name();
        EXPECT_NEAR(all[1].t, 10.0 + (hi[a] - lo[a]), 1e-9) << acc->Name();
      }
    }
  }
}

// Directions with +0 and -0 components give identical answers (1/(-0) = -inf must not misstep).
TEST(TriangleGridStability, SignedZeroDirections)
{
  Fixture f(arttest::BoxMesh({ -1, -1, -1 }, { 1, 1, 1 }, 4));
  for (const auto& acc : f.accs)
  {
    for (int a = 0; a < 3; ++a)
    {
      art::Vec3 o(0.2, 0.3, -0.4), d1(0, 0, 0), d2(-0.0, -0.0, -0.0);
      d1[a] = d2[a] = 1.0;
      art::Counters c;
      art::Hit h1, h2;
      ASSERT_TRUE(acc->Closest(MakeRay(o, d1), h1, c));
      ASSERT_TRUE(acc->Closest(MakeRay(o, d2), h2, c));
      EXPECT_EQ(h1.t, h2.t) << acc->Name();
      EXPECT_NEAR(h1.t, 1.0 - o[a], 1e-12) << acc->Name();
      EXPECT_EQ(h1.triangle, h2.triangle) << acc->Name();
    }
  }
}

// Rays through the corners and along the edges of the top-level voxels, and through mesh vertices.
TEST(TriangleGridStability, RaysThroughVoxelEdgesAndCorners)
{
  Fixture f(arttest::BoxMesh({ -1, -1, -1 }, { 1, 1, 1 }, 8));
  art::AcceleratorOptions uo;
  uo.kind = art::AcceleratorKind::UniformGrid;
  auto grid = art::MakeAccelerator(f.store, uo);
  const auto* g = dynamic_cast<const art::RecursiveGrid*>(grid.get());
  ASSERT_NE(g, nullptr);
  const art::Box3 b = g->GridBounds();
  int n = 0;
  for (int i = 0; i <= g->TopDims(0); ++i)
  {
    for (int j = 0; j <= g->TopDims(1); ++j)
    {
      const double x = b.lo.x + (b.hi.x - b.lo.x) * i / g->TopDims(0);
      const double y = b.lo.y + (b.hi.y - b.lo.y) * j / g->TopDims(1);
      // Straight down a voxel edge line, and diagonally through the corner at z = 0.
      ExpectSameAsBrute(f, MakeRay({ x, y, 5 }, { 0, 0, -1 }), "edge line");
      ExpectSameAsBrute(f, MakeRay({ x - 3, y - 3, -3 }, { 1, 1, 1 }), "corner diagonal");
      ++n;
    }
  }
  // The octree's split planes run through the centre: rays along them and through mesh vertices.
  for (int k = -4; k <= 4; ++k)
  {
    ExpectSameAsBrute(f, MakeRay({ k / 4.0, 0, 5 }, { 0, 0, -1 }), "octree mid plane");
    ExpectSameAsBrute(f, MakeRay({ k / 4.0, k / 8.0, -5 }, { 0, 0, 1 }), "mesh vertex");
  }
  EXPECT_GT(n, 4);
}

// Triangles lying exactly in voxel faces (the octree's x = 0 split plane, the grid's middle face):
// found from both sides and at grazing angles.
TEST(TriangleGridStability, TrianglesInVoxelFaces)
{
  // A closed box symmetric about 0 plus a square in the plane x = 0 made of 32 triangles.
  auto box = arttest::BoxMesh({ -1, -1, -1 }, { 1, 1, 1 }, 4);
  std::vector<art::Vec3> pts;
  for (size_t i = 0; i < box->PointCount(); ++i)
  {
    pts.push_back(box->Point(i));
  }
  std::vector<std::array<long long, 3>> tris;
  for (size_t i = 0; i < box->Size(); ++i)
  {
    const auto& r = box->Record(i);
    tris.push_back({ r.v[0], r.v[1], r.v[2] });
  }
  const long long base = static_cast<long long>(pts.size());
  for (int j = 0; j <= 4; ++j)
  {
    for (int k = 0; k <= 4; ++k)
    {
      pts.push_back({ 0.0, -0.5 + j * 0.25, -0.5 + k * 0.25 });
    }
  }
  for (int j = 0; j < 4; ++j)
  {
    for (int k = 0; k < 4; ++k)
    {
      const long long a = base + j * 5 + k, b = a + 5, c = b + 1, d = a + 1;
      tris.push_back({ a, b, c });
      tris.push_back({ a, c, d });
    }
  }
  Fixture f(std::make_shared<art::TriangleStore>(pts, tris));
  for (const auto& acc : f.accs)
  {
    for (double s : { 1.0, -1.0 })
    {
      for (double y : { -0.5, -0.3, 0.0, 0.25, 0.49 })
      {
        art::Counters c;
        art::Hit h;
        // From either side, perpendicular and oblique.
        ASSERT_TRUE(acc->Closest(MakeRay({ -0.5 * s, y, 0.1 }, { s, 0, 0 }), h, c)) << acc->Name();
        EXPECT_NEAR(h.t, 0.5, 1e-12) << acc->Name();
        ASSERT_TRUE(acc->Closest(MakeRay({ -0.5 * s, y, 0.1 }, { s, 0.01, -0.02 }), h, c)) << acc->Name();
        EXPECT_NEAR(h.t, 0.5, 1e-12) << acc->Name();
      }
    }
    // A ray lying in the plane x = 0 does not hit the square (det = 0) but does hit the box.
    art::Counters c;
    art::Hit h;
    ASSERT_TRUE(acc->Closest(MakeRay({ 0, -5, 0.1 }, { 0, 1, 0 }), h, c));
    EXPECT_NEAR(h.t, 4.0, 1e-12) << acc->Name();
  }
  for (double y : { -0.5, -0.25, 0.0, 0.3 })
  {
    ExpectSameAsBrute(f, MakeRay({ -2, y, 0.25 }, { 1, 0, 0 }), "through square");
    ExpectSameAsBrute(f, MakeRay({ -2, y, 0.25 }, { 1, 1e-3, 0 }), "oblique through square");
  }
}

// A NaN or zero direction returns no hit, and neither crashes nor hangs; so do infinite origins.
TEST(TriangleGridStability, InvalidRaysReturnNoHit)
{
  Fixture f(arttest::BoxMesh({ -1, -1, -1 }, { 1, 1, 1 }, 2));
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  const art::Ray bad[] = { MakeRay({ 0, 0, 0 }, { 0, 0, 0 }), MakeRay({ 0, 0, 0 }, { nan, 1, 0 }),
    MakeRay({ nan, 0, 0 }, { 1, 0, 0 }), MakeRay({ inf, 0, 0 }, { -1, 0, 0 }), MakeRay({ 0, 0, 0 }, { 1, inf, 0 }) };
  for (const auto& acc : f.accs)
  {
    for (const art::Ray& r : bad)
    {
      art::Counters c;
      art::Hit h;
      EXPECT_FALSE(acc->Closest(r, h, c)) << acc->Name();
      EXPECT_EQ(h.triangle, -1);
      EXPECT_FALSE(acc->Any(r, c));
      std::vector<art::Hit> all(3);
      acc->All(r, all, c);
      EXPECT_TRUE(all.empty());
    }
    // An empty interval [tmin, tmax] and one wholly before the box also miss.
    art::Ray r = MakeRay({ 0, 0, -5 }, { 0, 0, 1 });
    r.tmin = 2;
    r.tmax = 1;
    art::Counters c;
    art::Hit h;
    EXPECT_FALSE(acc->Closest(r, h, c));
    r.tmin = 0;
    r.tmax = 3.9;
    EXPECT_FALSE(acc->Closest(r, h, c));
    r.tmax = 4.0; // exactly at the face: [tmin, tmax] is closed
    EXPECT_TRUE(acc->Closest(r, h, c));
  }
}

// Segment queries: all hits in [tmin, tmax] sorted; rays starting inside; closest culls behind.
TEST(TriangleGridStability, SegmentsAndOriginInside)
{
  Fixture f(arttest::BoxMesh({ -1, -1, -1 }, { 1, 1, 1 }, 3));
  for (const auto& acc : f.accs)
  {
    art::Counters c;
    art::Hit h;
    ASSERT_TRUE(acc->Closest(MakeRay({ 0.1, 0.2, 0.3 }, { 0, 0, 2 }), h, c));
    EXPECT_NEAR(h.t, 0.35, 1e-12);
    art::Ray r = MakeRay({ 0.1, 0.2, -3 }, { 0, 0, 1 });
    r.tmin = 2.5;
    std::vector<art::Hit> all;
    acc->All(r, all, c);
    ASSERT_EQ(all.size(), 1u) << acc->Name();
    EXPECT_NEAR(all[0].t, 4.0, 1e-12);
    r.tmin = 0;
    acc->All(r, all, c);
    ASSERT_EQ(all.size(), 2u) << acc->Name();
    EXPECT_LT(all[0].t, all[1].t);
  }
}
