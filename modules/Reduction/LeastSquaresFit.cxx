#include "LeastSquaresFit.h"

#include "Error.h"
#include "ParallelTiles.h"
#include "VoxelRaster.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace art
{
namespace
{
constexpr int RegularizeBelow = 8; // voxel centres a tet needs to pin its four corners well

// Deterministic parallel sum: fixed chunks, partial sums added in chunk order.
template <class F>
double ParallelSum(long long n, F&& term)
{
  const long long grain = 4096, chunks = (n + grain - 1) / grain;
  std::vector<double> part(static_cast<size_t>(chunks), 0.0);
  ForEachRange(chunks, 1, [&](long long c0, long long c1, Counters&) {
    for (long long c = c0; c < c1; ++c)
    {
      double s = 0;
      for (long long i = c * grain, e = std::min(n, i + grain); i < e; ++i)
      {
        s += term(i);
      }
      part[c] = s;
    }
  });
  double s = 0;
  for (double p : part)
  {
    s += p;
  }
  return s;
}

// The voxel raster of tet t (its corners on the lattice). Bisection never makes a flat tet.
TetRaster RasterOf(const BisectionMesh& mesh, int t)
{
  LatticePoint P[4];
  for (int a = 0; a < 4; ++a)
  {
    P[a] = mesh.Vertex(mesh.Tet(t)[a]);
  }
  TetRaster r;
  if (!r.Setup(P))
  {
    throw Error("internal: a flat tetrahedron in the bisection mesh");
  }
  return r;
}
} // namespace

int LeastSquaresFit::PackedIndex(int a, int b)
{
  static const int idx[4][4] = { { 0, 1, 2, 3 }, { 1, 4, 5, 6 }, { 2, 5, 7, 8 }, { 3, 6, 8, 9 } };
  return idx[a][b];
}

LeastSquaresFit::LeastSquaresFit(const VoxelVolume& volume, double regularization, const OpacityImportance* importance)
  : Volume(volume)
  , Regularization(regularization)
  , Imp(importance)
{
}

void LeastSquaresFit::Extend(const BisectionMesh& mesh, std::vector<double>& x)
{
  for (int v = static_cast<int>(x.size()); v < mesh.NumberOfVertices(); ++v)
  {
    const auto& p = mesh.Parents(v);
    const double w = 0.25 * mesh.ParentQuarters(v);
    x.push_back(p[0] >= 0 ? (1.0 - w) * x[p[0]] + w * x[p[1]] : 0.0);
  }
}

TetMoments LeastSquaresFit::Gather(const BisectionMesh& mesh, int t, const std::vector<double>* fit) const
{
  const TetRaster r = RasterOf(mesh, t);
  TetMoments m;
  double plainDiag[4] = { 0, 0, 0, 0 }, sumW = 0; // unweighted: is the tet pinned by its voxels?
  double c[4] = { 0, 0, 0, 0 };
  const bool haveFit = Imp && fit && !fit->empty();
  if (haveFit)
  {
    for (int a = 0; a < 4; ++a)
    {
      c[a] = (*fit)[mesh.Tet(t)[a]];
    }
  }
  bool allFlat = true;
  double flatLo = -std::numeric_limits<double>::infinity(), flatHi = std::numeric_limits<double>::infinity();
  auto accumulate = [&](const auto* values) {
    r.ForEachVoxel(Volume.Dims, [&](long long idx, const double* l) {
      if (Mask && !(*Mask)[idx])
      {
        return;
      }
      double f = values[idx], w = 1.0;
      if (Imp)
      {
        const double u = haveFit ? c[0] * l[0] + c[1] * l[1] + c[2] * l[2] + c[3] * l[3] : f;
        w = Imp->Weight(idx, f, u);
        allFlat = allFlat && Imp->Flat(idx, f, u);
        flatLo = std::max(flatLo, Imp->FlatLo(idx));
        flatHi = std::min(flatHi, Imp->FlatHi(idx));
      }
      if (m.Count++ == 0)
      {
        m.F0 = f;
      }
      sumW += w;
      const double d = f - m.F0;
      m.G += w * d * d;
      for (int a = 0; a < 4; ++a)
      {
        plainDiag[a] += l[a] * l[a];
      }
      const double wl[4] = { w * l[0], w * l[1], w * l[2], w * l[3] };
      m.M[0] += wl[0] * l[0], m.M[1] += wl[0] * l[1], m.M[2] += wl[0] * l[2], m.M[3] += wl[0] * l[3];
      m.M[4] += wl[1] * l[1], m.M[5] += wl[1] * l[2], m.M[6] += wl[1] * l[3];
      m.M[7] += wl[2] * l[2], m.M[8] += wl[2] * l[3], m.M[9] += wl[3] * l[3];
      for (int a = 0; a < 4; ++a)
      {
        m.Bf[a] += wl[a] * d;
      }
    });
  };
  Volume.WithSamples(accumulate);
  m.Regularize = m.Count < RegularizeBelow || plainDiag[0] < 0.5 || plainDiag[1] < 0.5 || plainDiag[2] < 0.5 ||
    plainDiag[3] < 0.5;
  m.MeanWeight = m.Count > 0 ? sumW / m.Count : 1.0;
  m.AllFlat = Imp && allFlat;
  m.FlatLo = flatLo;
  m.FlatHi = flatHi;
  m.Version = mesh.Version(t);
  const double S = static_cast<double>(BisectionMesh::Scale);
  m.Volume = static_cast<double>(r.SixVolume()) / 6.0 / (S * S * S);
  return m;
}

void LeastSquaresFit::UpdateMoments(
  const BisectionMesh& mesh, const std::vector<int>& tets, const std::vector<double>* fit, const Done& done)
{
  Mom.resize(static_cast<size_t>(mesh.NumberOfTets()));
  GatherAll(mesh, tets, fit, done);
}

void LeastSquaresFit::GatherAll(
  const BisectionMesh& mesh, const std::vector<int>& tets, const std::vector<double>* fit, const Done& done)
{
  const long long n = static_cast<long long>(tets.size());
  // Twenty slices tell the progress every 5%; each is still thousands of tets on a large mesh.
  ForEachRangeInSlices(
    n, 64, 20,
    [&](long long b, long long e, Counters&) {
      for (long long i = b; i < e; ++i)
      {
        Mom[tets[i]] = Gather(mesh, tets[i], fit);
      }
    },
    done ? std::function<void(long long)>([&](long long end) { done(double(end) / double(n)); }) : nullptr);
}

long long LeastSquaresFit::Reweigh(const BisectionMesh& mesh, const std::vector<double>& fit, const Done& done)
{
  const int nt = mesh.NumberOfTets();
  Mom.resize(static_cast<size_t>(nt));
  std::vector<int> stale;
  for (int t = 0; t < nt; ++t)
  {
    const TetMoments& m = Mom[t];
    bool keep = m.AllFlat && m.Version == mesh.Version(t);
    if (keep)
    {
      // The fit at a voxel is a convex combination of the corners (up to round-off in the
      // barycentric weights, hence the margin): inside the flat interval, every voxel's weight
      // is its flat weight again.
      double lo = fit[mesh.Tet(t)[0]], hi = lo;
      for (int a = 1; a < 4; ++a)
      {
        lo = std::min(lo, fit[mesh.Tet(t)[a]]);
        hi = std::max(hi, fit[mesh.Tet(t)[a]]);
      }
      const double margin = 1e-9 * (std::max(std::fabs(lo), std::fabs(hi)) + 1.0);
      keep = lo - margin > m.FlatLo && hi + margin < m.FlatHi;
    }
    if (!keep)
    {
      stale.push_back(t);
    }
  }
  GatherAll(mesh, stale, &fit, done);
  return static_cast<long long>(stale.size());
}

int LeastSquaresFit::Solve(const BisectionMesh& mesh, std::vector<double>& x, double tolerance, int maxIterations)
{
  const int nv = mesh.NumberOfVertices();
  // Solved for x - shift, the mean voxel value: CG stops at a residual relative to the right-hand
  // side, which a large offset would dominate (small variations on a large offset stopped far
  // from their fit). The shifted right-hand side comes straight from the moments, which are
  // relative to each tet's own F0, so no digits of the variation are lost.
  double shift = 0, count = 0;
  for (int t = 0; t < mesh.NumberOfTets(); ++t)
  {
    shift += Mom[t].F0 * Mom[t].Count;
    count += Mom[t].Count;
  }
  shift = count > 0 ? shift / count : 0.0;
  // The coarse mesh starts at the mean (its regulariser anchors sparse tets there, not at 0);
  // new vertices start on the previous fit: exact warm start.
  const bool coarse = x.empty();
  Extend(mesh, x);
  if (coarse)
  {
    std::fill(x.begin(), x.end(), shift);
  }
  const std::vector<double> anchor = x; // the previous fit, interpolated onto new vertices
  // CSR rows assembled independently, each from the tets around its vertex, in a fixed order.
  std::vector<std::vector<int>> cols(nv);
  std::vector<std::vector<double>> vals(nv);
  std::vector<double> rhs(nv), diag(nv);
  ForEachRange(nv, 256, [&](long long v0, long long v1, Counters&) {
    std::vector<int> c;
    for (long long v = v0; v < v1; ++v)
    {
      c.clear();
      for (int t : mesh.TetsAround(static_cast<int>(v)))
      {
        for (int w : mesh.Tet(t))
        {
          c.push_back(w);
        }
      }
      std::sort(c.begin(), c.end());
      c.erase(std::unique(c.begin(), c.end()), c.end());
      std::vector<double> val(c.size(), 0.0);
      double bv = 0;
      for (int t : mesh.TetsAround(static_cast<int>(v)))
      {
        const auto& tv = mesh.Tet(t);
        const TetMoments& m = Mom[t];
        const int a = static_cast<int>(std::find(tv.begin(), tv.end(), v) - tv.begin());
        double rowSum = 0;
        for (int b = 0; b < 4; ++b)
        {
          const int p = PackedIndex(a, b);
          rowSum += m.M[p];
          // Continuous P1 mass matrix: volume / 20 * (1 + delta_ab).
          const double mc =
            m.Regularize ? Regularization * m.MeanWeight * m.Volume / 20.0 * (a == b ? 2.0 : 1.0) : 0.0;
          val[std::lower_bound(c.begin(), c.end(), tv[b]) - c.begin()] += m.M[p] + mc;
          bv += mc * (anchor[tv[b]] - shift);
        }
        bv += m.Bf[a] + (m.F0 - shift) * rowSum; // sum lambda_a (f - shift), from the moments about F0
      }
      rhs[v] = bv;
      diag[v] = val[std::lower_bound(c.begin(), c.end(), static_cast<int>(v)) - c.begin()];
      if (!(diag[v] > 0))
      {
        diag[v] = 1.0; // an unconstrained vertex (cannot happen with the regulariser); keep CG finite
      }
      cols[v] = c;
      vals[v] = std::move(val);
    }
  });
  auto spmv = [&](const std::vector<double>& in, std::vector<double>& out) {
    ForEachRange(nv, 512, [&](long long v0, long long v1, Counters&) {
      for (long long v = v0; v < v1; ++v)
      {
        double s = 0;
        const auto& c = cols[v];
        const auto& a = vals[v];
        for (size_t q = 0; q < c.size(); ++q)
        {
          s += a[q] * in[c[q]];
        }
        out[v] = s;
      }
    });
  };
  for (double& v : x)
  {
    v -= shift;
  }
  std::vector<double> r(nv), z(nv), p(nv), q(nv);
  spmv(x, q);
  for (int v = 0; v < nv; ++v)
  {
    r[v] = rhs[v] - q[v];
    z[v] = r[v] / diag[v];
  }
  p = z;
  const double bnorm = std::sqrt(ParallelSum(nv, [&](long long i) { return rhs[i] * rhs[i]; }));
  const double stop = tolerance * (bnorm > 0 ? bnorm : 1.0);
  double rz = ParallelSum(nv, [&](long long i) { return r[i] * z[i]; });
  int it = 0;
  for (; it < maxIterations; ++it)
  {
    const double rn = std::sqrt(ParallelSum(nv, [&](long long i) { return r[i] * r[i]; }));
    if (rn <= stop)
    {
      break;
    }
    spmv(p, q);
    const double pq = ParallelSum(nv, [&](long long i) { return p[i] * q[i]; });
    if (!(pq > 0))
    {
      break;
    }
    const double alpha = rz / pq;
    ForEachRange(nv, 4096, [&](long long v0, long long v1, Counters&) {
      for (long long v = v0; v < v1; ++v)
      {
        x[v] += alpha * p[v];
        r[v] -= alpha * q[v];
        z[v] = r[v] / diag[v];
      }
    });
    const double rzNew = ParallelSum(nv, [&](long long i) { return r[i] * z[i]; });
    const double beta = rzNew / rz;
    rz = rzNew;
    ForEachRange(nv, 4096, [&](long long v0, long long v1, Counters&) {
      for (long long v = v0; v < v1; ++v)
      {
        p[v] = z[v] + beta * p[v];
      }
    });
  }
  for (double& v : x)
  {
    v += shift;
  }
  return it;
}

void LeastSquaresFit::SquaredErrors(const BisectionMesh& mesh, const std::vector<double>& x, std::vector<double>& sse) const
{
  const int nt = mesh.NumberOfTets();
  sse.assign(nt, 0.0);
  ForEachRange(nt, 1024, [&](long long t0, long long t1, Counters&) {
    for (long long t = t0; t < t1; ++t)
    {
      const TetMoments& m = Mom[t];
      double d[4];
      for (int a = 0; a < 4; ++a)
      {
        d[a] = x[mesh.Tet(static_cast<int>(t))[a]] - m.F0;
      }
      double s = m.G;
      for (int a = 0; a < 4; ++a)
      {
        s -= 2 * d[a] * m.Bf[a];
        for (int b = 0; b < 4; ++b)
        {
          s += d[a] * m.M[PackedIndex(a, b)] * d[b];
        }
      }
      sse[t] = std::max(0.0, s);
    }
  });
}

void LeastSquaresFit::EdgeMoments(const BisectionMesh& mesh, const std::vector<int>& tets,
  std::vector<EdgeSplitMoments>& out, const std::vector<double>* fit) const
{
  out.resize(static_cast<size_t>(mesh.NumberOfTets()));
  const bool haveFit = Imp && fit && !fit->empty();
  ForEachRange(static_cast<long long>(tets.size()), 64, [&](long long b, long long e, Counters&) {
    for (long long i = b; i < e; ++i)
    {
      const int t = tets[i];
      const TetRaster r = RasterOf(mesh, t);
      double c[4] = { 0, 0, 0, 0 };
      for (int a = 0; haveFit && a < 4; ++a)
      {
        c[a] = (*fit)[mesh.Tet(t)[a]];
      }
      EdgeSplitMoments m;
      bool first = true;
      auto pass = [&](const auto* values) {
        r.ForEachVoxel(Volume.Dims, [&](long long idx, const double* l) {
          if (Mask && !(*Mask)[idx])
          {
            return;
          }
          const double f = values[idx];
          if (first)
          {
            m.F0 = f;
            first = false;
          }
          double w = 1.0;
          if (Imp)
          {
            w = Imp->Weight(idx, f, haveFit ? c[0] * l[0] + c[1] * l[1] + c[2] * l[2] + c[3] * l[3] : f);
          }
          const double wd = w * (f - m.F0);
          for (int k = 0; k < 6; ++k)
          {
            const double la = l[BisectionMesh::EdgeCorners[k][0]], lb = l[BisectionMesh::EdgeCorners[k][1]];
            for (int q = 0; q < EdgeSplitMoments::Positions; ++q)
            {
              // The new vertex at t = (q + 1) / 4 from the first corner: its hat is
              // min(lb / t, la / (1 - t)) over the star (2 min(la, lb) at the midpoint).
              const double t = 0.25 * (q + 1);
              const double phi = std::min(lb / t, la / (1.0 - t));
              const double wphi = w * phi;
              m.P[q][k] += wd * phi;
              m.Q[q][k] += wphi * phi;
              for (int c = 0; c < 4; ++c)
              {
                m.R[q][k][c] += wphi * l[c];
              }
            }
          }
        });
      };
      Volume.WithSamples(pass);
      out[t] = m;
    }
  });
}

void LeastSquaresFit::VertexVoxelRange(
  const BisectionMesh& mesh, std::vector<double>& lo, std::vector<double>& hi) const
{
  const int nt = mesh.NumberOfTets(), nv = mesh.NumberOfVertices();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> tlo(nt, inf), thi(nt, -inf);
  ForEachRange(nt, 64, [&](long long t0, long long t1, Counters&) {
    for (long long t = t0; t < t1; ++t)
    {
      const TetRaster r = RasterOf(mesh, static_cast<int>(t));
      double a = inf, b = -inf;
      r.ForEachVoxel(Volume.Dims, [&](long long idx, const double*) {
        if (Mask && !(*Mask)[idx])
        {
          return;
        }
        const double f = Volume.Value(idx);
        a = std::min(a, f);
        b = std::max(b, f);
      });
      tlo[t] = a;
      thi[t] = b;
    }
  });
  lo.assign(nv, inf);
  hi.assign(nv, -inf);
  ForEachRange(nv, 1024, [&](long long v0, long long v1, Counters&) {
    for (long long v = v0; v < v1; ++v)
    {
      for (int t : mesh.TetsAround(static_cast<int>(v)))
      {
        lo[v] = std::min(lo[v], tlo[t]);
        hi[v] = std::max(hi[v], thi[t]);
      }
    }
  });
}

VoxelErrorReport LeastSquaresFit::VoxelErrors(const BisectionMesh& mesh, const std::vector<double>& x) const
{
  const int nt = mesh.NumberOfTets();
  VoxelErrorReport out;
  out.TetRms.assign(nt, 0.0);
  out.TetMax.assign(nt, 0.0);
  out.TetWeightedMax.assign(nt, 0.0);
  out.TetWeightedSse.assign(nt, 0.0);
  std::vector<double> sse(nt, 0.0);
  std::vector<long long> count(nt, 0);
  std::vector<double>& wsse = out.TetWeightedSse;
  ForEachRange(nt, 64, [&](long long t0, long long t1, Counters&) {
    for (long long t = t0; t < t1; ++t)
    {
      const TetRaster r = RasterOf(mesh, static_cast<int>(t));
      double c[4];
      for (int a = 0; a < 4; ++a)
      {
        c[a] = x[mesh.Tet(static_cast<int>(t))[a]];
      }
      double s = 0, ws = 0, mx = 0, wmx = 0;
      long long n = 0;
      auto pass = [&](const auto* values) {
        r.ForEachVoxel(Volume.Dims, [&](long long idx, const double* l) {
          if (Mask && !(*Mask)[idx])
          {
            return;
          }
          const double u = c[0] * l[0] + c[1] * l[1] + c[2] * l[2] + c[3] * l[3];
          const double e = values[idx] - u;
          const double e2 = Imp ? Imp->Error2(idx, values[idx], u) : e * e;
          s += e * e;
          ws += e2;
          mx = std::max(mx, std::fabs(e));
          wmx = std::max(wmx, e2);
          ++n;
        });
      };
      Volume.WithSamples(pass);
      sse[t] = s;
      count[t] = n;
      wsse[t] = ws;
      out.TetRms[t] = n ? std::sqrt(s / n) : 0.0;
      out.TetMax[t] = mx;
      out.TetWeightedMax[t] = std::sqrt(wmx);
    }
  });
  double total = 0, wtotal = 0;
  for (int t = 0; t < nt; ++t)
  {
    total += sse[t];
    wtotal += wsse[t];
    out.Max = std::max(out.Max, out.TetMax[t]);
    out.WeightedMax = std::max(out.WeightedMax, out.TetWeightedMax[t]);
  }
  out.Voxels = Volume.NumberOfVoxels(); // the mesh covers the box: every voxel is in one tet
  if (Mask)
  {
    out.Voxels = 0;
    for (long long n : count)
    {
      out.Voxels += n;
    }
  }
  const double nvox = static_cast<double>(std::max<long long>(out.Voxels, 1));
  out.Rms = std::sqrt(total / nvox);
  out.WeightedRms = std::sqrt(wtotal / nvox);
  return out;
}
} // namespace art
