#include "WholeBoxComparison.h"

#include "BisectionMesh.h"
#include "Error.h"
#include "ParallelTiles.h"
#include "Progress.h"
#include "VoxelRaster.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace art
{
namespace
{
// A level's point on the lattice again (its vertices were lattice points before IndexToWorld).
LatticePoint ToLattice(const VoxelVolume& v, const double* w)
{
  double ijk[3];
  v.WorldToIndex(w, ijk);
  const double S = static_cast<double>(BisectionMesh::Scale);
  return { std::llround(ijk[0] * S), std::llround(ijk[1] * S), std::llround(ijk[2] * S) };
}
} // namespace

MaskedError ErrorInside(const VoxelVolume& volume, const std::vector<uint8_t>& inside, const ReducedMesh& mesh)
{
  const long long nt = mesh.NumberOfTets();
  std::vector<double> sse(static_cast<size_t>(nt), 0.0), mx(static_cast<size_t>(nt), 0.0);
  std::vector<long long> count(static_cast<size_t>(nt), 0);
  ForEachRange(nt, 64, [&](long long t0, long long t1, Counters&) {
    for (long long t = t0; t < t1; ++t)
    {
      LatticePoint P[4];
      double c[4];
      for (int a = 0; a < 4; ++a)
      {
        const int v = mesh.Tets[4 * t + a];
        P[a] = ToLattice(volume, &mesh.Points[3 * static_cast<size_t>(v)]);
        c[a] = mesh.Values[v];
      }
      TetRaster r;
      if (!r.Setup(P))
      {
        continue;
      }
      r.ForEachVoxel(volume.Dims, [&](long long idx, const double* l) {
        if (!inside[idx])
        {
          return;
        }
        const double e = volume.Value(idx) - (c[0] * l[0] + c[1] * l[1] + c[2] * l[2] + c[3] * l[3]);
        sse[t] += e * e;
        mx[t] = std::max(mx[t], std::fabs(e));
        ++count[t];
      });
    }
  });
  MaskedError out;
  double total = 0;
  for (long long t = 0; t < nt; ++t)
  {
    total += sse[t];
    out.Max = std::max(out.Max, mx[t]);
    out.Voxels += count[t];
  }
  out.Rms = out.Voxels > 0 ? std::sqrt(total / out.Voxels) : 0.0;
  return out;
}

WholeBoxFigures WholeBoxForRegionError(const VoxelVolume& volume, const std::vector<uint8_t>& inside,
  double targetRms, long long startTets, long long maxTets, Progress* progress)
{
  const auto t0 = std::chrono::steady_clock::now();
  WholeBoxFigures out;
  ReducerOptions ro;
  ro.TargetTets = std::max<long long>(maxTets, 6);
  for (double b = std::max<double>(6, startTets); b < 0.99 * ro.TargetTets; b *= 1.4)
  {
    ro.Levels.push_back(static_cast<long long>(b));
  }
  if (progress)
  {
    progress->Begin("whole-box comparison", 1.0);
  }
  double shown = 0;
  Progress local([&](double f, const std::string&) {
    if (progress)
    {
      progress->Advance(std::max(0.0, f - shown));
      shown = std::max(shown, f);
      if (progress->Cancelled())
      {
        local.Cancel();
      }
    }
  });
  bool met = false;
  auto onLevel = [&](const ReducedMesh& m) {
    if (met)
    {
      return;
    }
    const MaskedError e = ErrorInside(volume, inside, m);
    out.Levels.emplace_back(m.NumberOfTets(), e.Rms);
    if (e.Rms <= targetRms)
    {
      met = true;
      local.Cancel(); // the levels past this one are not needed
    }
  };
  try
  {
    TetReducer(ro).Run(volume, &local, onLevel);
  }
  catch (const Error&)
  {
    if (!local.Cancelled() || (progress && progress->Cancelled()))
    {
      throw;
    }
  }
  if (progress)
  {
    progress->End();
  }
  out.Reached = met;
  out.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (out.Levels.empty())
  {
    return out;
  }
  out.Tets = out.Levels.back().first;
  const size_t n = out.Levels.size();
  if (met && n >= 2 && out.Levels[n - 2].second > targetRms && targetRms > 0)
  {
    const double n0 = std::log(double(out.Levels[n - 2].first)), n1 = std::log(double(out.Levels[n - 1].first));
    const double e0 = std::log(out.Levels[n - 2].second), e1 = std::log(std::max(out.Levels[n - 1].second, 1e-300));
    const double f = e1 != e0 ? (std::log(targetRms) - e0) / (e1 - e0) : 1.0;
    out.Tets = static_cast<long long>(std::llround(std::exp(n0 + std::clamp(f, 0.0, 1.0) * (n1 - n0))));
  }
  return out;
}
} // namespace art
