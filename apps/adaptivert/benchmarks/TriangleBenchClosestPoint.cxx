// The closest-point table of `adaptivert bench triangles`: FindClosestPoint through
// vtkTriangleGridLocator against vtkStaticCellLocator and vtkCellLocator on the same points, with
// the distance error against brute force.
#ifdef ART_HAVE_TriangleGrid
#include "benchmarks/TriangleBench.h"

#include "ParallelTiles.h"

#include "vtkTriangleGridLocator.h"

#include <vtkCellLocator.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace trianglebench
{
namespace
{
// Query points as the tests draw them: a third uniform in the (slightly grown) box, a third near the
// surface (a random point of a random triangle moved up to 1% of the diagonal), a third 1-10
// diagonals away.
std::vector<art::Vec3> QueryPoints(const art::TriangleStore& st, size_t n)
{
  std::mt19937_64 g(17);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> nd;
  const art::Box3 b = st.Bounds();
  const double diag = b.Diagonal();
  std::vector<art::Vec3> xs(n);
  for (size_t i = 0; i < n; ++i)
  {
    art::Vec3 d(nd(g), nd(g), nd(g));
    d = d * (1.0 / (art::Length(d) + 1e-300));
    if (i % 3 == 0)
    {
      const art::Vec3 pad = b.Size() * 0.05;
      for (int a = 0; a < 3; ++a)
      {
        xs[i][a] = b.lo[a] - pad[a] + u(g) * (b.hi[a] - b.lo[a] + 2 * pad[a]);
      }
    }
    else if (i % 3 == 1)
    {
      const size_t t = static_cast<size_t>(u(g) * double(st.Size())) % st.Size();
      double w1 = u(g), w2 = u(g);
      if (w1 + w2 > 1)
      {
        w1 = 1 - w1, w2 = 1 - w2;
      }
      const art::TriangleRecord& r = st.Record(t);
      const art::Vec3 p0 = st.Point(r.v[0]), p1 = st.Point(r.v[1]), p2 = st.Point(r.v[2]);
      xs[i] = p0 + (p1 - p0) * w1 + (p2 - p0) * w2 + d * (0.01 * diag * u(g));
    }
    else
    {
      xs[i] = b.Center() + d * (diag * (1 + 9 * u(g)));
    }
  }
  return xs;
}

struct PointAnswer
{
  double d2 = -1;
  vtkIdType cell = -1;
};

// FindClosestPoint of `loc` on xs[0], xs[stride], ... (one thread: VTK's locators are timed that way).
void RunPoints(vtkAbstractCellLocator* loc, const std::vector<art::Vec3>& xs, size_t stride, std::vector<PointAnswer>* out)
{
  vtkNew<vtkGenericCell> cell;
  if (out)
  {
    out->clear();
  }
  for (size_t i = 0; i < xs.size(); i += stride)
  {
    const double x[3] = { xs[i].x, xs[i].y, xs[i].z };
    double cp[3], d2;
    vtkIdType id;
    int sub;
    loc->FindClosestPoint(x, cp, cell, id, sub, d2);
    if (out)
    {
      out->push_back({ d2, id });
    }
  }
}
} // namespace

void BenchClosestPoint(const Scene& s, size_t nPoints, int runs, std::vector<PointRow>& rows)
{
  const std::vector<art::Vec3> xs = QueryPoints(*s.store, nPoints);
  // The reference: our brute force (every triangle, exact in double) on a strided subset.
  const size_t refStride = std::max<size_t>(1, xs.size() / std::max<size_t>(1, std::min<size_t>(xs.size(),
                                                  s.store->Size() > 20000 ? 1000 : 5000)));
  std::vector<PointAnswer> ref;
  {
    vtkNew<vtkTriangleGridLocator> brute;
    brute->SetAcceleratorType(vtkTriangleGridLocator::BRUTE_FORCE);
    brute->SetDataSet(s.pd);
    brute->BuildLocator();
    RunPoints(brute, xs, refStride, &ref);
  }
  const double diag = s.store->Bounds().Diagonal();
  auto measure = [&](const std::string& name, vtkAbstractCellLocator* loc) {
    PointRow r;
    r.scene = s.name;
    r.engine = name;
    loc->SetDataSet(s.pd);
    const cli::BenchStats b = Time(std::min(runs, 3), [&] { loc->FreeSearchStructure(); loc->Modified(); loc->BuildLocator(); });
    r.buildMs = b.median * 1e3;
    // As many points as fit in about half a second per run (VTK's locators are slow on far points).
    const size_t probeStride = std::max<size_t>(1, xs.size() / 100);
    const auto t0 = Clock::now();
    RunPoints(loc, xs, probeStride, nullptr);
    const double per = Since(t0) / double((xs.size() + probeStride - 1) / probeStride);
    const size_t fit = static_cast<size_t>(0.5 / std::max(per, 1e-9));
    const size_t stride = std::max<size_t>(1, xs.size() / std::max<size_t>(fit, 300));
    r.points = (xs.size() + stride - 1) / stride;
    const cli::BenchStats t = Time(runs, [&] { RunPoints(loc, xs, stride, nullptr); });
    r.rate = { double(r.points) / t.median, double(r.points) / t.hi, double(r.points) / t.lo };
    std::vector<PointAnswer> got;
    RunPoints(loc, xs, refStride, &got);
    r.maxRelError = 0;
    r.refPoints = ref.size();
    for (size_t i = 0; i < ref.size(); ++i)
    {
      const double d = std::sqrt(std::max(got[i].d2, 0.0)), dr = std::sqrt(ref[i].d2);
      r.maxRelError = std::max(r.maxRelError, std::fabs(d - dr) / std::max(dr, 1e-9 * diag));
      r.sameCell += got[i].cell == ref[i].cell;
    }
    char buf[128];
    std::snprintf(buf, sizeof buf, "1 thread, %zu of %zu points", r.points, xs.size());
    r.note = buf;
    rows.push_back(r);
    std::fprintf(stderr, "  closest point %-32s build %8.1f ms  %10.0f queries/s  max rel. error %.2g\n",
      name.c_str(), r.buildMs, r.rate.median, r.maxRelError);
  };
  art::SetThreadCount(1);
  for (int kind : { vtkTriangleGridLocator::UNIFORM_GRID, vtkTriangleGridLocator::RECURSIVE_GRID,
         vtkTriangleGridLocator::OCTREE })
  {
    vtkNew<vtkTriangleGridLocator> loc;
    loc->SetAcceleratorType(kind);
    static const char* names[] = { "", "vtkTriangleGridLocator uniform grid", "vtkTriangleGridLocator R (default)",
      "vtkTriangleGridLocator O" };
    measure(names[kind], loc);
  }
  vtkNew<vtkStaticCellLocator> st;
  measure("VTK vtkStaticCellLocator", st);
  vtkNew<vtkCellLocator> cl;
  measure("VTK vtkCellLocator", cl);
}
} // namespace trianglebench
#endif // ART_HAVE_TriangleGrid
