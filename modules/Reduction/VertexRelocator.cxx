#include "VertexRelocator.h"

#include "Error.h"
#include "OpacityImportance.h"
#include "ParallelTiles.h"
#include "Progress.h"
#include "VoxelRaster.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace art
{
namespace
{
using i128 = __int128;

// Six times the signed volume of (a, b, c, d) in lattice units, exactly.
i128 Orient(const LatticePoint& a, const LatticePoint& b, const LatticePoint& c, const LatticePoint& d)
{
  const i128 u[3] = { b.x - a.x, b.y - a.y, b.z - a.z };
  const i128 v[3] = { c.x - a.x, c.y - a.y, c.z - a.z };
  const i128 w[3] = { d.x - a.x, d.y - a.y, d.z - a.z };
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

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

class Relocator
{
public:
  Relocator(BisectionMesh& mesh, const VoxelVolume& volume, std::vector<double>& x, const RelocationOptions& o,
    const OpacityImportance* imp)
    : Mesh(mesh)
    , Vol(volume)
    , X(x)
    , Opt(o)
    , Imp(imp)
  {
    for (int d = 0; d < 3; ++d)
    {
      Max[d] = static_cast<int64_t>(volume.Dims[d] - 1) * BisectionMesh::Scale;
      // Shape is judged in world units (anisotropic voxels); the direction matrix is a rotation.
      Spacing[d] = std::fabs(volume.Spacing[d]) / static_cast<double>(BisectionMesh::Scale);
    }
    const double range = std::max(1.0, std::fabs(volume.Range[0]) + std::fabs(volume.Range[1]));
    Scale2 = range * range;
  }

  double TotalSse() const
  {
    std::vector<double> per(static_cast<size_t>(Mesh.NumberOfTets()));
    ForEachRange(Mesh.NumberOfTets(), 256, [&](long long t0, long long t1, Counters&) {
      for (int t = static_cast<int>(t0); t < t1; ++t)
      {
        double s = 0;
        LatticePoint P[4];
        double c[4];
        for (int a = 0; a < 4; ++a)
        {
          P[a] = Mesh.Vertex(Mesh.Tet(t)[a]);
          c[a] = X[Mesh.Tet(t)[a]];
        }
        TetRaster r;
        if (!r.Setup(P))
        {
          throw Error("internal: a flat tetrahedron after relocation");
        }
        r.ForEachVoxel(Vol.Dims, [&](long long idx, const double* l) {
          const double f = Vol.Value(idx), u = c[0] * l[0] + c[1] * l[1] + c[2] * l[2] + c[3] * l[3];
          s += Imp ? Imp->Error2(idx, f, u) : (f - u) * (f - u);
        });
        per[t] = s;
      }
    });
    double s = 0;
    for (double e : per)
    {
      s += e; // in tet order: the same for any thread count
    }
    return s;
  }

  // Per-tet voxel moments, weighted by W when a transfer function weighs: count, sum f^2, sum f l_a, sum l_a l_b
  // (a <= b, in the order 00 01 02 03 11 12 13 22 23 33). A star's error for any values of its
  // vertices follows from its tets' moments without a voxel pass.
  static constexpr int NM = 16;
  static int Pair(int a, int b)
  {
    static const int idx[4][4] = { { 0, 1, 2, 3 }, { 1, 4, 5, 6 }, { 2, 5, 7, 8 }, { 3, 6, 8, 9 } };
    return 6 + idx[a][b];
  }
  void TetMoments(const LatticePoint P[4], double* m, bool& flat) const
  {
    std::fill(m, m + NM, 0.0);
    TetRaster r;
    flat = !r.Setup(P);
    if (flat)
    {
      return;
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
  }
  /// `progress` (optional) advances by `units` for each voxel pass.
  void ComputeMoments(Progress* progress, double units)
  {
    if (Imp)
    {
      // The weights at the fit relocated from (one reweighting step for the whole relocation,
      // as the refit after it takes): the weighted errors then follow from moments as the plain ones.
      W.assign(static_cast<size_t>(Vol.Dims[0]) * Vol.Dims[1] * Vol.Dims[2], static_cast<float>(Imp->Floor()));
      ForEachSlice(Mesh.NumberOfTets(), 256, progress, units, [&](long long t0, long long t1, Counters&) {
        for (long long t = t0; t < t1; ++t)
        {
          LatticePoint P[4];
          double c[4];
          for (int a = 0; a < 4; ++a)
          {
            P[a] = Mesh.Vertex(Mesh.Tet(static_cast<int>(t))[a]);
            c[a] = X[Mesh.Tet(static_cast<int>(t))[a]];
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
    Moments.assign(static_cast<size_t>(Mesh.NumberOfTets()) * NM, 0.0);
    ForEachSlice(Mesh.NumberOfTets(), 256, progress, units, [&](long long t0, long long t1, Counters&) {
      for (long long t = t0; t < t1; ++t)
      {
        LatticePoint P[4];
        for (int a = 0; a < 4; ++a)
        {
          P[a] = Mesh.Vertex(Mesh.Tet(static_cast<int>(t))[a]);
        }
        bool flat;
        TetMoments(P, &Moments[static_cast<size_t>(t) * NM], flat);
      }
    });
  }
  // Adds tet t's squared-error terms with v (local index vi) unknown, the others at c.
  static void AddFromMoments(const double* m, const double c[4], int vi, double& srr, double& srp,
    double& spp, long long& count)
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

  struct Scratch
  {
    std::vector<double> NewMoments; // of the star's tets at LastQ, the last place evaluated exactly
    LatticePoint LastQ{};
    std::vector<int> Star, Sign;
    std::vector<double> QOld;
    std::vector<std::pair<double, LatticePoint>> Top;
    std::vector<std::pair<double, double>> TopValue;
    long long Count = 0;
  };

  /// One visit of vertex v: returns true when it moved.
  bool Visit(int v, Scratch& sc) const
  {
    std::vector<int>& Star = sc.Star;
    std::vector<int>& Sign = sc.Sign;
    std::vector<double>& QOld = sc.QOld;
    const LatticePoint p = Mesh.Vertex(v);
    bool fixed[3];
    int free = 0;
    for (int d = 0; d < 3; ++d)
    {
      fixed[d] = p[d] == 0 || p[d] == Max[d];
      free += fixed[d] ? 0 : 1;
    }
    if (free == 0)
    {
      return false; // a box corner
    }
    Star = Mesh.TetsAround(v);
    const size_t n = Star.size();
    Sign.resize(n);
    QOld.resize(n);
    for (size_t i = 0; i < n; ++i)
    {
      LatticePoint P[4];
      Corners(Star[i], v, p, P);
      const i128 o = Orient(P[0], P[1], P[2], P[3]);
      Sign[i] = o > 0 ? 1 : -1;
      QOld[i] = Quality(P);
    }
    double best, bestValue;
    sc.LastQ.x = -1; // no place evaluated exactly yet in this visit
    if (!Evaluate(v, p, false, sc, best, bestValue, -1))
    {
      return false;
    }
    if (best <= 1e-20 * Scale2 * sc.Count)
    {
      X[v] = bestValue;
      return false; // the star already fits its voxels
    }
    X[v] = bestValue; // the vertex's own best value at its place: never worse
    const long long count = sc.Count;
    // Candidates are screened on a subsample of the star's voxels (every s-th per axis, s chosen
    // so that enough remain); only the best few are evaluated exactly.
    int stride = std::max(1, Opt.ScreenStride);
    if (Opt.ScreenStride <= 0)
    {
      while (stride < 3 && count >= static_cast<long long>(Opt.ScreenVoxels) * (stride + 1) * (stride + 1) * (stride + 1))
      {
        ++stride;
      }
    }
    double screenAt, unusedValue;
    if (!Evaluate(v, p, false, sc, screenAt, unusedValue, stride))
    {
      return false;
    }
    // Candidate directions, in lattice units.
    std::vector<std::array<double, 3>> dirs;
    double g[3];
    Gradient(p, g);
    dirs.push_back({ g[0], g[1], g[2] });
    dirs.push_back({ -g[0], -g[1], -g[2] });
    for (int d = 0; d < 3; ++d)
    {
      std::array<double, 3> a = { 0, 0, 0 };
      a[d] = 1;
      dirs.push_back(a);
      a[d] = -1;
      dirs.push_back(a);
    }
    double cen[3] = { 0, 0, 0 };
    for (int t : Star)
    {
      for (int a = 0; a < 4; ++a)
      {
        const LatticePoint& q = Mesh.Vertex(Mesh.Tet(t)[a]);
        cen[0] += q.x, cen[1] += q.y, cen[2] += q.z;
      }
    }
    dirs.push_back({ cen[0] / (4.0 * n) - p.x, cen[1] / (4.0 * n) - p.y, cen[2] / (4.0 * n) - p.z });
    // The best screened candidates, best first (ties keep the earlier one: deterministic).
    const int keep = std::max(1, Opt.ExactCandidates);
    std::vector<std::pair<double, LatticePoint>>& top = sc.Top;
    std::vector<std::pair<double, double>>& topValue = sc.TopValue;
    top.clear();
    topValue.clear();
    std::array<double, 3> bestDir = { 0, 0, 0 };
    double bestStep = 0;
    auto screen = [&](const std::array<double, 3>& d, double step) {
      LatticePoint q = p;
      q.x = fixed[0] ? p.x : p.x + std::llround(step * d[0]);
      q.y = fixed[1] ? p.y : p.y + std::llround(step * d[1]);
      q.z = fixed[2] ? p.z : p.z + std::llround(step * d[2]);
      if (q.x == p.x && q.y == p.y && q.z == p.z)
      {
        return;
      }
      double e, value;
      if (!Evaluate(v, q, true, sc, e, value, stride) || !(e < screenAt * (1.0 - 1e-9)))
      {
        return;
      }
      size_t at = top.size();
      while (at > 0 && e < top[at - 1].first)
      {
        --at;
      }
      if (at < static_cast<size_t>(keep))
      {
        if (at == 0)
        {
          bestDir = d, bestStep = step;
        }
        top.insert(top.begin() + static_cast<std::ptrdiff_t>(at), { e, q });
        topValue.insert(topValue.begin() + static_cast<std::ptrdiff_t>(at), { e, value });
        if (top.size() > static_cast<size_t>(keep))
        {
          top.pop_back();
          topValue.pop_back();
        }
      }
    };
    for (auto& d : dirs)
    {
      for (int k = 0; k < 3; ++k)
      {
        d[k] = fixed[k] ? 0 : d[k];
      }
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (!(len > 0))
      {
        continue;
      }
      const double tmax = Reach(v, p, d.data(), Star);
      screen(d, 0.3 * tmax);
    }
    if (!top.empty())
    {
      // Coarse to fine: either side of the best step along its direction. (Four fixed steps per
      // direction, 0.15 .. 0.85 of the reach, ended under 1% lower at twice the screening.)
      const std::array<double, 3> d = bestDir;
      const double step = bestStep;
      screen(d, 0.5 * step);
      screen(d, 1.5 * step);
    }
    LatticePoint bestP = p;
    for (size_t i = 0; i < top.size(); ++i)
    {
      const LatticePoint& q = top[i].second;
      double e, value;
      sc.LastQ.x = -1; // the moments are being overwritten
      if (!Evaluate(v, q, false, sc, e, value))
      {
        continue;
      }
      sc.LastQ = q;
      if (e < best * (1.0 - 1e-9))
      {
        best = e;
        bestValue = value;
        bestP = q;
      }
    }
    if (bestP.x == p.x && bestP.y == p.y && bestP.z == p.z)
    {
      return false;
    }
    // The moments of the accepted place: evaluated last or re-evaluated here.
    double e, value;
    if (!(bestP.x == sc.LastQ.x && bestP.y == sc.LastQ.y && bestP.z == sc.LastQ.z))
    {
      Evaluate(v, bestP, false, sc, e, value);
    }
    for (size_t i = 0; i < Star.size(); ++i)
    {
      std::copy_n(&sc.NewMoments[i * NM], NM, &Moments[static_cast<size_t>(Star[i]) * NM]);
    }
    Mesh.MoveVertex(v, bestP);
    X[v] = bestValue;
    return true;
  }

private:
  void Corners(int t, int v, const LatticePoint& at, LatticePoint P[4]) const
  {
    for (int a = 0; a < 4; ++a)
    {
      const int w = Mesh.Tet(t)[a];
      P[a] = w == v ? at : Mesh.Vertex(w);
    }
  }

  // 6 sqrt(2) V / l_rms^3 in world units: 1 for the regular tet, 0 when flat.
  double Quality(const LatticePoint P[4]) const
  {
    double e[6][3];
    int k = 0;
    for (int a = 0; a < 4; ++a)
    {
      for (int b = a + 1; b < 4; ++b, ++k)
      {
        for (int d = 0; d < 3; ++d)
        {
          e[k][d] = static_cast<double>(P[b][d] - P[a][d]) * Spacing[d];
        }
      }
    }
    double l2 = 0;
    for (auto& r : e)
    {
      l2 += r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
    }
    // edges 0: (0,1), 1: (0,2), 2: (0,3)
    const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
      e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    const double lrms = std::sqrt(l2 / 6.0);
    return lrms > 0 ? std::sqrt(2.0) * std::fabs(det) / (lrms * lrms * lrms) : 0.0;
  }

  // How far v can go along d (lattice units per unit of d) before a tet of its star flattens.
  double Reach(int v, const LatticePoint& p, const double d[3], const std::vector<int>& Star) const
  {
    double tmax = 1e300;
    for (int t : Star)
    {
      int o[3], k = 0;
      for (int a = 0; a < 4; ++a)
      {
        if (Mesh.Tet(t)[a] != v)
        {
          o[k++] = Mesh.Tet(t)[a];
        }
      }
      const LatticePoint &a = Mesh.Vertex(o[0]), &b = Mesh.Vertex(o[1]), &c = Mesh.Vertex(o[2]);
      const double u[3] = { double(b.x - a.x), double(b.y - a.y), double(b.z - a.z) };
      const double w[3] = { double(c.x - a.x), double(c.y - a.y), double(c.z - a.z) };
      double nrm[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0] };
      const double h = nrm[0] * double(p.x - a.x) + nrm[1] * double(p.y - a.y) + nrm[2] * double(p.z - a.z);
      const double nd = nrm[0] * d[0] + nrm[1] * d[1] + nrm[2] * d[2];
      if (h * nd < 0)
      {
        tmax = std::min(tmax, -h / nd);
      }
    }
    return tmax < 1e300 ? tmax : 0.0;
  }

  // Trilinear central differences of the voxels at p, in value per lattice unit.
  void Gradient(const LatticePoint& p, double g[3]) const
  {
    const double S = static_cast<double>(BisectionMesh::Scale);
    const double c[3] = { p.x / S, p.y / S, p.z / S };
    for (int d = 0; d < 3; ++d)
    {
      double lo[3] = { c[0], c[1], c[2] }, hi[3] = { c[0], c[1], c[2] };
      lo[d] = std::max(0.0, c[d] - 1.0);
      hi[d] = std::min(double(Vol.Dims[d] - 1), c[d] + 1.0);
      g[d] = hi[d] > lo[d] ? (Sample(hi) - Sample(lo)) / ((hi[d] - lo[d]) * S) : 0.0;
    }
  }

  double Sample(const double c[3]) const
  {
    int i0[3];
    double f[3];
    for (int d = 0; d < 3; ++d)
    {
      i0[d] = std::min(Vol.Dims[d] - 2, std::max(0, static_cast<int>(std::floor(c[d]))));
      f[d] = c[d] - i0[d];
    }
    double s = 0;
    for (int k = 0; k < 8; ++k)
    {
      const int o[3] = { k & 1, (k >> 1) & 1, (k >> 2) & 1 };
      const double w = (o[0] ? f[0] : 1 - f[0]) * (o[1] ? f[1] : 1 - f[1]) * (o[2] ? f[2] : 1 - f[2]);
      const long long idx = (i0[0] + o[0]) + static_cast<long long>(Vol.Dims[0]) *
        ((i0[1] + o[1]) + static_cast<long long>(Vol.Dims[1]) * (i0[2] + o[2]));
      s += w * Vol.Value(idx);
    }
    return s;
  }

  // Tet t's fitted values at its corners with v's left out (0), and v's corner in t.
  int Others(int t, int v, double c[4]) const
  {
    int vi = 0;
    for (int a = 0; a < 4; ++a)
    {
      const int w = Mesh.Tet(t)[a];
      c[a] = w == v ? 0.0 : X[w];
      vi = w == v ? a : vi;
    }
    return vi;
  }

  // The star's squared error with v at q and its value refitted (the others fixed). With
  // `checked`, false when a tet would flip, flatten or fall below the quality floor.
  // `stride` 0: exactly, every voxel (TetRaster); -1: exactly at v's current place, from the
  // stored moments when unweighted; s > 0: screened on every s-th voxel per axis (ScreenRaster).
  bool Evaluate(int v, const LatticePoint& q, bool checked, Scratch& sc, double& err, double& value,
    int stride = 0) const
  {
    const std::vector<int>& Star = sc.Star;
    double srr = 0, srp = 0, spp = 0;
    long long count = 0;
    // Every tet is checked before any is rasterised: most rejected candidates cost no voxel.
    for (size_t i = 0; checked && i < Star.size(); ++i)
    {
      LatticePoint P[4];
      Corners(Star[i], v, q, P);
      const i128 o = Orient(P[0], P[1], P[2], P[3]);
      if (o == 0 || (o > 0) != (sc.Sign[i] > 0) || Quality(P) < std::min(Opt.QualityFloor, sc.QOld[i]))
      {
        return false;
      }
    }
    if (stride <= 0)
    {
      // Exact, from moments: the stored ones at v's place (stride -1), fresh ones elsewhere.
      sc.NewMoments.resize(Star.size() * NM);
      for (size_t i = 0; i < Star.size(); ++i)
      {
        const int t = Star[i];
        double c[4];
        const int vi = Others(t, v, c);
        const double* m = &Moments[static_cast<size_t>(t) * NM];
        if (stride == 0)
        {
          LatticePoint P[4];
          Corners(t, v, q, P);
          bool flat;
          TetMoments(P, &sc.NewMoments[i * NM], flat);
          if (flat)
          {
            return false;
          }
          m = &sc.NewMoments[i * NM];
        }
        AddFromMoments(m, c, vi, srr, srp, spp, count);
      }
    }
    // Screening: a floating-point raster of every stride-th voxel per axis.
    for (size_t i = 0; stride > 0 && i < Star.size(); ++i)
    {
      const int t = Star[i];
      LatticePoint P[4];
      Corners(t, v, q, P);
      double c[4];
      const int vi = Others(t, v, c);
      Vol.WithSamples([&](const auto* values) {
        auto add = [&](long long idx, const double* l) {
          const double res = values[idx] - (c[0] * l[0] + c[1] * l[1] + c[2] * l[2] + c[3] * l[3]);
          const double phi = l[vi];
          const double w = W.empty() ? 1.0 : W[idx];
          srr += w * res * res;
          srp += w * res * phi;
          spp += w * phi * phi;
          ++count;
        };
        ScreenRaster r;
        if (r.Setup(P, Vol.Dims))
        {
          r.ForEachVoxel(Vol.Dims, stride, add);
        }
      });
    }
    if (!(spp > 1e-12))
    {
      return false;
    }
    value = srp / spp;
    err = srr - srp * value;
    sc.Count = count;
    return true;
  }

  BisectionMesh& Mesh;
  const VoxelVolume& Vol;
  std::vector<double>& X;
  RelocationOptions Opt;
  const OpacityImportance* Imp;
  int64_t Max[3];
  double Spacing[3];
  double Scale2 = 1;
  mutable std::vector<double> Moments; // NM per tet, for the tets' current places
  std::vector<float> W;                // weighted: each voxel's weight, frozen at the fit relocated from
};
} // namespace

RelocationStats VertexRelocator::Relocate(BisectionMesh& mesh, const VoxelVolume& volume, std::vector<double>& x,
  const RelocationOptions& options, const OpacityImportance* importance, Progress* progress)
{
  const int nv = mesh.NumberOfVertices();
  if (static_cast<int>(x.size()) != nv)
  {
    throw Error("internal: relocation needs one value per vertex");
  }
  Relocator r(mesh, volume, x, options, importance);
  RelocationStats s;
  // The set-up's voxel passes (the weights when weighted, the moments) count half a sweep each:
  // on a large volume they take seconds, which the progress must show.
  const double passUnits = 0.5 * nv;
  if (progress)
  {
    progress->Begin("relocate", (importance ? 2 : 1) * passUnits + double(options.Sweeps) * nv);
  }
  if (options.MeasureSse)
  {
    s.SseBefore = r.TotalSse();
  }
  r.ComputeMoments(progress, passUnits);
  mesh.StopRefinement();
  // Vertices with no tet in common neither move nor read each other's place or value: each
  // colour class of the greedy colouring (in vertex order) is relaxed in parallel, with the same
  // result for any thread count.
  std::vector<int> colour(static_cast<size_t>(nv), -1), stamp;
  std::vector<std::vector<int>> classes;
  for (int v = 0; v < nv; ++v)
  {
    stamp.assign(classes.size() + 1, 0);
    for (int t : mesh.TetsAround(v))
    {
      for (int w : mesh.Tet(t))
      {
        if (colour[w] >= 0)
        {
          stamp[colour[w]] = 1;
        }
      }
    }
    int c = 0;
    while (stamp[c])
    {
      ++c;
    }
    colour[v] = c;
    if (c == static_cast<int>(classes.size()))
    {
      classes.emplace_back();
    }
    classes[c].push_back(v);
  }
  // Active set: a sweep visits the vertices that moved, or a neighbour of which moved, last sweep.
  std::vector<char> active(static_cast<size_t>(nv), 1), next(static_cast<size_t>(nv), 0), moved(static_cast<size_t>(nv), 0);
  for (int sweep = 0; sweep < options.Sweeps; ++sweep)
  {
    long long count = 0;
    for (const auto& cls : classes)
    {
      if (progress)
      {
        if (progress->Cancelled())
        {
          throw Error("cancelled");
        }
        progress->Advance(double(cls.size()));
      }
      ForEachRange(static_cast<long long>(cls.size()), 8, [&](long long b, long long e, Counters&) {
        Relocator::Scratch sc;
        for (long long i = b; i < e; ++i)
        {
          const int v = cls[i];
          moved[v] = active[v] && r.Visit(v, sc) ? 1 : 0;
        }
      });
    }
    std::fill(next.begin(), next.end(), 0);
    for (int v = 0; v < nv; ++v)
    {
      s.Visited += active[v];
      if (moved[v])
      {
        ++count;
        for (int t : mesh.TetsAround(v))
        {
          for (int w : mesh.Tet(t))
          {
            next[w] = 1;
          }
        }
      }
    }
    active.swap(next);
    s.Moved += count;
    ++s.Sweeps;
    if (count == 0)
    {
      break;
    }
  }
  if (options.MeasureSse)
  {
    s.SseAfter = r.TotalSse();
  }
  if (progress)
  {
    progress->End();
  }
  return s;
}
} // namespace art
