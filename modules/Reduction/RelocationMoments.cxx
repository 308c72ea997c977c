#include "RelocationMoments.h"

#include "Error.h"
#include "OpacityImportance.h"
#include "ParallelTiles.h"
#include "Progress.h"
#include "VoxelRaster.h"

#include <algorithm>
#include <functional>

namespace art
{
namespace
{
// ForEachRange in ten slices, each followed on the calling thread by its share of `units` of
// progress and a look at the cancel flag: the set-up's voxel passes take seconds on a large volume.
template <class F>
void ForEachSlice(long long n, long long grain, Progress* progress, double units, F&& f)
{
  long long done = 0;
  ForEachRangeInSlices(n, grain, 10, f,
    progress ? std::function<void(long long)>([&](long long end) {
      if (progress->Cancelled())
      {
        throw Error("cancelled");
      }
      progress->Advance(units * double(end - done) / double(n));
      done = end;
    })
             : nullptr);
}
} // namespace

int RelocationMoments::Pair(int a, int b)
{
  static const int idx[4][4] = { { 0, 1, 2, 3 }, { 1, 4, 5, 6 }, { 2, 5, 7, 8 }, { 3, 6, 8, 9 } };
  return 6 + idx[a][b];
}

RelocationMoments::RelocationMoments(const VoxelVolume& volume, const OpacityImportance* importance)
  : Vol(volume)
  , Imp(importance)
{
}

bool RelocationMoments::OfTet(const LatticePoint P[4], double* m) const
{
  std::fill(m, m + NM, 0.0);
  TetRaster r;
  if (!r.Setup(P))
  {
    return false;
  }
  Vol.WithSamples([&](const auto* values) {
    const float* w = W.empty() ? nullptr : W.data();
    r.ForEachVoxel(Vol.Dims, [&](long long idx, const double* l) {
      const double k = w ? w[idx] : 1.0, f = values[idx], kf = k * f;
      const double kl[4] = { k * l[0], k * l[1], k * l[2], k * l[3] };
      m[0] += 1;
      m[1] += kf * f;
      m[2] += kf * l[0], m[3] += kf * l[1], m[4] += kf * l[2], m[5] += kf * l[3];
      m[6] += kl[0] * l[0], m[7] += kl[0] * l[1], m[8] += kl[0] * l[2], m[9] += kl[0] * l[3];
      m[10] += kl[1] * l[1], m[11] += kl[1] * l[2], m[12] += kl[1] * l[3];
      m[13] += kl[2] * l[2], m[14] += kl[2] * l[3], m[15] += kl[3] * l[3];
    });
  });
  return true;
}

void RelocationMoments::Compute(const BisectionMesh& mesh, const std::vector<double>& x, Progress* progress, double units)
{
  if (Imp)
  {
    // The weights at the fit relocated from (one reweighting step for the whole relocation, as
    // the refit after it takes): the weighted errors then follow from moments as the plain ones.
    W.assign(static_cast<size_t>(Vol.Dims[0]) * Vol.Dims[1] * Vol.Dims[2], static_cast<float>(Imp->Floor()));
    ForEachSlice(mesh.NumberOfTets(), 256, progress, units, [&](long long t0, long long t1, Counters&) {
      for (long long t = t0; t < t1; ++t)
      {
        LatticePoint P[4];
        double c[4];
        for (int a = 0; a < 4; ++a)
        {
          P[a] = mesh.Vertex(mesh.Tet(static_cast<int>(t))[a]);
          c[a] = x[mesh.Tet(static_cast<int>(t))[a]];
        }
        TetRaster r;
        if (r.Setup(P))
        {
          r.ForEachVoxel(Vol.Dims, [&](long long idx, const double* l) {
            const double fit = c[0] * l[0] + c[1] * l[1] + c[2] * l[2] + c[3] * l[3];
            W[static_cast<size_t>(idx)] = static_cast<float>(Imp->Weight(idx, Vol.Value(idx), fit));
          });
        }
      }
    });
  }
  Moments.assign(static_cast<size_t>(mesh.NumberOfTets()) * NM, 0.0);
  ForEachSlice(mesh.NumberOfTets(), 256, progress, units, [&](long long t0, long long t1, Counters&) {
    for (long long t = t0; t < t1; ++t)
    {
      LatticePoint P[4];
      for (int a = 0; a < 4; ++a)
      {
        P[a] = mesh.Vertex(mesh.Tet(static_cast<int>(t))[a]);
      }
      OfTet(P, Of(static_cast<int>(t)));
    }
  });
}

void RelocationMoments::AddStarTerms(
  const double* m, const double c[4], int vi, double& srr, double& srp, double& spp, long long& count)
{
  double r = m[1];
  for (int a = 0; a < 4; ++a)
  {
    r -= 2.0 * c[a] * m[2 + a];
    for (int b = 0; b < 4; ++b)
    {
      r += c[a] * c[b] * m[Pair(a, b)];
    }
  }
  double rp = m[2 + vi];
  for (int a = 0; a < 4; ++a)
  {
    rp -= c[a] * m[Pair(a, vi)];
  }
  srr += r;
  srp += rp;
  spp += m[Pair(vi, vi)];
  count += static_cast<long long>(m[0]);
}
} // namespace art
