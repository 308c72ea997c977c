#include "RegionReducer.h"

#include "AvailableMemory.h"
#include "BisectionMesh.h"
#include "Error.h"
#include "LeastSquaresFit.h"
#include "MeanSpacing.h"
#include "Progress.h"
#include "ReducedLevel.h"
#include "RegionSizing.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace art
{
namespace
{
double Since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A mesher's mesh on the reducer's lattice (voxel index coordinates times 2^16, as the fit's
// voxel raster wants them), positively oriented there.
struct LatticeMesh
{
  std::vector<LatticePoint> Points;
  std::vector<std::array<int, 4>> Tets;
  std::vector<int> Subdomain;
  std::vector<double> Scaled; ///< the points again in scaled index space, for the size field
};

LatticeMesh ToLattice(const ImageDomainMesh& dm, const double s[3], const std::string& file)
{
  LatticeMesh m;
  const size_t nv = dm.Points.size() / 3, nt = dm.Tets.size() / 4;
  const double S = static_cast<double>(BisectionMesh::Scale);
  m.Points.resize(nv);
  m.Scaled.resize(3 * nv);
  for (size_t v = 0; v < nv; ++v)
  {
    int64_t q[3];
    for (int a = 0; a < 3; ++a)
    {
      q[a] = std::llround(dm.Points[3 * v + a] / s[a] * S);
      m.Scaled[3 * v + a] = static_cast<double>(q[a]) / S * s[a];
    }
    m.Points[v] = { q[0], q[1], q[2] };
  }
  m.Tets.resize(nt);
  long long flat = 0;
  using i128 = __int128;
  for (size_t t = 0; t < nt; ++t)
  {
    std::array<int, 4> c = { dm.Tets[4 * t], dm.Tets[4 * t + 1], dm.Tets[4 * t + 2], dm.Tets[4 * t + 3] };
    const LatticePoint &a = m.Points[c[0]], &b = m.Points[c[1]], &d = m.Points[c[2]], &e = m.Points[c[3]];
    const i128 u[3] = { b.x - a.x, b.y - a.y, b.z - a.z }, v[3] = { d.x - a.x, d.y - a.y, d.z - a.z },
               w[3] = { e.x - a.x, e.y - a.y, e.z - a.z };
    const i128 six = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
      u[2] * (v[0] * w[1] - v[1] * w[0]);
    flat += six == 0 ? 1 : 0;
    if (six < 0)
    {
      std::swap(c[1], c[2]);
    }
    m.Tets[t] = c;
  }
  if (flat > 0)
  {
    throw Error("internal: the region's mesh has " + std::to_string(flat) + " tets with no volume", file);
  }
  m.Subdomain = dm.Subdomain;
  return m;
}

// The voxel values CGAL meshes: islands dropped from the region are moved out of its range.
std::vector<float> GrayForMesher(const VoxelVolume& v, const RegionMask& mask, double lo, double hi)
{
  const long long n = v.NumberOfVoxels();
  std::vector<float> g(static_cast<size_t>(n));
  const float out = static_cast<float>(lo - std::max(1.0, hi - lo));
  for (long long i = 0; i < n; ++i)
  {
    const double x = v.Value(i);
    g[i] = !mask.Inside[i] && x >= lo && x <= hi ? out : static_cast<float>(x);
  }
  return g;
}

// Weights that smooth a label map's surfaces (Stalling, Zoeckler & Hege 1998, as CGAL's
// generate_label_weights makes them): per voxel, 255 times the largest Gaussian-blurred indicator
// of any label (the background's too). Each label is blurred within its box only.
std::vector<uint8_t> LabelWeights(const RegionMask& mask, const int d[3], double sigma)
{
  const long long n = static_cast<long long>(d[0]) * d[1] * d[2];
  const int r = std::max(1, static_cast<int>(std::ceil(3 * sigma)));
  std::vector<double> kernel(2 * r + 1);
  double ks = 0;
  for (int k = -r; k <= r; ++k)
  {
    ks += kernel[k + r] = std::exp(-0.5 * k * k / (sigma * sigma));
  }
  for (double& k : kernel)
  {
    k /= ks;
  }
  std::vector<float> best(static_cast<size_t>(n), 0.f);
  const int slots = static_cast<int>(mask.Labels.size()) + 1;
  for (int s = 0; s < slots; ++s)
  {
    int lo[3] = { d[0], d[1], d[2] }, hi[3] = { -1, -1, -1 };
    for (int k = 0; k < d[2]; ++k)
      for (int j = 0; j < d[1]; ++j)
        for (int i = 0; i < d[0]; ++i)
        {
          if (mask.Slot[i + static_cast<size_t>(d[0]) * (j + static_cast<size_t>(d[1]) * k)] == s)
          {
            const int p[3] = { i, j, k };
            for (int a = 0; a < 3; ++a)
            {
              lo[a] = std::min(lo[a], p[a]);
              hi[a] = std::max(hi[a], p[a]);
            }
          }
        }
    if (hi[0] < 0)
    {
      continue;
    }
    int b[3];
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::max(0, lo[a] - r);
      hi[a] = std::min(d[a] - 1, hi[a] + r);
      b[a] = hi[a] - lo[a] + 1;
    }
    const size_t bn = static_cast<size_t>(b[0]) * b[1] * b[2];
    std::vector<float> f(bn), g(bn);
    for (int k = 0; k < b[2]; ++k)
      for (int j = 0; j < b[1]; ++j)
        for (int i = 0; i < b[0]; ++i)
        {
          const size_t src = (lo[0] + i) + static_cast<size_t>(d[0]) * ((lo[1] + j) + static_cast<size_t>(d[1]) * (lo[2] + k));
          f[i + static_cast<size_t>(b[0]) * (j + static_cast<size_t>(b[1]) * k)] = mask.Slot[src] == s ? 1.f : 0.f;
        }
    const size_t stride[3] = { 1, static_cast<size_t>(b[0]), static_cast<size_t>(b[0]) * b[1] };
    for (int a = 0; a < 3; ++a)
    {
      for (size_t idx = 0; idx < bn; ++idx)
      {
        const int c = static_cast<int>((idx / stride[a]) % b[a]);
        double sum = 0;
        for (int k = -r; k <= r; ++k)
        {
          const int q = std::clamp(c + k, 0, b[a] - 1);
          sum += kernel[k + r] * f[idx + (static_cast<long long>(q) - c) * static_cast<long long>(stride[a])];
        }
        g[idx] = static_cast<float>(sum);
      }
      f.swap(g);
    }
    for (int k = 0; k < b[2]; ++k)
      for (int j = 0; j < b[1]; ++j)
        for (int i = 0; i < b[0]; ++i)
        {
          const size_t dst = (lo[0] + i) + static_cast<size_t>(d[0]) * ((lo[1] + j) + static_cast<size_t>(d[1]) * (lo[2] + k));
          best[dst] = std::max(best[dst], f[i + static_cast<size_t>(b[0]) * (j + static_cast<size_t>(b[1]) * k)]);
        }
  }
  std::vector<uint8_t> w(static_cast<size_t>(n));
  for (long long i = 0; i < n; ++i)
  {
    w[i] = static_cast<uint8_t>(std::lround(255.0 * std::clamp(best[i], 0.f, 1.f)));
  }
  return w;
}

// One meshing and its fit.
struct Candidate
{
  LatticeMesh Mesh;
  std::vector<double> X;
  VoxelErrorReport Errors;
  std::vector<long long> TetVoxels;
  int Iterations = 0;
};

// The values at each vertex, interpolated trilinearly from the region's voxels among the eight
// around it (all eight when none is inside): where the fit's regulariser anchors a tet that holds
// few voxels, as many of a region mesher's tets do. Exact on a linear field, and near the data
// where a single mean for the whole region is not.
std::vector<double> VertexAnchors(const VoxelVolume& values, const RegionMask& mask, const LatticeMesh& mesh)
{
  const double S = static_cast<double>(BisectionMesh::Scale);
  const int* d = values.Dims;
  std::vector<double> x(mesh.Points.size());
  for (size_t v = 0; v < x.size(); ++v)
  {
    const LatticePoint& p = mesh.Points[v];
    const double q[3] = { p.x / S, p.y / S, p.z / S };
    int i0[3];
    double f[3];
    for (int a = 0; a < 3; ++a)
    {
      const double c = std::clamp(q[a], 0.0, static_cast<double>(d[a] - 1));
      i0[a] = std::min(static_cast<int>(std::floor(c)), std::max(d[a] - 2, 0));
      f[a] = d[a] > 1 ? c - i0[a] : 0.0;
    }
    double sum[2] = { 0, 0 }, weight[2] = { 0, 0 }; // [0] inside the region, [1] all eight
    for (int corner = 0; corner < 8; ++corner)
    {
      long long idx = 0;
      double w = 1;
      for (int a = 2; a >= 0; --a)
      {
        const int up = (corner >> a) & 1;
        const int i = std::min(i0[a] + up, d[a] - 1);
        idx = idx * d[a] + i;
        w *= up ? f[a] : 1.0 - f[a];
      }
      const double value = values.Value(idx);
      sum[1] += w * value, weight[1] += w;
      if (mask.Inside[static_cast<size_t>(idx)])
      {
        sum[0] += w * value, weight[0] += w;
      }
    }
    x[v] = weight[0] > 1e-9 ? sum[0] / weight[0] : sum[1] / weight[1];
  }
  return x;
}

void FitCandidate(const VoxelVolume& values, const RegionMask& mask, const RegionOptions& opt, bool fit, Candidate& c)
{
  BisectionMesh bm;
  bm.InitFromTets(c.Mesh.Points, c.Mesh.Tets);
  LeastSquaresFit lsf(values, opt.Regularization);
  lsf.SetMask(&mask.Inside);
  std::vector<int> all(c.Mesh.Tets.size());
  for (size_t t = 0; t < all.size(); ++t)
  {
    all[t] = static_cast<int>(t);
  }
  lsf.UpdateMoments(bm, all);
  c.TetVoxels.resize(all.size());
  for (size_t t = 0; t < all.size(); ++t)
  {
    c.TetVoxels[t] = lsf.Moments(static_cast<int>(t)).Count;
  }
  c.X.clear();
  if (fit)
  {
    c.X = VertexAnchors(values, mask, c.Mesh);
    c.Iterations = lsf.Solve(bm, c.X, opt.SolverTolerance);
  }
  else
  {
    c.X.assign(static_cast<size_t>(bm.NumberOfVertices()), 0.0);
  }
  c.Errors = lsf.VoxelErrors(bm, c.X);
}

// The chosen meshing as the reducer's output, in world coordinates, positively oriented there.
ReducedMesh Output(const VoxelVolume& geometry, const VoxelVolume& values, const Candidate& c, bool fit)
{
  ReducedMesh out;
  const size_t nv = c.Mesh.Points.size(), nt = c.Mesh.Tets.size();
  out.Points.resize(3 * nv);
  const double S = static_cast<double>(BisectionMesh::Scale);
  for (size_t v = 0; v < nv; ++v)
  {
    const LatticePoint& p = c.Mesh.Points[v];
    const double ijk[3] = { p.x / S, p.y / S, p.z / S };
    geometry.IndexToWorld(ijk, &out.Points[3 * v]);
  }
  out.Tets.resize(4 * nt);
  for (size_t t = 0; t < nt; ++t)
  {
    WritePositiveTet(c.Mesh.Tets[t], out.Points, &out.Tets[4 * t]);
  }
  if (fit)
  {
    out.Values.assign(c.X.begin(), c.X.begin() + static_cast<std::ptrdiff_t>(nv));
    out.TetRms = c.Errors.TetRms;
    out.TetMax = c.Errors.TetMax;
    out.Rms = out.WeightedRms = c.Errors.Rms;
    out.Max = out.WeightedMax = c.Errors.Max;
    out.Range[0] = values.Range[0];
    out.Range[1] = values.Range[1];
    out.ScalarName = values.Name;
  }
  out.SourceSpacing = MeanVoxelSpacing(geometry.Dims, geometry.Spacing);
  out.SolverIterations = c.Iterations;
  return out;
}

void CheckOptions(const VoxelVolume& volume, const RegionOptions& opt, bool fit)
{
  if (opt.TargetTets <= 0 && opt.TargetError < 0)
  {
    throw Error("a region reduction needs a tet budget or an error bound", volume.File);
  }
  if (!fit && opt.TargetTets <= 0)
  {
    throw Error("a label map without values to fit is meshed to a tet budget, not an error bound", volume.File);
  }
  if (opt.Values)
  {
    for (int a = 0; a < 3; ++a)
    {
      if (opt.Values->Dims[a] != volume.Dims[a])
      {
        throw Error("the values to fit have " + std::to_string(opt.Values->Dims[0]) + " x " +
            std::to_string(opt.Values->Dims[1]) + " x " + std::to_string(opt.Values->Dims[2]) +
            " voxels, the label map " + std::to_string(volume.Dims[0]) + " x " + std::to_string(volume.Dims[1]) +
            " x " + std::to_string(volume.Dims[2]) + ": they must share the grid",
          opt.Values->File.empty() ? volume.File : opt.Values->File);
      }
    }
  }
}
} // namespace

double RegionMemoryNeeded(long long voxels, long long tets)
{
  return 40.0 * static_cast<double>(voxels) + 1500.0 * static_cast<double>(tets);
}

RegionResult ReduceRegion(const VoxelVolume& volume, const RegionOptions& opt, const DomainMesher& mesher, Progress* progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  const bool fit = !opt.Labels || opt.Values;
  CheckOptions(volume, opt, fit);
  const VoxelVolume& values = opt.Values ? *opt.Values : volume;
  RegionResult res;
  res.Mask = opt.Labels ? MaskByLabels(volume, opt.Background, opt.MinIslandVoxels)
                        : MaskByRange(volume, opt.Lo, opt.Hi, opt.MinIslandVoxels);
  const long long cap = 6 * res.Mask.Voxels; // about the full resolution of the region
  const long long budget = opt.TargetTets > 0 ? std::min(opt.TargetTets, cap) : 0;
  const double need = RegionMemoryNeeded(volume.NumberOfVoxels(), budget > 0 ? budget : cap / 4);
  if (ExceedsAvailableMemory(need, AvailableMemoryBytes()))
  {
    throw Error("the region's meshing needs about " + std::to_string(static_cast<long long>(need / 1e9 + 0.5)) +
        " GB, more than the memory available; give a smaller --tets",
      volume.File);
  }
  const double s[3] = { std::fabs(volume.Spacing[0]), std::fabs(volume.Spacing[1]), std::fabs(volume.Spacing[2]) };
  const double voxel = MeanVoxelSpacing(volume.Dims, s);
  double extent = 0;
  for (int a = 0; a < 3; ++a)
  {
    extent = std::max(extent, (volume.Dims[a] - 1) * s[a]);
  }
  RegionSizing sizing(volume, res.Mask.Inside, opt.NodeVoxels, opt.MinEdgeVoxels * voxel, 0.25 * extent);

  ImageDomainRequest req;
  std::copy(volume.Dims, volume.Dims + 3, req.Dims);
  std::copy(s, s + 3, req.Spacing);
  std::vector<float> gray;
  std::vector<uint8_t> weights;
  if (opt.Labels)
  {
    req.Slots = res.Mask.Slot.data();
    if (opt.SmoothLabels)
    {
      weights = LabelWeights(res.Mask, volume.Dims, 1.0);
      req.Weights = weights.data();
    }
  }
  else
  {
    gray = GrayForMesher(volume, res.Mask, opt.Lo, opt.Hi);
    req.Values = gray.data();
    req.Lo = opt.Lo;
    req.Hi = opt.Hi;
  }

  double goal = budget > 0 ? static_cast<double>(budget)
                           : std::clamp(static_cast<double>(res.Mask.Voxels) / 50.0, 2000.0, 200000.0);
  SizeGrid size = sizing.Uniform(goal);
  Candidate best;
  bool haveBest = false, bestInBudget = false;
  const int rounds = budget > 0 ? opt.Rounds : opt.MaxRounds;
  if (progress)
  {
    progress->Begin("mesh the region", rounds);
  }
  for (int r = 0; r < rounds + (budget > 0 ? 2 : 0); ++r)
  {
    if (progress && progress->Cancelled())
    {
      throw Error("cancelled");
    }
    RegionRound round;
    round.ExpectedTets = sizing.ExpectedTets(size);
    req.Size = size;
    req.Distance = RegionSizing::DistanceFor(size, opt.DistanceFraction, opt.FacetDistance * voxel);
    auto tm = std::chrono::steady_clock::now();
    Candidate c;
    c.Mesh = ToLattice(mesher(req), s, volume.File);
    round.MeshSeconds = Since(tm);
    tm = std::chrono::steady_clock::now();
    FitCandidate(values, res.Mask, opt, fit, c);
    round.FitSeconds = Since(tm);
    const long long nt = static_cast<long long>(c.Mesh.Tets.size());
    round.Tets = nt;
    round.Vertices = static_cast<long long>(c.Mesh.Points.size());
    round.Rms = fit ? c.Errors.Rms : std::numeric_limits<double>::quiet_NaN();
    res.Rounds.push_back(round);
    if (progress)
    {
      progress->Advance(1.0);
    }
    sizing.Calibrate(size, nt);
    const bool inBudget = budget <= 0 || std::fabs(nt - budget) <= opt.BudgetTolerance * budget;
    const bool better = !haveBest || (inBudget && !bestInBudget) ||
      (inBudget == bestInBudget &&
        (fit && inBudget ? c.Errors.Rms < best.Errors.Rms
                         : std::fabs(nt - budget) < std::fabs(static_cast<long long>(best.Mesh.Tets.size()) - budget)));
    if (budget <= 0 || better)
    {
      best = std::move(c);
      res.ChosenRound = r;
      haveBest = true;
      bestInBudget = inBudget;
    }
    const Candidate& last = budget <= 0 || res.ChosenRound == r ? best : c;
    if (opt.TargetError >= 0 && fit && last.Errors.Rms <= opt.TargetError)
    {
      break; // the bound is met (with a budget too: whichever comes first)
    }
    if (budget > 0)
    {
      if (r + 1 >= rounds && bestInBudget)
      {
        break;
      }
    }
    else
    {
      if (nt >= cap)
      {
        break; // the region's full resolution: the bound cannot be met
      }
      goal = std::min<double>(cap, nt * std::pow(last.Errors.Rms / std::max(opt.TargetError, 1e-300), 1.5) * 1.1);
    }
    size = fit ? sizing.Adapted(goal, last.Mesh.Scaled, last.Mesh.Tets, last.Errors.TetRms, last.TetVoxels)
               : sizing.Uniform(goal);
  }
  if (progress)
  {
    progress->End();
  }
  res.Mesh = Output(volume, values, best, fit);
  if (opt.Values)
  {
    res.Mesh.Source = opt.Values->Statistics; // the values' window, for their default transfer function
  }
  res.CoveredVoxels = best.Errors.Voxels;
  res.TetLabels.resize(best.Mesh.Subdomain.size(), 1);
  if (opt.Labels)
  {
    for (size_t t = 0; t < res.TetLabels.size(); ++t)
    {
      const int slot = best.Mesh.Subdomain[t];
      res.TetLabels[t] = slot >= 1 && slot <= static_cast<int>(res.Mask.Labels.size()) ? res.Mask.Labels[slot - 1] : 0;
    }
  }
  res.Mesh.TargetTets = opt.TargetTets;
  res.Mesh.TargetError = opt.TargetError;
  res.Mesh.TargetReached = opt.TargetError < 0 || (fit && res.Mesh.Rms <= opt.TargetError) || bestInBudget;
  if (opt.TargetError >= 0 && budget <= 0)
  {
    res.Mesh.TargetReached = fit && res.Mesh.Rms <= opt.TargetError;
  }
  res.Mesh.RefinementLevels = static_cast<int>(res.Rounds.size());
  res.Mesh.BuildSeconds = Since(t0);
  res.Mask.Slot.clear();
  res.Mask.Slot.shrink_to_fit();
  return res;
}
} // namespace art
