#include "Accelerator.h"
#include "TriangleStore.h"
#include "TriangleTestUtil.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <set>

TEST(TriangleStore, RecordIsOneCacheLine)
{
  EXPECT_EQ(sizeof(art::TriangleRecord), 64u);
}

TEST(TriangleStore, CoplanarTrianglesShareOnePlane)
{
  // A box with 4x4 squares per face: 192 triangles on exactly 6 planes.
  auto s = arttest::BoxMesh({ 0, 0, 0 }, { 1, 2, 3 }, 4);
  ASSERT_EQ(s->Size(), 192u);
  EXPECT_EQ(s->Planes().size(), 6u);
  // Sorted by plane: each plane's triangles form one run, flagged SharedPlane except the last.
  size_t runs = 0;
  for (size_t i = 0; i < s->Size(); ++i)
  {
    if (i == 0 || s->Record(i).plane != s->Record(i - 1).plane)
    {
      ++runs;
    }
    const bool shared = (s->Record(i).flags & art::TriangleRecord::SharedPlane) != 0;
    EXPECT_EQ(shared, i + 1 < s->Size() && s->Record(i + 1).plane == s->Record(i).plane);
    EXPECT_TRUE(s->Record(i).flags & art::TriangleRecord::AxisPlane);
  }
  EXPECT_EQ(runs, 6u);
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
