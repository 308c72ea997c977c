#include "Accelerator.h"
#include "TriangleStore.h"
#include "TriangleTestUtil.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <set>

TEST(TriangleStore, RecordIsSixteenBytes)
{
  EXPECT_EQ(sizeof(art::TriangleRecord), 16u);
}

TEST(TriangleStore, CoplanarTrianglesShareOnePlane)
{
  // A box with 4x4 squares per face: 192 triangles on exactly 6 planes, 32 on each.
  auto s = arttest::BoxMesh({ 0, 0, 0 }, { 1, 2, 3 }, 4);
  ASSERT_EQ(s->Size(), 192u);
  ASSERT_EQ(s->Planes().size(), 6u);
  EXPECT_EQ(s->PlaneCount(), 6u);
  std::vector<int> count(6, 0);
  for (size_t i = 0; i < s->Size(); ++i)
  {
    const std::uint32_t pl = s->Record(i).plane;
    ASSERT_LT(pl, 6u);
    ++count[pl];
    // Every vertex lies in its plane.
    const art::PlaneRecord& P = s->Planes()[pl];
    for (int k = 0; k < 3; ++k)
    {
      const art::Vec3 v = s->Vertex(i, k);
      EXPECT_NEAR(P.n[0] * v.x + P.n[1] * v.y + P.n[2] * v.z, P.d, 1e-6);
    }
  }
  EXPECT_EQ(count, std::vector<int>(6, 32));
  // The order the structures keep: each plane's records together.
  const std::vector<std::uint32_t> order = art::PlaneOrder(*s);
  size_t runs = 0;
  for (size_t i = 0; i < order.size(); ++i)
  {
    runs += i == 0 || s->Record(order[i]).plane != s->Record(order[i - 1]).plane;
  }
  EXPECT_EQ(runs, 6u);
}

TEST(TriangleStore, PlanesOfTheirOwnHaveNoRecord)
{
  // Two triangles in z = 0 and one tilted: one shared plane, two distinct planes.
  std::vector<art::Vec3> pts = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 0, 0, 1 } };
  art::TriangleStore s(pts, { { 0, 1, 2 }, { 1, 3, 2 }, { 0, 1, 4 } });
  ASSERT_EQ(s.Size(), 3u);
  EXPECT_EQ(s.Planes().size(), 1u);
  EXPECT_EQ(s.PlaneCount(), 2u);
  EXPECT_EQ(s.Record(0).plane, 0u);
  EXPECT_EQ(s.Record(1).plane, 0u);
  EXPECT_EQ(s.Record(2).plane, art::TriangleRecord::NoPlane);
}

TEST(TriangleStore, DoublePointsKeptOnlyWhenNotFloats)
{
  std::vector<art::Vec3> pts = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 0.5, 0 } };
  art::TriangleStore floats(pts, { { 0, 1, 2 } });
  EXPECT_TRUE(floats.PointsAreFloats());
  EXPECT_EQ(floats.Point(2).y, 0.5);
  pts[2].y = 0.1; // not a float
  art::TriangleStore doubles(pts, { { 0, 1, 2 } });
  EXPECT_FALSE(doubles.PointsAreFloats());
  EXPECT_EQ(doubles.Point(2).y, 0.1);
  EXPECT_EQ(doubles.Vertex(0, 2).y, double(0.1f));
  EXPECT_GT(doubles.MemoryBytes(), floats.MemoryBytes() + 3 * sizeof(art::Vec3) - 1);
}

TEST(TriangleStore, OriginalIndexMapRunsAndArrays)
{
  // Runs stepping by one (a gap where triangles were dropped) and standing (a strip's triangles).
  std::vector<long long> o = { 0, 1, 2, 4, 5, 6, 6, 6, 6, 7, 8, 100, 100 };
  art::OriginalIndexMap m;
  m.Assign(o);
  for (size_t i = 0; i < o.size(); ++i)
  {
    EXPECT_EQ(m.At(i), o[i]) << i;
  }
  // Identity: one run, a few bytes however long.
  std::vector<long long> id(100000);
  for (size_t i = 0; i < id.size(); ++i)
  {
    id[i] = static_cast<long long>(i) + 7;
  }
  m.Assign(id);
  EXPECT_LT(m.MemoryBytes(), 64u);
  EXPECT_EQ(m.At(99999), 100006);
  // Every record its own run: a plain array, and indices past 32 bits kept whole.
  std::vector<long long> wide = { 0, 3, 6, 9, 5000000000LL, 5000000002LL };
  m.Assign(wide);
  for (size_t i = 0; i < wide.size(); ++i)
  {
    EXPECT_EQ(m.At(i), wide[i]) << i;
  }
}

TEST(TriangleStore, DropsDegenerateKeepsOriginalIndex)
{
  std::vector<art::Vec3> pts = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 2, 0, 0 } };
  // 0: good, 1: collinear (zero area), 2: repeated vertex, 3: bad index, 4: good.
  art::TriangleStore s(pts, { { 0, 1, 2 }, { 0, 1, 3 }, { 1, 1, 2 }, { 0, 1, 7 }, { 3, 2, 1 } });
  ASSERT_EQ(s.Size(), 2u);
  EXPECT_EQ(s.DroppedCount(), 3u);
  std::set<long long> orig = { s.OriginalIndex(0), s.OriginalIndex(1) };
  EXPECT_EQ(orig, (std::set<long long>{ 0, 4 }));
  // A ray hitting the second good triangle reports its input index 4.
  auto store = std::make_shared<art::TriangleStore>(s);
  auto acc = art::MakeAccelerator(store, {});
  art::Ray r;
  r.org = { 1.5, 0.2, 1 };
  r.dir = { 0, 0, -1 };
  art::Hit h;
  art::Counters c;
  ASSERT_TRUE(acc->Closest(r, h, c));
  EXPECT_EQ(h.triangle, 4);
  EXPECT_DOUBLE_EQ(h.t, 1.0);
}

TEST(TriangleStore, FromPolyDataTriangulatesPolygonsAndStrips)
{
  vtkNew<vtkPoints> pts;
  // A unit square (quad), an L-shaped hexagon (non-convex) at z = 1, a strip of 4 points at z = 2.
  const double p[][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 2, 0, 1 }, { 2, 1, 1 },
    { 1, 1, 1 }, { 1, 2, 1 }, { 0, 2, 1 }, { 0, 0, 2 }, { 1, 0, 2 }, { 0, 1, 2 }, { 1, 1, 2 } };
  for (auto& q : p)
  {
    pts->InsertNextPoint(q);
  }
  vtkNew<vtkCellArray> verts, polys, strips;
  vtkIdType v0 = 0;
  verts->InsertNextCell(1, &v0);
  const vtkIdType quad[] = { 0, 1, 2, 3 }, hex[] = { 4, 5, 6, 7, 8, 9 }, strip[] = { 10, 11, 12, 13 };
  polys->InsertNextCell(4, quad);
  polys->InsertNextCell(6, hex);
  strips->InsertNextCell(4, strip);
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(pts);
  pd->SetVerts(verts);
  pd->SetPolys(polys);
  pd->SetStrips(strips);
  auto s = std::make_shared<art::TriangleStore>(art::TriangleStore::FromPolyData(pd));
  EXPECT_EQ(s->Size(), 2u + 4u + 2u);
  auto acc = art::MakeAccelerator(s, {});
  art::Counters c;
  art::Hit h;
  art::Ray r;
  r.dir = { 0, 0, -1 };
  // The notch of the L (cell 2) at (1.5, 1.5) is empty, and the quad spans only [0,1]^2.
  r.org = { 1.5, 1.5, 5 };
  EXPECT_FALSE(acc->Closest(r, h, c));
  r.org = { 0.5, 1.5, 5 };
  ASSERT_TRUE(acc->Closest(r, h, c));
  EXPECT_EQ(h.triangle, 2);
  r.org = { 0.7, 0.6, 5 };
  ASSERT_TRUE(acc->Closest(r, h, c));
  EXPECT_EQ(h.triangle, 3); // the strip
  std::vector<art::Hit> all;
  acc->All(r, all, c);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].triangle, 3);
  EXPECT_EQ(all[1].triangle, 2);
  EXPECT_EQ(all[2].triangle, 1);
  EXPECT_DOUBLE_EQ(all[2].t, 5.0);
}
