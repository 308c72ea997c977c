#include "AnisotropicAdaptation.h"

#include "BisectionMesh.h"
#include "AvailableMemory.h"
#include "Error.h"
#include "LeastSquaresFit.h"
#include "MmgRemesher.h"
#include "OpacityImportance.h"
#include "ParallelTiles.h"
#include "Progress.h"
#include "ReducedLevel.h"
#include "VertexRelocator.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numeric>

namespace art
{
namespace
{
using i128 = __int128;
constexpr double TetsPerVertexInside = 6.3; // tets per vertex of a large mesh, boundary aside

i128 Orient(const LatticePoint& a, const LatticePoint& b, const LatticePoint& c, const LatticePoint& d)
{
  const i128 u[3] = { b.x - a.x, b.y - a.y, b.z - a.z };
  const i128 v[3] = { c.x - a.x, c.y - a.y, c.z - a.z };
  const i128 w[3] = { d.x - a.x, d.y - a.y, d.z - a.z };
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

// The voxels trilinearly at p (voxel index coordinates): the fit's starting values.
double Trilinear(const VoxelVolume& v, const double p[3])
{
  int i0[3];
  double f[3];
  for (int d = 0; d < 3; ++d)
  {
    const double c = std::min<double>(v.Dims[d] - 1, std::max(0.0, p[d]));
    i0[d] = std::min(std::max(0, v.Dims[d] - 2), static_cast<int>(std::floor(c)));
    f[d] = c - i0[d];
  }
  double s = 0;
  for (int k = 0; k < 8; ++k)
  {
    const int o[3] = { k & 1, (k >> 1) & 1, (k >> 2) & 1 };
    const double w = (o[0] ? f[0] : 1 - f[0]) * (o[1] ? f[1] : 1 - f[1]) * (o[2] ? f[2] : 1 - f[2]);
    if (w == 0)
    {
      continue;
    }
    const int c[3] = { std::min(v.Dims[0] - 1, i0[0] + o[0]), std::min(v.Dims[1] - 1, i0[1] + o[1]),
      std::min(v.Dims[2] - 1, i0[2] + o[2]) };
    s += w * v.Value(c[0] + static_cast<long long>(v.Dims[0]) * (c[1] + static_cast<long long>(v.Dims[1]) * c[2]));
  }
  return s;
}

double TetVolume(const double* p0, const double* p1, const double* p2, const double* p3)
{
  double e[3][3];
  for (int d = 0; d < 3; ++d)
  {
    e[0][d] = p1[d] - p0[d];
    e[1][d] = p2[d] - p0[d];
    e[2][d] = p3[d] - p0[d];
  }
  return std::fabs(e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
    6.0;
}

double Seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The transfer function's weight of each voxel at its own value: where opacity changes, the
// metric asks for shorter edges.
std::vector<float> MetricWeights(const VoxelVolume& volume, const OpacityImportance& imp, double exponent)
{
  const long long n = volume.NumberOfVoxels();
  std::vector<float> w(static_cast<size_t>(n));
  ForEachRange(n, 1 << 14, [&](long long i0, long long i1, Counters&) {
    for (long long i = i0; i < i1; ++i)
    {
      const double f = volume.Value(i);
      w[static_cast<size_t>(i)] = static_cast<float>(std::pow(imp.Weight(i, f, f), exponent));
    }
  });
  return w;
}
} // namespace

AnisotropicAdaptation::AnisotropicAdaptation(const VoxelVolume& volume, const ReducerOptions& options,
  const OpacityImportance* importance, Progress* progress, std::function<void(double)> share)
  : Volume(volume)
  , Opt(options)
  , Importance(importance)
  , Prog(progress)
{
  std::string why;
  if (!MmgRemesher::Available(&why))
  {
    throw Error("anisotropic refinement needs MMG (libmmg3d 5.8): " + why +
        "; cmake/setup.sh installs it beside AdaptiveRT's libraries, or set ART_MMG_LIBRARY to its path",
      volume.File);
  }
  std::vector<float> weights;
  if (Importance)
  {
    weights = MetricWeights(volume, *Importance, Opt.MetricWeightExponent);
  }
  Metric = std::make_unique<HessianMetric>(volume, Opt.Metric, Importance ? &weights : nullptr, share);
}

AnisotropicAdaptation::~AnisotropicAdaptation() = default;

AnisotropicAdaptation::Mesh AnisotropicAdaptation::UniformMesh(double vertices) const
{
  // A Kuhn grid of about `vertices` vertices, its boxes about cubic in voxels.
  double cells = 1;
  for (int d = 0; d < 3; ++d)
  {
    cells *= Volume.Dims[d] - 1;
  }
  const double h = std::cbrt(cells / std::max(1.0, vertices));
  int cubes[3];
  for (int d = 0; d < 3; ++d)
  {
    cubes[d] = std::max(1, std::min(Volume.Dims[d] - 1, static_cast<int>(std::lround((Volume.Dims[d] - 1) / h))));
  }
  BisectionMesh kuhn;
  kuhn.InitKuhn(Volume.Dims, cubes);
  Mesh m;
  const double S = static_cast<double>(BisectionMesh::Scale);
  m.Points.resize(3 * static_cast<size_t>(kuhn.NumberOfVertices()));
  for (int v = 0; v < kuhn.NumberOfVertices(); ++v)
  {
    for (int d = 0; d < 3; ++d)
    {
      m.Points[3 * static_cast<size_t>(v) + d] = kuhn.Vertex(v)[d] / S;
    }
  }
  m.Tets.resize(4 * static_cast<size_t>(kuhn.NumberOfTets()));
  for (int t = 0; t < kuhn.NumberOfTets(); ++t)
  {
    std::copy(kuhn.Tet(t).begin(), kuhn.Tet(t).end(), m.Tets.begin() + 4 * static_cast<size_t>(t));
  }
  return m;
}

double AnisotropicAdaptation::MeshComplexity(
  const Mesh& m, const std::vector<double>& metric6, const std::vector<double>& volume) const
{
  // sqrt(det M) over each tet by the four-point Gauss rule, M interpolated linearly between its
  // vertices as MMG interpolates it; summed in tet order (the same for any thread count).
  const long long nt = static_cast<long long>(m.Tets.size() / 4);
  const long long grain = 4096, chunks = (nt + grain - 1) / grain;
  std::vector<double> part(static_cast<size_t>(chunks), 0.0);
  ForEachRange(chunks, 1, [&](long long c0, long long c1, Counters&) {
    const double a = 0.5854101966249685, b = 0.1381966011250105;
    for (long long c = c0; c < c1; ++c)
    {
      double sum = 0;
      for (long long t = c * grain, e = std::min(nt, t + grain); t < e; ++t)
      {
        const int* q = &m.Tets[4 * static_cast<size_t>(t)];
        double s = 0;
        for (int g = 0; g < 4; ++g)
        {
          double x[6];
          for (int i = 0; i < 6; ++i)
          {
            x[i] = 0;
            for (int k = 0; k < 4; ++k)
            {
              x[i] += (k == g ? a : b) * metric6[6 * static_cast<size_t>(q[k]) + i];
            }
          }
          const double det =
            x[0] * (x[3] * x[5] - x[4] * x[4]) - x[1] * (x[1] * x[5] - x[4] * x[2]) + x[2] * (x[1] * x[4] - x[3] * x[2]);
          s += std::sqrt(std::max(0.0, det));
        }
        sum += volume[static_cast<size_t>(t)] * 0.25 * s;
      }
      part[static_cast<size_t>(c)] = sum;
    }
  });
  return std::accumulate(part.begin(), part.end(), 0.0);
}

double AnisotropicAdaptation::VerticesFor(long long tets) const
{
  // tets = a V - b V^(2/3) (the boundary's vertices have fewer tets), solved by Newton.
  double v = tets / 5.6;
  for (int it = 0; it < 30; ++it)
  {
    const double c = std::cbrt(v);
    const double f = TetsPerVertexInside * v - BoundaryTets * c * c - tets;
    const double df = TetsPerVertexInside - BoundaryTets * 2.0 / 3.0 / c;
    v = std::max(4.0, v - f / std::max(df, 1.0));
  }
  return v;
}

AnisotropicAdaptation::Mesh AnisotropicAdaptation::Remesh(const Mesh& start, long long tets, double complexity)
{
  const auto t0 = std::chrono::steady_clock::now();
  // A budget coarser than the longest edge allows gets edges up to twice a uniform mesh's of
  // its size: with the edges capped at 24 voxels, 500 tets of the 128 CT came out as 967.
  double cells = 1;
  for (int d = 0; d < 3; ++d)
  {
    cells *= std::max(1, Volume.Dims[d] - 1);
  }
  Metric->SetHmax(std::max(Opt.Metric.Hmax, 2.0 * std::cbrt(cells / VerticesFor(tets))));
  const long long nv = static_cast<long long>(start.Points.size() / 3), nt = static_cast<long long>(start.Tets.size() / 4);
  std::vector<HessianMetric::Local> local(static_cast<size_t>(nv));
  ForEachRange(nv, 1024, [&](long long v0, long long v1, Counters&) {
    for (long long v = v0; v < v1; ++v)
    {
      local[static_cast<size_t>(v)] = Metric->Decompose(&start.Points[3 * static_cast<size_t>(v)]);
    }
  });
  std::vector<double> volume(static_cast<size_t>(nt));
  for (long long t = 0; t < nt; ++t)
  {
    const int* q = &start.Tets[4 * static_cast<size_t>(t)];
    volume[static_cast<size_t>(t)] = TetVolume(&start.Points[3 * static_cast<size_t>(q[0])],
      &start.Points[3 * static_cast<size_t>(q[1])], &start.Points[3 * static_cast<size_t>(q[2])],
      &start.Points[3 * static_cast<size_t>(q[3])]);
  }
  // The scale at which the metric MMG sees, interpolated over the start mesh, has the complexity
  // the calibration says gives `vertices`: bisection on its logarithm.
  MetricMesh in;
  in.Points = start.Points;
  in.Tets = start.Tets;
  in.Metric.resize(6 * static_cast<size_t>(nv));
  auto metricAt = [&](double scale) {
    ForEachRange(nv, 4096, [&](long long v0, long long v1, Counters&) {
      for (long long v = v0; v < v1; ++v)
      {
        Metric->Compose(local[static_cast<size_t>(v)], scale, &in.Metric[6 * static_cast<size_t>(v)]);
      }
    });
  };
  double lo = -60, hi = 60;
  while (hi - lo > 1e-4)
  {
    const double mid = 0.5 * (lo + hi);
    metricAt(std::exp(mid));
    (MeshComplexity(start, in.Metric, volume) < complexity ? lo : hi) = mid;
  }
  metricAt(std::exp(0.5 * (lo + hi)));
  const double boxLo[3] = { 0, 0, 0 };
  const double boxHi[3] = { Volume.Dims[0] - 1.0, Volume.Dims[1] - 1.0, Volume.Dims[2] - 1.0 };
  RemeshOptions ro;
  ro.Hmin = Metric->Options().Hmin;
  ro.Hmax = Metric->Options().Hmax;
  ro.NoMove = !Opt.RemeshMovesVertices;
  ro.ExpectedVertices = complexity * VerticesPerComplexity;
  Mesh out;
  MmgRemesher::Remesh(in, boxLo, boxHi, ro, out.Points, out.Tets);

  AdaptationRound r;
  r.TargetTets = tets;
  r.Complexity = complexity;
  r.Vertices = static_cast<long long>(out.Points.size() / 3);
  r.Tets = static_cast<long long>(out.Tets.size() / 4);
  r.Seconds = Seconds(t0);
  History.push_back(r);
  return out;
}

void AnisotropicAdaptation::Calibrate(const AdaptationRound& r)
{
  // The next level's first ask, from this remeshing.
  VerticesPerComplexity = r.Vertices / r.Complexity;
  const double c = std::cbrt(double(r.Vertices));
  BoundaryTets = std::max(0.0, (TetsPerVertexInside * r.Vertices - r.Tets) / (c * c));
}

int AnisotropicAdaptation::Relocate(
  BisectionMesh& mesh, LeastSquaresFit& fit, const std::vector<int>& all, std::vector<double>& x) const
{
  // The metric aligns the tets with the voxels' curvature; relocation then moves each vertex to
  // where its star fits the voxels best (VertexRelocator), as on the lattice. Thin tets are the
  // point here, so a move may leave a tet at a twentieth of the regular quality where the
  // lattice keeps a fifth.
  RelocationOptions ro;
  ro.Sweeps = Opt.RelocateSweeps;
  ro.QualityFloor = std::min(Opt.RelocateQualityFloor, 0.05);
  ro.MeasureSse = false;
  VertexRelocator::Relocate(mesh, Volume, x, ro, Importance, Prog); // moves vertices, keeps the tets
  fit.UpdateMoments(mesh, all);
  return fit.Solve(mesh, x, Opt.SolverTolerance);
}

ReducedMesh AnisotropicAdaptation::Fit(const Mesh& m, long long tets) const
{
  const size_t nv = m.Points.size() / 3, nt = m.Tets.size() / 4;
  std::vector<LatticePoint> lattice(nv);
  const double S = static_cast<double>(BisectionMesh::Scale);
  for (size_t v = 0; v < nv; ++v)
  {
    lattice[v] = { std::llround(m.Points[3 * v] * S), std::llround(m.Points[3 * v + 1] * S),
      std::llround(m.Points[3 * v + 2] * S) };
  }
  std::vector<std::array<int, 4>> tv(nt);
  for (size_t t = 0; t < nt; ++t)
  {
    std::array<int, 4> q = { m.Tets[4 * t], m.Tets[4 * t + 1], m.Tets[4 * t + 2], m.Tets[4 * t + 3] };
    const i128 o = Orient(lattice[q[0]], lattice[q[1]], lattice[q[2]], lattice[q[3]]);
    if (o == 0)
    {
      throw Error("internal: the remeshed mesh has a flat tetrahedron on the voxel lattice");
    }
    if (o < 0)
    {
      std::swap(q[2], q[3]);
    }
    tv[t] = q;
  }
  // Starting values and the anchor of sparse tets: the voxels at the vertices, where the
  // lattice puts them (a linear field stays exact).
  std::vector<double> x(nv);
  for (size_t v = 0; v < nv; ++v)
  {
    const double p[3] = { lattice[v].x / S, lattice[v].y / S, lattice[v].z / S };
    x[v] = Trilinear(Volume, p);
  }
  BisectionMesh mesh;
  mesh.InitFromTets(std::move(lattice), tv);
  // The values are the plain L2 fit even when a transfer function weighs the reduction: its
  // weights have already put the vertices where opacity changes (the metric), and a fit
  // weighted again drew worse on every mesh measured, more so the finer the mesh.
  LeastSquaresFit fit(Volume, Opt.Regularization, nullptr);
  std::vector<int> all(nt);
  std::iota(all.begin(), all.end(), 0);
  fit.UpdateMoments(mesh, all);
  int iterations = fit.Solve(mesh, x, Opt.SolverTolerance);
  const bool relocate = Opt.RelocateVertices && Volume.NumberOfVoxels() >= Opt.RelocateVoxelsPerTet * static_cast<double>(nt);
  if (relocate)
  {
    iterations += Relocate(mesh, fit, all, x);
  }
  const std::vector<double> y =
    OutputValues(mesh, fit, x, Opt.ClampToVoxels, Opt.CapOpacity ? Importance : nullptr);
  // The errors are judged as the reduction is weighted.
  const LeastSquaresFit judge(Volume, Opt.Regularization, Importance);
  ReducedMesh out = Snapshot(Volume, mesh, y, judge.VoxelErrors(mesh, y));
  out.TargetTets = tets;
  out.SolverIterations = iterations;
  out.RefinementLevels = static_cast<int>(History.size());
  out.Weighted = Importance != nullptr;
  out.Relocated = relocate;
  return out;
}

AnisotropicAdaptation::Mesh AnisotropicAdaptation::Converge(
  const Mesh& start, long long tets, const std::function<void(double)>& done)
{
  // Remeshings of the same start until the count is within the tolerance: the tet count grows
  // with the complexity asked, but not smoothly on small meshes (the box's faces and the
  // longest edges set a floor, and MMG's collapses there move the count by a third at once).
  // Once tries fall on both sides of the budget the next ask halves the bracket (in log);
  // before, it follows the count's response seen so far. Small meshes are cheap: more tries.
  const int tries = 1 + std::max(0, Opt.AdaptationRetries) * (tets < 20000 ? 5 : 1);
  double ask = VerticesFor(tets) / VerticesPerComplexity;
  double below = 0, above = 0; // the closest asks that gave too few and too many tets
  double lastAsk = 0, lastTets = 0;
  Mesh best;
  size_t bestRound = 0;
  for (int r = 0; r < tries; ++r)
  {
    if (Prog && Prog->Cancelled())
    {
      throw Error("cancelled");
    }
    Mesh m = Remesh(start, tets, ask);
    const long long nt = static_cast<long long>(m.Tets.size() / 4);
    if (best.Tets.empty() || std::llabs(nt - tets) < std::llabs(static_cast<long long>(best.Tets.size() / 4) - tets))
    {
      best = std::move(m);
      bestRound = History.size() - 1;
    }
    if (done)
    {
      done(0.8 * (r + 1) / tries);
    }
    if (std::fabs(double(nt - tets)) <= Opt.BudgetTolerance * tets)
    {
      break;
    }
    if (nt < tets)
    {
      below = std::max(below, ask);
    }
    else
    {
      above = above > 0 ? std::min(above, ask) : ask;
    }
    double next;
    if (below > 0 && above > 0)
    {
      next = std::sqrt(below * above);
    }
    else
    {
      // The count's response to the ask so far (1: proportional), kept within [0.3, 1.5].
      double slope = 1.0;
      if (lastAsk > 0 && lastAsk != ask && lastTets > 0)
      {
        slope = std::min(1.5, std::max(0.3, std::log(nt / lastTets) / std::log(ask / lastAsk)));
      }
      next = ask * std::pow(double(tets) / nt, 1.0 / slope);
    }
    lastAsk = ask;
    lastTets = double(nt);
    ask = next;
  }
  Calibrate(History[bestRound]);
  return best;
}

ReducedMesh AnisotropicAdaptation::Adapt(long long tets, const std::function<void(double)>& done)
{
  // A large first level is calibrated on a remeshing an eighth its size first.
  if (History.empty() && tets >= 40000)
  {
    const long long proxy = tets / 8;
    Remesh(UniformMesh(VerticesFor(proxy)), proxy, VerticesFor(proxy) / VerticesPerComplexity);
    Calibrate(History.back());
  }
  const Mesh best = Converge(UniformMesh(VerticesFor(tets)), tets, done);
  ReducedMesh out = Fit(best, tets);
  if (done)
  {
    done(1.0);
  }
  return out;
}

namespace
{
// The error an error bound is on: RMS or max, weighted when the reduction is.
double BoundedError(const ReducedMesh& m, const ReductionPlan& plan)
{
  return plan.MaxMetric ? (m.Weighted ? m.WeightedMax : m.Max) : (m.Weighted ? m.WeightedRms : m.Rms);
}
} // namespace

std::vector<ReducedMesh> ReduceAnisotropic(const VoxelVolume& volume, const ReducerOptions& options,
  const ReductionPlan& plan, Progress* progress, const std::function<void(const ReducedMesh&)>& onLevel)
{
  const TetReducer reducer(options);
  if (progress)
  {
    progress->Begin("reduce", 1.0);
  }
  double reported = 0;
  auto advanceTo = [&](double f) {
    if (progress && f > reported)
    {
      progress->Advance(f - reported);
      reported = f;
    }
  };
  std::unique_ptr<OpacityImportance> importance;
  if (!options.ScalarOpacity.empty())
  {
    importance = std::make_unique<OpacityImportance>(options.ScalarOpacity);
    importance->SetIsoValues(options.IsoValues);
    importance->Prepare(volume, options.ImportanceFloor, options.ImportanceRadius,
      [&](double f) { advanceTo(0.05 * f); });
  }
  AnisotropicAdaptation adaptation(
    volume, options, importance.get(), progress, [&](double f) { advanceTo(0.05 + 0.1 * f); });
  // The levels share the rest of the bar by their size (a remeshing's time grows with its tets).
  const double total = std::accumulate(plan.Budgets.begin(), plan.Budgets.end(), 0.0);
  double before = 0;
  std::vector<ReducedMesh> out;
  auto finish = [&](ReducedMesh m, long long budget) {
    m.TargetTets = budget;
    m.TargetError = plan.ErrorBound;
    m.BuildSeconds = plan.Elapsed();
    m.Refinement = "anisotropic";
    m.Nested = false;
    if (budget > 0)
    {
      const double asked = double(std::min(budget, plan.Cap));
      m.TargetReached = m.TargetReached && std::fabs(m.NumberOfTets() - asked) <= options.BudgetTolerance * asked;
    }
    if (onLevel)
    {
      onLevel(m);
    }
    out.push_back(std::move(m));
  };
  for (long long b : plan.Budgets)
  {
    const long long tets = std::min(b, plan.Cap);
    const double share = total > 0 ? b / total : 1.0;
    ReducedMesh m = adaptation.Adapt(tets, [&](double f) {
      advanceTo(0.15 + (plan.HaveError && options.TargetTets <= 0 ? 0.4 : 0.85) * (before + share * f));
    });
    before += share;
    const bool met = plan.HaveError && BoundedError(m, plan) <= plan.ErrorBound;
    finish(std::move(m), b);
    if (met)
    {
      break;
    }
  }
  const bool metAlready = !out.empty() && plan.HaveError && BoundedError(out.back(), plan) <= plan.ErrorBound;
  if (plan.HaveError && options.TargetTets <= 0 && !metAlready)
  {
    // An error bound alone: the budget grows until the error is met, up to one tet per voxel.
    long long tets = out.empty() ? std::max<long long>(2000, volume.NumberOfVoxels() / 1000) : out.back().NumberOfTets();
    double error = out.empty() ? -1 : BoundedError(out.back(), plan);
    double first = error;
    for (int step = 0;; ++step)
    {
      if (error > 0)
      {
        const double grow = std::min(8.0, std::max(1.5, 1.2 * std::pow(error / plan.ErrorBound, 1.5)));
        tets = std::min(plan.Cap, static_cast<long long>(std::ceil(tets * grow)));
        reducer.CheckGrowth(volume, out.empty() ? 0 : out.back().NumberOfTets(), tets, AvailableMemoryBytes());
      }
      ReducedMesh m = adaptation.Adapt(tets);
      error = BoundedError(m, plan);
      first = first < 0 ? error : first;
      const bool met = error <= plan.ErrorBound;
      if (met || tets >= plan.Cap || step >= 12)
      {
        m.TargetReached = met;
        finish(std::move(m), 0);
        break;
      }
      if (first > plan.ErrorBound && plan.ErrorBound > 0)
      {
        advanceTo(0.55 + 0.4 * std::log(first / error) / std::log(first / plan.ErrorBound));
      }
    }
  }
  if (progress)
  {
    progress->End();
  }
  return out;
}
} // namespace art
