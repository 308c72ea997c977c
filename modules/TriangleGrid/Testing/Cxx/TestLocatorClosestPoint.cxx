// vtkTriangleGridLocator::FindClosestPoint against VTK's own locators on the same data: equal to
// vtkStaticCellLocator's and vtkCellLocator's (distance to 1e-9 relative, same cell unless two cells
// are equally near) for random points inside, near and far outside the surface, for every accelerator.
#include "LocatorTestUtil.h"

#include <vtkCellLocator.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangleFilter.h>

#include <gtest/gtest.h>

#include <cstdio>

using namespace arttest;

namespace
{
struct Stats
{
  size_t queries = 0, sameCell = 0, ties = 0;
  double maxRel = 0;
};

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

// One locator's FindClosestPoint against a VTK locator's on every point: same distance, same cell
// or an equally near one, same closest point.
// The references may come from a triangulated copy refPd of pd, whose triangles div * i .. div * i + div - 1
// are cell i of pd (vtkQuad::EvaluatePosition clamps parametric coordinates outside the quad, so
// VTK's own answer on quads is not the nearest point; on their triangles it is).
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

} // namespace

TEST(LocatorClosestPoint, ClosestPointUnderworksMatchesVTK)
{
  auto pd = LoadIf(std::string(ART_SOURCE_DIR) + "/data/am_underworks.ply");
  ASSERT_TRUE(pd);
  CheckAgainstVTK(pd, 3000, "am_underworks");
}

TEST(LocatorClosestPoint, ClosestPointBunnyMatchesVTK)
{
  auto pd = LoadIf(std::string(ART_SHARED_DATA) + "/bunny.ply");
  if (!pd)
  {
    GTEST_SKIP() << "no bunny.ply in " << ART_SHARED_DATA;
  }
  CheckAgainstVTK(pd, 1500, "bunny");
}

TEST(LocatorClosestPoint, ClosestPointStripsAndQuadsMatchVTK)
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

