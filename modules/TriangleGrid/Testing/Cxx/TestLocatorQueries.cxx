// vtkTriangleGridLocator's other point and box queries: FindClosestPointWithinRadius (and its
// inside flag), FindCellsWithinBounds equal to the exact answer (brute force) and inside VTK's bucket
// answer, FindCell where vtkCellLocator finds a cell within tol; the rebuild rules and bad datasets;
// a line hit's pcoords on quads and polygons; queries from several threads at once.
#include "LocatorTestUtil.h"

#include <vtkAppendFilter.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellLocator.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkMath.h>
#include <vtkPoints.h>
#include <vtkSphereSource.h>
#include <vtkStaticCellLocator.h>

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <cstdio>
#include <set>
#include <thread>

using namespace arttest;

namespace
{
// Within a radius: found (same as without) when the radius exceeds the distance, not found below it.
void CheckRadius(vtkPolyData* pd, size_t n)
{
  const auto xs = QueryPoints(pd, n, 11);
  vtkNew<vtkStaticCellLocator> ref;
  ref->SetDataSet(pd);
  ref->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  for (int kind : Kinds)
  {
    auto loc = Ours(pd, kind);
    size_t bad = 0, insideChecked = 0;
    for (const auto& q : xs)
    {
      double x[3] = { q[0], q[1], q[2] }, cp[3], d2, cp2[3], d22;
      vtkIdType id, id2;
      int sub, inside;
      loc->FindClosestPoint(x, cp, cell, id, sub, d2);
      const double d = std::sqrt(d2);
      if (loc->FindClosestPointWithinRadius(x, 1.01 * d + 1e-12, cp2, cell, id2, sub, d22, inside) != 1 ||
        id2 != id || d22 != d2)
      {
        ++bad;
      }
      if (d > 0 && loc->FindClosestPointWithinRadius(x, 0.99 * d, cp2, cell, id2, sub, d22, inside) != 0)
      {
        ++bad;
      }
      // inside is the cell's EvaluatePosition verdict (VTK's), except on the cell's very boundary.
      loc->FindClosestPointWithinRadius(x, 2 * d + 1, cp2, cell, id2, sub, d22, inside);
      int vtkInside;
      CellDistance2(pd, id2, x, &vtkInside);
      if (inside != vtkInside)
      {
        // Only where the projection lies on an edge to rounding: then both verdicts are right.
        double pc[3], w[64], c3[3], dd;
        int s;
        pd->GetCell(id2, cell);
        cell->EvaluatePosition(x, c3, s, pc, dd, w);
        const double margin = std::min({ pc[0], pc[1], 1 - pc[0] - pc[1] });
        bad += std::fabs(margin) > 1e-9 ? 1 : 0;
      }
      ++insideChecked;
    }
    EXPECT_EQ(bad, 0u) << "kind " << kind;
    EXPECT_EQ(insideChecked, xs.size());
  }
}

// Boxes: ours is exactly the cells that intersect the box (brute force is the reference), and
// inside the bucket answers of VTK's locators.
void CheckBoxes(vtkPolyData* pd, size_t n)
{
  std::mt19937_64 g(3);
  std::uniform_real_distribution<double> u(0, 1);
  double b[6];
  pd->GetBounds(b);
  const double diag = Diagonal(pd);
  auto brute = Ours(pd, vtkTriangleGridLocator::BRUTE_FORCE);
  vtkNew<vtkCellLocator> cref;
  cref->SetDataSet(pd);
  cref->BuildLocator();
  std::vector<vtkSmartPointer<vtkTriangleGridLocator>> locs;
  for (int kind : Kinds)
  {
    locs.push_back(Ours(pd, kind));
  }
  vtkNew<vtkIdList> ref, got, vtkIds;
  size_t nonEmpty = 0;
  for (size_t i = 0; i < n; ++i)
  {
    double box[6];
    const double s = diag * (0.002 + 0.1 * u(g));
    for (int a = 0; a < 3; ++a)
    {
      const double c = b[2 * a] + u(g) * (b[2 * a + 1] - b[2 * a]);
      box[2 * a] = c - s * u(g);
      box[2 * a + 1] = c + s * u(g);
    }
    brute->FindCellsWithinBounds(box, ref);
    nonEmpty += ref->GetNumberOfIds() > 0 ? 1 : 0;
    std::set<vtkIdType> refSet(ref->begin(), ref->end());
    for (auto& loc : locs)
    {
      loc->FindCellsWithinBounds(box, got);
      ASSERT_EQ(std::set<vtkIdType>(got->begin(), got->end()), refSet) << "box " << i << " kind " << loc->GetAcceleratorType();
    }
    cref->FindCellsWithinBounds(box, vtkIds);
    std::set<vtkIdType> vtkSet(vtkIds->begin(), vtkIds->end());
    for (vtkIdType id : refSet)
    {
      ASSERT_TRUE(vtkSet.count(id)) << "cell " << id << " intersects box " << i << " but vtkCellLocator lists it not";
    }
  }
  EXPECT_GT(nonEmpty, n / 4);
}

// FindCell near the surface: where vtkCellLocator finds a cell within tol, ours finds it (or one as
// near); where ours finds one, it lies within tol; where neither does, no cell is within tol.
void CheckFindCell(vtkPolyData* pd, size_t n)
{
  const double diag = Diagonal(pd);
  const double tol = 1e-3 * diag;
  auto xs = QueryPoints(pd, n, 5);
  vtkNew<vtkCellLocator> cref;
  cref->SetDataSet(pd);
  cref->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  for (int kind : Kinds)
  {
    auto loc = Ours(pd, kind);
    size_t bad = 0, found = 0, vtkFound = 0, vtkWithin = 0;
    for (const auto& q : xs)
    {
      double x[3] = { q[0], q[1], q[2] }, pc[3], w[64], pcr[3], wr[64];
      const vtkIdType id = loc->FindCell(x, tol * tol, cell, pc, w);
      const vtkIdType idRef = cref->FindCell(x, tol * tol, cell, pcr, wr);
      found += id >= 0;
      vtkFound += idRef >= 0;
      if (id >= 0 && CellDistance2(pd, id, x) > tol * tol * (1 + 1e-9))
      {
        ++bad;
      }
      // vtkCellLocator (9.1) ignores tol2 for a surface: it answers whenever x lies in a cell's box
      // and projects inside it, however far from its plane. Compared where its cell is within tol.
      const bool refWithin = idRef >= 0 && CellDistance2(pd, idRef, x) <= tol * tol;
      vtkWithin += refWithin ? 1 : 0;
      if (refWithin && (id < 0 || CellDistance2(pd, id, x) > CellDistance2(pd, idRef, x) + 1e-18 * diag * diag))
      {
        if (++bad <= 3)
        {
          ADD_FAILURE() << "kind " << kind << " x (" << x[0] << ", " << x[1] << ", " << x[2] << "): ours " << id
                        << (id >= 0 ? " d2 " + std::to_string(CellDistance2(pd, id, x)) : std::string())
                        << ", vtkCellLocator " << idRef << " d2 " << CellDistance2(pd, idRef, x);
        }
      }
      if (id < 0)
      {
        double cp[3], d2;
        vtkIdType c;
        int s;
        loc->FindClosestPoint(x, cp, c, s, d2);
        bad += d2 <= tol * tol ? 1 : 0;
      }
      if (id >= 0 && id == idRef)
      {
        for (int k = 0; k < 3; ++k)
        {
          bad += std::fabs(w[k] - wr[k]) > 1e-9 ? 1 : 0; // the cell's own weights at x
        }
      }
    }
    EXPECT_EQ(bad, 0u) << "kind " << kind;
    EXPECT_GT(found, xs.size() / 20) << "kind " << kind; // part of the near-surface third
    EXPECT_GE(found, vtkWithin);
    std::printf("FindCell kind %d: ours %zu of %zu within tol; vtkCellLocator %zu (%zu of them within tol)\n", kind,
      found, xs.size(), vtkFound, vtkWithin);
  }
}
} // namespace

TEST(LocatorQueries, WithinRadius)
{
  auto pd = LoadIf(std::string(ART_SOURCE_DIR) + "/data/am_underworks.ply");
  ASSERT_TRUE(pd);
  CheckRadius(pd, 1500);
  CheckRadius(QuadPlane(), 600);
}

TEST(LocatorQueries, CellsWithinBounds)
{
  auto pd = LoadIf(std::string(ART_SOURCE_DIR) + "/data/am_underworks.ply");
  ASSERT_TRUE(pd);
  CheckBoxes(pd, 400);
  CheckBoxes(StripSphere(), 200);
}

// An infinite side reaches every located cell, as with VTK's locators (none came back); NaN none.
TEST(LocatorQueries, InfiniteBoxesHoldEveryCell)
{
  auto pd = LoadIf(std::string(ART_SOURCE_DIR) + "/data/am_underworks.ply");
  ASSERT_TRUE(pd);
  const double inf = std::numeric_limits<double>::infinity();
  double b[6];
  pd->GetBounds(b);
  for (int kind : Kinds)
  {
    auto loc = Ours(pd, kind);
    vtkNew<vtkIdList> ids;
    // Every located cell: as many as a finite box around the scene holds (its 3 zero-area
    // triangles are not located).
    double around[6] = { b[0] - 1, b[1] + 1, b[2] - 1, b[3] + 1, b[4] - 1, b[5] + 1 };
    loc->FindCellsWithinBounds(around, ids);
    const vtkIdType located = ids->GetNumberOfIds();
    EXPECT_GE(located, pd->GetNumberOfCells() - 3);
    double all[6] = { -inf, inf, -inf, inf, -inf, inf };
    loc->FindCellsWithinBounds(all, ids);
    EXPECT_EQ(ids->GetNumberOfIds(), located) << "kind " << kind;
    double upper[6] = { 0.5 * (b[0] + b[1]), inf, -inf, inf, -inf, inf }; // one half: some, not all
    loc->FindCellsWithinBounds(upper, ids);
    EXPECT_GT(ids->GetNumberOfIds(), 0) << "kind " << kind;
    EXPECT_LT(ids->GetNumberOfIds(), pd->GetNumberOfCells()) << "kind " << kind;
    double nan[6] = { std::nan(""), 1, -1, 1, -1, 1 };
    loc->FindCellsWithinBounds(nan, ids);
    EXPECT_EQ(ids->GetNumberOfIds(), 0) << "kind " << kind;
  }
}

TEST(LocatorQueries, FindCell)
{
  auto pd = LoadIf(std::string(ART_SOURCE_DIR) + "/data/am_underworks.ply");
  ASSERT_TRUE(pd);
  CheckFindCell(pd, 1500);
  CheckFindCell(QuadPlane(), 600);
}

// UseExistingSearchStructure keeps a structure only over a data set with as many cells: pointed
// at a coarser one, it named cells up to 464 of 24 and handed them to GetCell (probe13).
TEST(LocatorQueries, ExistingStructureIsNotKeptOverFewerCells)
{
  vtkNew<vtkSphereSource> fine, coarse;
  fine->SetThetaResolution(30);
  fine->SetPhiResolution(30);
  coarse->SetThetaResolution(6);
  coarse->SetPhiResolution(4);
  fine->Update();
  coarse->Update();
  vtkNew<vtkTriangleGridLocator> loc;
  loc->SetDataSet(fine->GetOutput());
  loc->BuildLocator();
  loc->UseExistingSearchStructureOn();
  loc->SetDataSet(coarse->GetOutput());
  loc->BuildLocator();
  const vtkIdType n = coarse->GetOutput()->GetNumberOfCells();
  for (double z : { 0.3, -0.3 })
  {
    double x[3] = { 0.05, 0.02, z }, cp[3], d2;
    vtkIdType id;
    int sub;
    loc->FindClosestPoint(x, cp, id, sub, d2);
    EXPECT_TRUE(id >= 0 && id < n) << id << " of " << n;
  }
}

TEST(LocatorQueries, RebuildsWhenTheDataSetChanges)
{
  auto pd = StripSphere();
  double x[3] = { 3, -1, 10 }, cp[3], d2;
  vtkIdType id;
  int sub;
  for (int existing = 0; existing < 2; ++existing)
  {
    vtkNew<vtkPolyData> copy;
    copy->DeepCopy(pd);
    auto loc = Ours(copy, vtkTriangleGridLocator::RECURSIVE_GRID);
    loc->SetUseExistingSearchStructure(existing);
    loc->FindClosestPoint(x, cp, id, sub, d2);
    EXPECT_NEAR(std::sqrt(d2), 8 - 1.5, 1e-9);
    // Lift the sphere by 2 along z: the top is now 4.5 from x.
    vtkPoints* pts = copy->GetPoints();
    for (vtkIdType i = 0; i < pts->GetNumberOfPoints(); ++i)
    {
      double p[3];
      pts->GetPoint(i, p);
      pts->SetPoint(i, p[0], p[1], p[2] + 2);
    }
    pts->Modified();
    copy->Modified();
    loc->FindClosestPoint(x, cp, id, sub, d2);
    // Rebuilt unless told to keep the existing structure (which keeps the geometry it copied).
    EXPECT_NEAR(std::sqrt(d2), existing ? 6.5 : 4.5, 1e-9) << "UseExistingSearchStructure " << existing;
    loc->FreeSearchStructure();
    loc->FindClosestPoint(x, cp, id, sub, d2);
    EXPECT_NEAR(std::sqrt(d2), 4.5, 1e-9);
  }
}

TEST(LocatorQueries, NoPolygonsIsAnErrorNotACrash)
{
  int errors = 0;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&errors);
  count->SetCallback([](vtkObject*, unsigned long, void* cd, void*) { ++*static_cast<int*>(cd); });
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(0, 0, 0);
  pts->InsertNextPoint(1, 0, 0);
  pts->InsertNextPoint(0, 1, 0);
  vtkNew<vtkCellArray> lines, verts;
  const vtkIdType l[2] = { 0, 1 }, v[1] = { 2 };
  lines->InsertNextCell(2, l);
  verts->InsertNextCell(1, v);
  vtkNew<vtkPolyData> linesOnly, empty;
  linesOnly->SetPoints(pts);
  linesOnly->SetLines(lines);
  linesOnly->SetVerts(verts);
  for (vtkPolyData* pd : { linesOnly.GetPointer(), empty.GetPointer() })
  {
    errors = 0;
    vtkNew<vtkTriangleGridLocator> loc;
    loc->AddObserver(vtkCommand::ErrorEvent, count);
    loc->SetDataSet(pd);
    double x[3] = { 0.2, 0.2, 1 }, cp[3], d2, pc[3], w[3];
    vtkIdType id = 7;
    int sub;
    loc->FindClosestPoint(x, cp, id, sub, d2);
    EXPECT_EQ(id, -1);
    EXPECT_EQ(loc->FindClosestPointWithinRadius(x, 10, cp, id, sub, d2), 0);
    vtkNew<vtkGenericCell> cell;
    EXPECT_EQ(loc->FindCell(x, 1, cell, pc, w), -1);
    vtkNew<vtkIdList> ids;
    double box[6] = { -1, 1, -1, 1, -1, 1 };
    loc->FindCellsWithinBounds(box, ids);
    EXPECT_EQ(ids->GetNumberOfIds(), 0);
    EXPECT_EQ(errors, 1) << "one error for the build, none per query";
  }
}

TEST(LocatorQueries, AnalyticInsideFlag)
{
  // One triangle: above its middle x projects inside; beyond a vertex it does not.
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(0, 0, 0);
  pts->InsertNextPoint(2, 0, 0);
  pts->InsertNextPoint(0, 2, 0);
  vtkNew<vtkCellArray> tri;
  const vtkIdType t[3] = { 0, 1, 2 };
  tri->InsertNextCell(3, t);
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(pts);
  pd->SetPolys(tri);
  for (int kind : Kinds)
  {
    auto loc = Ours(pd, kind);
    double x[3] = { 0.5, 0.5, 3 }, cp[3], d2;
    vtkIdType id;
    int sub, inside;
    vtkNew<vtkGenericCell> cell;
    ASSERT_EQ(loc->FindClosestPointWithinRadius(x, 5, cp, cell, id, sub, d2, inside), 1);
    EXPECT_EQ(inside, 1);
    EXPECT_DOUBLE_EQ(d2, 9);
    EXPECT_EQ(cell->GetCellType(), VTK_TRIANGLE);
    double y[3] = { -3, -4, 0 };
    ASSERT_EQ(loc->FindClosestPointWithinRadius(y, 6, cp, cell, id, sub, d2, inside), 1);
    EXPECT_EQ(inside, 0);
    EXPECT_DOUBLE_EQ(d2, 25);
    EXPECT_EQ(cp[0], 0);
    EXPECT_EQ(cp[1], 0);
    EXPECT_EQ(loc->FindClosestPointWithinRadius(y, 5, cp, cell, id, sub, d2, inside), 0)
      << "strictly within the radius";
  }
}


TEST(LocatorQueries, LineHitGivesTheCellsOwnPcoords)
{
  // A quad's and a polygon's pcoords are the cell's own (bilinear, the polygon's frame), not the
  // weights in the triangle of its triangulation that was hit: vtkCellPicker interpolates the
  // hit's normal and texture coordinates with them (quads: up to 0.5 of the cell off).
  vtkNew<vtkPoints> hexPts;
  for (int k = 0; k < 6; ++k)
  {
    hexPts->InsertNextPoint(2 * std::cos(k * M_PI / 3), 2 * std::sin(k * M_PI / 3), 0.5);
  }
  vtkNew<vtkCellArray> hexCell;
  const vtkIdType h[6] = { 0, 1, 2, 3, 4, 5 };
  hexCell->InsertNextCell(6, h);
  vtkNew<vtkPolyData> hexagon;
  hexagon->SetPoints(hexPts);
  hexagon->SetPolys(hexCell);
  vtkSmartPointer<vtkPolyData> quads = QuadPlane();
  for (vtkPolyData* pd : { quads.GetPointer(), hexagon.GetPointer() })
  {
    vtkNew<vtkCellLocator> ref;
    ref->SetDataSet(pd);
    ref->BuildLocator();
    double b[6];
    pd->GetBounds(b);
    std::mt19937_64 g(5);
    std::uniform_real_distribution<double> u(0, 1);
    for (int kind : Kinds)
    {
      auto loc = Ours(pd, kind);
      vtkNew<vtkGenericCell> cell, refCell;
      int hits = 0;
      for (int i = 0; i < 200; ++i)
      {
        // Segments from above the surface's box to below it, the plane's normal mostly along z.
        const double p1[3] = { b[0] + u(g) * (b[1] - b[0]), b[2] + u(g) * (b[3] - b[2]), b[5] + 3 };
        const double p2[3] = { b[0] + u(g) * (b[1] - b[0]), b[2] + u(g) * (b[3] - b[2]), b[4] - 3 };
        double t, x[3], pc[3], rt, rx[3], rpc[3];
        int sub, rsub;
        vtkIdType id, rid;
        const int hit = loc->IntersectWithLine(p1, p2, 0.0, t, x, pc, sub, id, cell);
        const int refHit = ref->IntersectWithLine(p1, p2, 0.0, rt, rx, rpc, rsub, rid, refCell);
        ASSERT_EQ(hit, refHit);
        if (!hit)
        {
          continue;
        }
        ++hits;
        // The cell's own location at (subId, pcoords) is the hit point.
        double back[3], w[8];
        cell->EvaluateLocation(sub, pc, back, w);
        // (The engine traces in float and a quad's pcoords come by Newton steps: 1e-6 of a cell.)
        EXPECT_LT(std::sqrt(vtkMath::Distance2BetweenPoints(back, x)), 1e-6) << "kind " << kind << " cell " << id;
        if (id == rid)
        {
          EXPECT_NEAR(pc[0], rpc[0], 1e-6);
          EXPECT_NEAR(pc[1], rpc[1], 1e-6);
        }
      }
      EXPECT_GT(hits, 50);
    }
  }
}

TEST(LocatorQueries, AnyDataSetOfSurfaceCells)
{
  // vtkCellLocator takes any vtkDataSet; this one said 'needs a vtkPolyData input' to an
  // unstructured grid of triangles (a clipped surface) and to an image slice of pixels. Their line
  // hits and closest cells must be vtkCellLocator's (cells named by the data set's own ids).
  vtkNew<vtkAppendFilter> append;
  append->AddInputData(StripSphere());
  append->Update();
  vtkNew<vtkImageData> slice;
  slice->SetDimensions(7, 5, 1);
  slice->SetSpacing(0.5, 0.75, 1);
  slice->SetOrigin(1.5, -2, 2);
  for (vtkDataSet* ds : { static_cast<vtkDataSet*>(append->GetOutput()), static_cast<vtkDataSet*>(slice.GetPointer()) })
  {
    vtkNew<vtkCellLocator> ref;
    ref->SetDataSet(ds);
    ref->BuildLocator();
    vtkNew<vtkTriangleGridLocator> loc;
    loc->SetDataSet(ds);
    loc->BuildLocator();
    ASSERT_GT(loc->GetNumberOfTriangles(), 0) << ds->GetClassName();
    double b[6];
    ds->GetBounds(b);
    std::mt19937_64 g(9);
    std::uniform_real_distribution<double> u(0, 1);
    vtkNew<vtkGenericCell> cell;
    int hits = 0;
    for (int i = 0; i < 200; ++i)
    {
      const double p1[3] = { b[0] + u(g) * (b[1] - b[0]), b[2] + u(g) * (b[3] - b[2]), b[5] + 2 };
      const double p2[3] = { b[0] + u(g) * (b[1] - b[0]), b[2] + u(g) * (b[3] - b[2]), b[4] - 2 };
      double t, x[3], pc[3], rt, rx[3], rpc[3];
      int sub, rsub;
      vtkIdType id = -1, rid = -1;
      const int hit = loc->IntersectWithLine(p1, p2, 0.0, t, x, pc, sub, id, cell);
      ASSERT_EQ(hit, ref->IntersectWithLine(p1, p2, 0.0, rt, rx, rpc, rsub, rid, cell));
      if (hit)
      {
        ++hits;
        EXPECT_EQ(id, rid) << ds->GetClassName();
        EXPECT_NEAR(t, rt, 1e-6);
      }
      // The closest cell of a point above the surface: as near as VTK's (ties may differ).
      double q[3] = { p1[0], p1[1], b[5] + 0.3 }, cp[3], rcp[3], d2, rd2;
      vtkIdType c, rc;
      loc->FindClosestPoint(q, cp, cell, c, sub, d2);
      ref->FindClosestPoint(q, rcp, cell, rc, rsub, rd2);
      EXPECT_NEAR(d2, rd2, 1e-9);
      EXPECT_NEAR(CellDistance2(ds, c, q), d2, 1e-9) << "cell " << c << " of " << ds->GetClassName();
    }
    EXPECT_GT(hits, 100);
  }
  // A grid of tets is refused in one error (this locator finds surfaces), no crash after it.
  vtkNew<vtkPoints> corners;
  corners->InsertNextPoint(0, 0, 0);
  corners->InsertNextPoint(1, 0, 0);
  corners->InsertNextPoint(0, 1, 0);
  corners->InsertNextPoint(0, 0, 1);
  vtkNew<vtkUnstructuredGrid> tet;
  tet->SetPoints(corners);
  const vtkIdType four[4] = { 0, 1, 2, 3 };
  tet->InsertNextCell(VTK_TETRA, 4, four);
  int errors = 0;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&errors);
  count->SetCallback([](vtkObject*, unsigned long, void* cd, void*) { ++*static_cast<int*>(cd); });
  vtkNew<vtkTriangleGridLocator> loc;
  loc->AddObserver(vtkCommand::ErrorEvent, count);
  loc->SetDataSet(tet);
  double x[3] = { 0.5, 0.5, 5 }, cp[3], d2;
  vtkIdType id;
  int sub;
  loc->FindClosestPoint(x, cp, id, sub, d2);
  EXPECT_EQ(id, -1);
  EXPECT_EQ(errors, 1);
}

TEST(LocatorQueries, QueriesFromSeveralThreadsAtOnce)
{
  // A polydata as a source hands it over (its cell map not built) and queries from 4 threads at
  // once, each with its own vtkGenericCell, as vtkTrimmedExtrusionFilter makes them: the queries
  // asked the polydata for cell types, and the first such call builds the map unguarded, so the
  // threads built it together (double free, or a crash in vtkPolyData::BuildCells). The build now
  // makes the map, and the threads' answers are those of one thread.
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(120, 120);
  plane->Update();
  for (int kind : Kinds)
  {
    vtkNew<vtkPolyData> pd;
    pd->SetPoints(plane->GetOutput()->GetPoints());
    pd->SetPolys(plane->GetOutput()->GetPolys());
    ASSERT_TRUE(pd->NeedToBuildCells());
    auto loc = Ours(pd, kind);
    EXPECT_FALSE(pd->NeedToBuildCells()) << "the build leaves the polydata's cell map to the first queries";
    const int nthreads = 4, n = 300;
    auto ask = [&](int k, int i, vtkGenericCell* cell) {
      std::mt19937 g(1000 * k + i);
      std::uniform_real_distribution<double> u(-0.49, 0.49);
      const double p1[3] = { u(g), u(g), 1 }, p2[3] = { p1[0], p1[1], -1 };
      double t, x[3], pc[3], cp[3], d2, q[3] = { p1[0], p1[1], 0.3 };
      int sub, sub2;
      vtkIdType line = -1, near = -1;
      loc->IntersectWithLine(p1, p2, 0.0, t, x, pc, sub, line, cell);
      loc->FindClosestPoint(q, cp, cell, near, sub2, d2);
      return std::array<vtkIdType, 3>{ line, near, sub };
    };
    std::vector<std::array<vtkIdType, 3>> expected;
    {
      vtkNew<vtkGenericCell> cell;
      for (int k = 0; k < nthreads; ++k)
        for (int i = 0; i < n; ++i)
          expected.push_back(ask(k, i, cell));
    }
    // Again on a fresh polydata, from the threads.
    vtkNew<vtkPolyData> fresh;
    fresh->SetPoints(plane->GetOutput()->GetPoints());
    fresh->SetPolys(plane->GetOutput()->GetPolys());
    loc->SetDataSet(fresh);
    loc->BuildLocator();
    std::atomic<int> ready{ 0 }, differ{ 0 };
    std::vector<std::thread> threads;
    for (int k = 0; k < nthreads; ++k)
    {
      threads.emplace_back([&, k] {
        vtkNew<vtkGenericCell> cell;
        ++ready;
        while (ready < nthreads)
        {
        }
        for (int i = 0; i < n; ++i)
          if (ask(k, i, cell) != expected[static_cast<size_t>(k * n + i)])
            ++differ;
      });
    }
    for (auto& t : threads)
      t.join();
    EXPECT_EQ(differ, 0) << "kind " << kind;
  }
}

TEST(LocatorQueries, FarSceneLargerThanAThousandthOfItsDistance)
{
  // Survey coordinates: a ground triangle 1e4 across at (1e7, 1e7) with two small roof triangles.
  // The store took coordinates from the scene's centre only beyond 1000 diagonals, so here it kept
  // them from the origin, where a float is whole units: the 0.3-wide triangle was missed and the
  // other hit 0.02 too high. Line hits must be vtkCellLocator's, to float precision of the scene.
  const double o = 1e7;
  const double xyz[9][3] = { { 0, 0, 0 }, { 10000, 0, 0 }, { 0, 10000, 0 }, { 5000.1, 5000.1, 10 },
    { 5000.4, 5000.1, 10 }, { 5000.1, 5000.4, 10 }, { 6000.2, 3000.2, 20.3 }, { 6000.6, 3000.2, 20.3 },
    { 6000.2, 3000.6, 20.7 } };
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& p : xyz)
  {
    pts->InsertNextPoint(o + p[0], o + p[1], p[2]);
  }
  vtkNew<vtkCellArray> tris;
  for (vtkIdType c = 0; c < 3; ++c)
  {
    const vtkIdType ids[3] = { 3 * c, 3 * c + 1, 3 * c + 2 };
    tris->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(pts);
  pd->SetPolys(tris);
  vtkNew<vtkCellLocator> ref;
  ref->SetDataSet(pd);
  ref->BuildLocator();
  vtkNew<vtkGenericCell> cell;
  const double aims[3][2] = { { 5000.2, 5000.2 }, { 6000.3, 3000.3 }, { 1234.56, 2345.67 } };
  for (int kind : Kinds)
  {
    auto loc = Ours(pd, kind);
    for (int a = 0; a < 3; ++a)
    {
      const double p1[3] = { o + aims[a][0], o + aims[a][1], 100 }, p2[3] = { p1[0], p1[1], -100 };
      double t, x[3], pc[3], rt, rx[3], rpc[3];
      int sub, rsub;
      vtkIdType id = -1, rid = -1;
      ASSERT_EQ(ref->IntersectWithLine(p1, p2, 0.0, rt, rx, rpc, rsub, rid, cell), 1);
      ASSERT_EQ(loc->IntersectWithLine(p1, p2, 0.0, t, x, pc, sub, id, cell), 1) << "kind " << kind << " aim " << a;
      EXPECT_EQ(id, rid) << "kind " << kind << " aim " << a;
      // The store traces float vertices taken from the scene's centre: within 1e-7 of its diagonal
      // (1.4e-3 here; the small triangles are 0.3-0.4 across).
      EXPECT_NEAR(x[2], rx[2], 1.5e-3) << "kind " << kind << " aim " << a;
      EXPECT_NEAR(pc[0], rpc[0], 1e-2);
      EXPECT_NEAR(pc[1], rpc[1], 1e-2);
    }
  }
}

TEST(LocatorQueries, FindCellWithZeroToleranceFindsPointsOnTheSurface)
{
  // FindCell(x) asks with tol2 = 0. A random point of a random triangle (in double) lies on the
  // surface, but the closest point's arithmetic leaves ~1e-17 of it, and tol2 = 0 was taken
  // literally: 26% of such points on am_underworks and 55% on a sphere got -1, where
  // vtkStaticCellLocator and vtkCellLocator find every one.
  auto level = LoadIf(std::string(ART_SOURCE_DIR) + "/data/am_underworks.ply");
  ASSERT_TRUE(level);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(1000, -2000, 500);
  sphere->SetThetaResolution(30);
  sphere->SetPhiResolution(20);
  sphere->Update();
  for (vtkPolyData* pd : { level.GetPointer(), sphere->GetOutput() })
  {
    std::mt19937_64 g(4);
    std::uniform_real_distribution<double> u(0, 1);
    std::uniform_int_distribution<vtkIdType> pick(0, pd->GetNumberOfCells() - 1);
    for (int kind : Kinds)
    {
      auto loc = Ours(pd, kind);
      vtkNew<vtkGenericCell> cell;
      int missed = 0;
      for (int i = 0; i < 300; ++i)
      {
        pd->GetCell(pick(g), cell);
        double a = u(g), b = u(g);
        if (a + b > 1)
        {
          a = 1 - a;
          b = 1 - b;
        }
        double p[3][3], x[3];
        for (int k = 0; k < 3; ++k)
        {
          cell->GetPoints()->GetPoint(k, p[k]);
        }
        for (int j = 0; j < 3; ++j)
        {
          x[j] = p[0][j] + a * (p[1][j] - p[0][j]) + b * (p[2][j] - p[0][j]);
        }
        const vtkIdType id = loc->FindCell(x);
        if (id < 0)
        {
          ++missed;
        }
        else
        {
          EXPECT_LT(CellDistance2(pd, id, x), 1e-20) << "kind " << kind;
        }
      }
      EXPECT_EQ(missed, 0) << "kind " << kind << ", " << pd->GetNumberOfCells() << " cells";
    }
  }
}

TEST(LocatorQueries, ConcaveFourPointPolygon)
{
  // A VTK_POLYGON of 4 points with its reflex corner at index 1 (a dart), in an unstructured grid.
  // The store cut every 4-gon into a fan from corner 0, whose diagonal 0-2 runs outside a dart: a
  // line through the notch hit the cell and a point above the notch was 'on' it, where
  // vtkCellLocator (vtkPolygon's own tests) misses and finds the dart's edge.
  vtkNew<vtkPoints> pts;
  const double xyz[4][3] = { { 0, 0, 0 }, { 1, 0.8, 0 }, { 2, 0, 0 }, { 1, 2, 0 } };
  for (const auto& p : xyz)
  {
    pts->InsertNextPoint(p);
  }
  for (int rotate = 0; rotate < 4; ++rotate)
  {
    vtkNew<vtkUnstructuredGrid> ug;
    ug->SetPoints(pts);
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = (k + rotate) % 4; // the reflex corner at every index in turn
    }
    ug->InsertNextCell(VTK_POLYGON, 4, ids);
    vtkNew<vtkCellLocator> ref;
    ref->SetDataSet(ug);
    ref->BuildLocator();
    vtkNew<vtkGenericCell> cell;
    for (int kind : Kinds)
    {
      vtkNew<vtkTriangleGridLocator> loc;
      loc->SetAcceleratorType(kind);
      loc->SetDataSet(ug);
      loc->BuildLocator();
      double t, x[3], pc[3];
      int sub;
      vtkIdType id;
      const double notch[2][3] = { { 1, 0.3, 1 }, { 1, 0.3, -1 } }, body[2][3] = { { 1, 1.2, 1 }, { 1, 1.2, -1 } };
      EXPECT_EQ(loc->IntersectWithLine(notch[0], notch[1], 0.0, t, x, pc, sub, id, cell), 0) << "rotation " << rotate;
      EXPECT_EQ(ref->IntersectWithLine(notch[0], notch[1], 0.0, t, x, pc, sub, id, cell), 0);
      EXPECT_EQ(loc->IntersectWithLine(body[0], body[1], 0.0, t, x, pc, sub, id, cell), 1) << "rotation " << rotate;
      double q[3] = { 1, 0.3, 0.2 }, cp[3], rcp[3], d2, rd2;
      vtkIdType c, rc;
      loc->FindClosestPoint(q, cp, cell, c, sub, d2);
      ref->FindClosestPoint(q, rcp, cell, rc, sub, rd2);
      EXPECT_NEAR(d2, rd2, 1e-12) << "rotation " << rotate << " kind " << kind;
    }
  }
}
