#include "SurfaceTetrahedralizer.h"

#include "BisectionMesh.h"
#include "Error.h"
#include "LeastSquaresFit.h"
#include "MeanSpacing.h"
#include "Progress.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>

namespace art
{
namespace
{
struct Fitted
{
  std::vector<double> X;
  VoxelErrorReport Errors;
  std::vector<long long> Voxels; ///< per tet
};

// The trilinear interpolant of the voxels at continuous index ijk (clamped to the box).
double Sample(const VoxelVolume& volume, const double ijk[3])
{
  int i0[3];
  double f[3];
  for (int a = 0; a < 3; ++a)
  {
    const double u = std::clamp(ijk[a], 0.0, static_cast<double>(volume.Dims[a] - 1));
    i0[a] = std::min(static_cast<int>(u), std::max(volume.Dims[a] - 2, 0));
    f[a] = volume.Dims[a] > 1 ? u - i0[a] : 0.0;
  }
  double s = 0;
  for (int c = 0; c < 8; ++c)
  {
    const int d[3] = { c & 1, (c >> 1) & 1, (c >> 2) & 1 };
    long long idx = 0, stride = 1;
    double w = 1;
    for (int a = 0; a < 3; ++a)
    {
      idx += stride * std::min(i0[a] + d[a], volume.Dims[a] - 1);
      stride *= volume.Dims[a];
      w *= d[a] ? f[a] : 1 - f[a];
    }
    s += w * volume.Value(idx);
  }
  return s;
}

// The least-squares fit of the volume's voxels on the mesh, placed in the volume's frame.
Fitted Fit(const TetGenMesh& m, const VoxelVolume& volume, const std::string& file)
{
  const size_t nv = m.Points.size() / 3, nt = m.Tets.size() / 4;
  std::vector<LatticePoint> pts(nv);
  std::vector<double> start(nv); // the interpolant at each vertex: the regulariser's first anchor
  const double S = static_cast<double>(BisectionMesh::Scale);
  for (size_t v = 0; v < nv; ++v)
  {
    double ijk[3];
    volume.WorldToIndex(&m.Points[3 * v], ijk);
    pts[v] = { std::llround(ijk[0] * S), std::llround(ijk[1] * S), std::llround(ijk[2] * S) };
    start[v] = Sample(volume, ijk);
  }
  std::vector<std::array<int, 4>> tets(nt);
  for (size_t t = 0; t < nt; ++t)
  {
    tets[t] = { m.Tets[4 * t], m.Tets[4 * t + 1], m.Tets[4 * t + 2], m.Tets[4 * t + 3] };
  }
  BisectionMesh bm;
  bm.InitFromTets(std::move(pts), tets);
  LeastSquaresFit lsf(volume, 1e-3); // a light regulariser: TetGen's tets hold few voxels each
  std::vector<int> all(nt);
  std::iota(all.begin(), all.end(), 0);
  Fitted f;
  try
  {
    lsf.UpdateMoments(bm, all);
  }
  catch (const Error&)
  {
    throw Error("a tet of the mesh is flat once placed in the volume's voxels (a volume far larger than the surface?)",
      file);
  }
  f.Voxels.resize(nt);
  long long covered = 0;
  for (size_t t = 0; t < nt; ++t)
  {
    f.Voxels[t] = lsf.Moments(static_cast<int>(t)).Count;
    covered += f.Voxels[t];
  }
  if (covered == 0)
  {
    throw Error("no voxel of the volume lies inside the surface: are they in the same place (--frame)?", file);
  }
  // Tets smaller than a few voxels are regularised towards an anchor (at first the interpolant
  // at the vertices, which a vertex no voxel constrains keeps); each further solve anchors at
  // the fit before (iterated Tikhonov), converging to the least-squares fit where the voxels
  // determine it.
  f.X = start;
  const double still = 1e-9 * std::max(volume.Range[1] - volume.Range[0], 1e-300);
  for (int k = 0; k < 200; ++k)
  {
    const std::vector<double> before = f.X;
    lsf.Solve(bm, f.X, 1e-10);
    double moved = 0.0;
    for (size_t i = 0; i < before.size(); ++i)
    {
      moved = std::max(moved, std::fabs(f.X[i] - before[i]));
    }
    if (moved <= still)
    {
      break;
    }
  }
  // The errors over the voxels inside the mesh only: the mask is every voxel, the mean theirs.
  f.Errors = lsf.VoxelErrors(bm, f.X);
  f.Errors.Voxels = covered;
  double sse = 0;
  for (size_t t = 0; t < nt; ++t)
  {
    sse += f.Errors.TetRms[t] * f.Errors.TetRms[t] * static_cast<double>(f.Voxels[t]);
  }
  f.Errors.Rms = std::sqrt(sse / static_cast<double>(covered));
  return f;
}

// A volume bound that gives about `tets` tets, calibrated on TetGen's own counts.
TetGenMesh MeshToBudget(const TriangleSurface& s, double solid, long long tets, const SurfaceMeshOptions& o,
  std::vector<std::pair<long long, double>>& rounds)
{
  TetGenSettings g = o.TetGen;
  g.MaxVolume = -1;
  TetGenMesh coarsest = MeshSurface(s, g);
  rounds.emplace_back(coarsest.NumberOfTets(), std::numeric_limits<double>::quiet_NaN());
  if (coarsest.NumberOfTets() >= tets * (1.0 - o.BudgetTolerance))
  {
    return coarsest; // the surface alone asks for this many
  }
  double a = 3.0 * solid / tets; // TetGen's tets are about a third of the bound on average
  TetGenMesh best = coarsest;
  for (int k = 0; k < 5; ++k)
  {
    g.MaxVolume = a;
    TetGenMesh m = MeshSurface(s, g);
    rounds.emplace_back(m.NumberOfTets(), std::numeric_limits<double>::quiet_NaN());
    if (std::fabs(m.NumberOfTets() - tets) < std::fabs(best.NumberOfTets() - tets))
    {
      best = std::move(m);
    }
    if (std::fabs(best.NumberOfTets() - tets) <= o.BudgetTolerance * tets)
    {
      break;
    }
    a *= static_cast<double>(rounds.back().first) / static_cast<double>(tets);
  }
  return best;
}

// Refines the share of tets whose voxels the fit misses most (squared error summed).
TetGenMesh RefineWorst(const TetGenMesh& m, const Fitted& f, double fraction, const TetGenSettings& g)
{
  const size_t nt = m.Tets.size() / 4;
  std::vector<double> sse(nt);
  for (size_t t = 0; t < nt; ++t)
  {
    sse[t] = f.Errors.TetRms[t] * f.Errors.TetRms[t] * static_cast<double>(f.Voxels[t]);
  }
  std::vector<int> order(nt);
  std::iota(order.begin(), order.end(), 0);
  const size_t k = std::max<size_t>(1, static_cast<size_t>(fraction * nt));
  std::partial_sort(order.begin(), order.begin() + std::min(k, nt), order.end(),
    [&](int a, int b) { return sse[a] > sse[b]; });
  const std::vector<double> vol = TetVolumes(m);
  std::vector<double> bound(nt, -1.0);
  for (size_t i = 0; i < std::min(k, nt); ++i)
  {
    if (sse[order[i]] > 0)
    {
      bound[order[i]] = 0.25 * vol[order[i]];
    }
  }
  return RefineMesh(m, bound, g);
}

ReducedMesh Output(const TetGenMesh& m, const Fitted* f, const VoxelVolume* volume)
{
  ReducedMesh out;
  out.Points = m.Points;
  out.Tets = m.Tets;
  if (f && volume)
  {
    out.Values.assign(f->X.begin(), f->X.begin() + static_cast<std::ptrdiff_t>(m.Points.size() / 3));
    out.TetRms = f->Errors.TetRms;
    out.TetMax = f->Errors.TetMax;
    out.Rms = out.WeightedRms = f->Errors.Rms;
    out.Max = out.WeightedMax = f->Errors.Max;
    out.Range[0] = volume->Range[0];
    out.Range[1] = volume->Range[1];
    out.ScalarName = volume->Name;
    out.SourceSpacing = MeanVoxelSpacing(volume->Dims, volume->Spacing);
  }
  return out;
}
} // namespace

SurfaceMeshResult TetrahedralizeSurface(
  TriangleSurface surface, const SurfaceMeshOptions& o, const std::string& file, Progress* progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  SurfaceMeshResult res;
  res.Surface = CheckSurface(surface);
  if (!res.Surface.Valid())
  {
    throw Error(res.Surface.Problem(), file);
  }
  if (o.TargetTets <= 0 && o.MaxVolume <= 0 && !o.Volume)
  {
    throw Error("give a tet budget or a largest tet volume", file);
  }
  if (progress)
  {
    progress->Begin("tetrahedralize", 1.0);
  }
  try
  {
    const double solid = res.Surface.Volume;
    const bool refine = o.Volume && o.TargetTets > 0;
    TetGenMesh m;
    if (o.MaxVolume > 0 || o.TargetTets <= 0)
    {
      TetGenSettings g = o.TetGen;
      g.MaxVolume = o.MaxVolume;
      m = MeshSurface(surface, g);
      res.Rounds.emplace_back(m.NumberOfTets(), std::numeric_limits<double>::quiet_NaN());
    }
    else
    {
      // With values, a third of the budget is spent first; the rest goes where the fit is worst.
      m = MeshToBudget(surface, solid, refine ? std::max<long long>(o.TargetTets / 3, 4) : o.TargetTets, o, res.Rounds);
    }
    std::unique_ptr<Fitted> f;
    if (o.Volume)
    {
      f = std::make_unique<Fitted>(Fit(m, *o.Volume, file));
      res.Rounds.back().second = f->Errors.Rms;
    }
    for (int r = 0; refine && r < o.MaxRounds && m.NumberOfTets() < o.TargetTets * (1.0 - o.BudgetTolerance); ++r)
    {
      if (progress && progress->Cancelled())
      {
        throw Error("cancelled");
      }
      const double share = std::min(o.RefineFraction, (o.TargetTets - m.NumberOfTets()) / (3.0 * m.NumberOfTets()));
      m = RefineWorst(m, *f, std::max(share, 1e-3), o.TetGen);
      f = std::make_unique<Fitted>(Fit(m, *o.Volume, file));
      res.Rounds.emplace_back(m.NumberOfTets(), f->Errors.Rms);
      if (progress)
      {
        progress->Advance(1.0 / o.MaxRounds);
      }
    }
    res.Mesh = Output(m, f.get(), o.Volume);
    res.CoveredVoxels = f ? f->Errors.Voxels : 0;
    TetVolumes(m, &res.MeshVolume);
  }
  catch (const Error& e)
  {
    throw Error(e.problem(), e.file().empty() ? file : e.file());
  }
  res.Mesh.TargetTets = o.TargetTets;
  res.Mesh.RefinementLevels = static_cast<int>(res.Rounds.size());
  res.Mesh.BuildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (progress)
  {
    progress->End();
  }
  return res;
}
} // namespace art
