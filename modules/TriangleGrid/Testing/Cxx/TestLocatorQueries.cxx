// vtkTriangleGridLocator's point and box queries against VTK's own locators on the same data:
// FindClosestPoint[WithinRadius] equal to vtkStaticCellLocator's and vtkCellLocator's (distance to
// 1e-9 relative, same cell unless two cells are equally near) for random points inside, near and far
// outside the surface, for every accelerator; FindCellsWithinBounds equal to the exact answer (brute
// force) and inside VTK's bucket answers; FindCell where vtkCellLocator finds a cell; rebuild rules.
#include "DataLoader.h"
#include "vtkTriangleGridLocator.h"

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellLocator.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkStaticCellLocator.h>
#include <vtkStripper.h>
#include <vtkTriangleFilter.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace
{
const int Kinds[] = { vtkTriangleGridLocator::BRUTE_FORCE, vtkTriangleGridLocator::UNIFORM_GRID,
  vtkTriangleGridLocator::RECURSIVE_GRID, vtkTriangleGridLocator::OCTREE };

double Diagonal(vtkPolyData* pd)
{
  double b[6];
  pd->GetBounds(b);
  return std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
}

// Query points: a third uniform in the (slightly grown) bounding box, a third near the surface
// (a random point of a random cell moved up to 1% of the diagonal), a third 1-10 diagonals away.
std::vector<std::array<double, 3>> QueryPoints(vtkPolyData* pd, size_t n, unsigned seed)
{
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0, 1);
  double b[6];
  pd->GetBounds(b);
  const double diag = Diagonal(pd);
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  std::vector<std::array<double, 3>> xs(n);
  vtkNew<vtkIdList> ids;
  for (size_t i = 0; i < n; ++i)
  {
    std::array<double, 3>& x = xs[i];
    std::normal_distribution<double> nd;
    double d[3] = { nd(g), nd(g), nd(g) };
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) + 1e-300;
    if (i % 3 == 0)
    {
      for (int a = 0; a < 3; ++a)
      {
        const double pad = 0.05 * (b[2 * a + 1] - b[2 * a]);
        x[a] = b[2 * a] - pad + u(g) * (b[2 * a + 1] - b[2 * a] + 2 * pad);
      }
    }
    else if (i % 3 == 1)
    {
      const vtkIdType cell = static_cast<vtkIdType>(u(g) * pd->GetNumberOfCells()) % pd->GetNumberOfCells();
      pd->GetCellPoints(cell, ids);
      double w[3] = { u(g), u(g), 0 };
      if (w[0] + w[1] > 1)
      {
        w[0] = 1 - w[0], w[1] = 1 - w[1];
      }
      w[2] = 1 - w[0] - w[1];
      x = { 0, 0, 0 };
      for (int k = 0; k < 3; ++k)
      {
        const double* p = pd->GetPoint(ids->GetId(std::min<vtkIdType>(k, ids->GetNumberOfIds() - 1)));
        for (int a = 0; a < 3; ++a)
        {
          x[a] += w[k] * p[a];
        }
      }
      const double off = 0.01 * diag * u(g);
      for (int a = 0; a < 3; ++a)
      {
        x[a] += off * d[a] / len;
      }
    }
    else
    {
      const double r = diag * (1 + 9 * u(g));
      for (int a = 0; a < 3; ++a)
      {
        x[a] = c[a] + r * d[a] / len;
      }
    }
  }
  return xs;
}

// Squared distance from x to cell `id` by the cell's own EvaluatePosition (VTK's measure).
double CellDistance2(vtkPolyData* pd, vtkIdType id, const double x[3], int* inside = nullptr)
{
  vtkNew<vtkGenericCell> cell;
  pd->GetCell(id, cell);
  double cp[3], pc[3], d2;
  std::vector<double> w(static_cast<size_t>(cell->GetNumberOfPoints())); // a strip has many
  int sub;
  const int r = cell->EvaluatePosition(x, cp, sub, pc, d2, w.data());
  if (inside)
  {
    *inside = r;
  }
  return d2;
}

struct Stats
{
  size_t queries = 0, sameCell = 0, ties = 0;
  double maxRel = 0;
};

// One locator's FindClosestPoint against a VTK locator's on every point: same distance, same cell
// or an equally near one, same closest point.
// `ref` may locate a triangulated copy refPd of pd whose triangles div * i .. div * i + div - 1
// are cell i of pd (vtkQuad::EvaluatePosition clamps parametric coordinates outside the quad, so
// VTK's own answer on quads is not the nearest point; on their triangles it is).
struct Answer
{
  double cp[3], d2;
  vtkIdType id;
};

std::vector<Answer> Answers(vtkAbstractCellLocator* loc, const std::vector<std::array<double, 3>>& xs)
{
  std::vector<Answer> out(xs.size());
  vtkNew<vtkGenericCell> cell;
  for (size_t i = 0; i < xs.size(); ++i)
  {
    int sub;
    loc->FindClosestPoint(xs[i].data(), out[i].cp, cell, out[i].id, sub, out[i].d2);
  }
  return out;
}

void CompareClosest(vtkPolyData* pd, const std::vector<Answer>& ours, const std::vector<Answer>& refs,
  const std::vector<std::array<double, 3>>& xs, Stats& st, const std::string& what, vtkPolyData* refPd = nullptr,
  int div = 1)
{
  refPd = refPd ? refPd : pd;
  auto cellDistance2 = [&](vtkIdType id, const double x[3]) {
    double d2 = VTK_DOUBLE_MAX;
    for (int k = 0; k < div; ++k)
    {
      d2 = std::min(d2, CellDistance2(refPd, div * id + k, x));
    }
    return d2;
  };
  const double diag = Diagonal(pd);
  size_t failures = 0;
  for (size_t i = 0; i < ours.size(); ++i)
  {
    double x[3] = { xs[i][0], xs[i][1], xs[i][2] };
    const double* cp = ours[i].cp;
    const double d2 = ours[i].d2;
    const vtkIdType id = ours[i].id;
    const double* cpRef = refs[i].cp;
    const double d2Ref = refs[i].d2;
    const vtkIdType idRef = refs[i].id / div;
    ++st.queries;
    const double d = std::sqrt(d2), dRef = std::sqrt(d2Ref);
    // 1e-9 relative; points lying on the surface (distance ~1e-16) get a floor of 1e-12 diagonals.
    const double tol = 1e-9 * std::max(dRef, 1e-3 * diag);
    st.maxRel = std::max(st.maxRel, std::fabs(d - dRef) / std::max(dRef, 1e-3 * diag));
    bool ok = id >= 0 && std::fabs(d - dRef) <= tol;
    if (ok && id == idRef)
    {
      ++st.sameCell;
    }
    else if (ok)
    {
      // A tie: the reference's cell is exactly as near as ours.
      ok = std::fabs(std::sqrt(cellDistance2(idRef, x)) - d) <= tol &&
        std::fabs(std::sqrt(cellDistance2(id, x)) - d) <= tol;
      st.ties += ok ? 1 : 0;
    }
    if (ok)
    {
      for (int a = 0; a < 3; ++a)
      {
        // The closest point is unique on a surface unless x is equally near two parts of it.
        ok = ok && (std::fabs(cp[a] - cpRef[a]) <= 1e-7 * diag || id != idRef);
      }
    }
    if (!ok && ++failures <= 5)
    {
      ADD_FAILURE() << what << ": x = (" << x[0] << ", " << x[1] << ", " << x[2] << "): ours cell " << id
                    << " d " << d << ", reference cell " << idRef << " d " << dRef;
    }
  }
  EXPECT_EQ(failures, 0u) << what;
}

vtkSmartPointer<vtkTriangleGridLocator> Ours(vtkPolyData* pd, int kind)
{
  auto loc = vtkSmartPointer<vtkTriangleGridLocator>::New();
  loc->SetDataSet(pd);
  loc->SetAcceleratorType(kind);
  loc->BuildLocator();
  return loc;
}

void CheckAgainstVTK(vtkPolyData* pd, size_t n, const std::string& name, vtkPolyData* refPd = nullptr, int div = 1)
{
  const auto xs = QueryPoints(pd, n, 7);
  vtkNew<vtkStaticCellLocator> sref;
  sref->SetDataSet(refPd ? refPd : pd);
  sref->BuildLocator();
  vtkNew<vtkCellLocator> cref;
  cref->SetDataSet(refPd ? refPd : pd);
  cref->BuildLocator();
  const auto sAnswers = Answers(sref, xs), cAnswers = Answers(cref, xs);
  for (int kind : Kinds)
  {
    auto loc = Ours(pd, kind);
    // Brute force on a large mesh checks a prefix of the points (it scans every triangle).
    const bool prefix = kind == vtkTriangleGridLocator::BRUTE_FORCE && pd->GetNumberOfCells() > 20000;
    const auto ours = Answers(loc, prefix ? std::vector<std::array<double, 3>>(xs.begin(), xs.begin() + 300) : xs);
    Stats s1, s2;
    CompareClosest(pd, ours, sAnswers, xs, s1, name + " kind " + std::to_string(kind) + " vs vtkStaticCellLocator", refPd, div);
    CompareClosest(pd, ours, cAnswers, xs, s2, name + " kind " + std::to_string(kind) + " vs vtkCellLocator", refPd, div);
    // Ties are common (far points are often nearest a vertex that many cells share); each was
    // checked above to be exactly as near.
    EXPECT_EQ(s1.sameCell + s1.ties, s1.queries) << name;
    std::printf("%s kind %d: %zu queries, same cell %zu / %zu (static / cell locator), ties %zu / %zu, max rel %.2g / %.2g\n",
      name.c_str(), kind, s1.queries, s1.sameCell, s2.sameCell, s1.ties, s2.ties, s1.maxRel, s2.maxRel);
  }
}

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

vtkSmartPointer<vtkPolyData> LoadIf(const std::string& path)
{
  if (!std::ifstream(path).good())
  {
    return nullptr;
  }
  return art::LoadSurface(path);
}

vtkSmartPointer<vtkPolyData> StripSphere()
{
  vtkNew<vtkSphereSource> s;
  s.GetPointer()->SetCenter(3, -1, 2);
  s->SetRadius(1.5);
  s->SetThetaResolution(40);
  s->SetPhiResolution(30);
  vtkNew<vtkStripper> strip;
  strip->SetInputConnection(s->GetOutputPort());
  strip->Update();
  return strip->GetOutput();
}

vtkSmartPointer<vtkPolyData> QuadPlane()
{
  vtkNew<vtkPlaneSource> p;
  p->SetOrigin(0, 0, 0);
  p->SetPoint1(4, 1, 0);
  p->SetPoint2(-1, 3, 2);
  p->SetResolution(17, 13);
  p->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION); // float points make the quads bend
  p->Update();
  return p->GetOutput();
}
} // namespace

TEST(LocatorQueries, ClosestPointUnderworksMatchesVTK)
{
  auto pd = LoadIf(std::string(ART_SOURCE_DIR) + "/data/am_underworks.ply");
  ASSERT_TRUE(pd);
  CheckAgainstVTK(pd, 3000, "am_underworks");
}

TEST(LocatorQueries, ClosestPointBunnyMatchesVTK)
{
  auto pd = LoadIf(std::string(ART_SHARED_DATA) + "/bunny.ply");
  if (!pd)
  {
    GTEST_SKIP() << "no bunny.ply in " << ART_SHARED_DATA;
  }
  CheckAgainstVTK(pd, 1500, "bunny");
}

TEST(LocatorQueries, ClosestPointStripsAndQuadsMatchVTK)
{
  auto sphere = StripSphere();
  ASSERT_GT(sphere->GetNumberOfStrips(), 0);
  CheckAgainstVTK(sphere, 1500, "strip sphere");
  // Quads: VTK's locators on the same quads cut in two (cell i -> triangles 2i, 2i+1).
  auto quads = QuadPlane();
  vtkNew<vtkTriangleFilter> cut;
  cut->SetInputData(quads);
  cut->Update();
  ASSERT_EQ(cut->GetOutput()->GetNumberOfCells(), 2 * quads->GetNumberOfCells());
  CheckAgainstVTK(quads, 1500, "quad plane", cut->GetOutput(), 2);
  // And on the quads themselves VTK's answer is never nearer than ours.
  const auto xs = QueryPoints(quads, 500, 9);
  vtkNew<vtkStaticCellLocator> onQuads;
  onQuads->SetDataSet(quads);
  onQuads->BuildLocator();
  auto loc = Ours(quads, vtkTriangleGridLocator::RECURSIVE_GRID);
  size_t nearer = 0;
  for (const auto& q : xs)
  {
    double x[3] = { q[0], q[1], q[2] }, cp[3], d2, d2Ref;
    vtkIdType id;
    int sub;
    loc->FindClosestPoint(x, cp, id, sub, d2);
    onQuads->FindClosestPoint(x, cp, id, sub, d2Ref);
    nearer += std::sqrt(d2Ref) < std::sqrt(d2) * (1 - 1e-9) ? 1 : 0;
  }
  EXPECT_EQ(nearer, 0u);
}

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

TEST(LocatorQueries, FindCell)
{
  auto pd = LoadIf(std::string(ART_SOURCE_DIR) + "/data/am_underworks.ply");
  ASSERT_TRUE(pd);
  CheckFindCell(pd, 1500);
  CheckFindCell(QuadPlane(), 600);
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
