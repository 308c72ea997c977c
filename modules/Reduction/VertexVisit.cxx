#include "VertexVisit.h"

#include "VoxelRaster.h"

#include <algorithm>
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
} // namespace

VertexVisit::VertexVisit(BisectionMesh& mesh, const VoxelVolume& volume, std::vector<double>& x,
  const RelocationOptions& options, RelocationMoments& moments)
  : Mesh(mesh)
  , Vol(volume)
  , X(x)
  , Opt(options)
  , Moments(moments)
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

bool VertexVisit::Visit(int v, Scratch& sc) const
{
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
  PrepareStar(v, p, sc);
  double best, bestValue;
  sc.LastQ.x = -1; // no place evaluated exactly yet in this visit
  if (!Evaluate(v, p, false, sc, best, bestValue, -1))
  {
    return false;
  }
  X[v] = bestValue; // the vertex's own best value at its place: never worse
  if (best <= 1e-20 * Scale2 * sc.Count)
  {
    return false; // the star already fits its voxels
  }
  const int stride = ScreenStride(sc.Count);
  double screenAt, unusedValue;
  if (!Evaluate(v, p, false, sc, screenAt, unusedValue, stride))
  {
    return false;
  }
  ScreenCandidates(v, p, fixed, stride, screenAt, sc);
  // The best screened candidates, evaluated exactly.
  LatticePoint bestP = p;
  for (size_t i = 0; i < sc.Top.size(); ++i)
  {
    const LatticePoint& q = sc.Top[i].second;
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
  for (size_t i = 0; i < sc.Star.size(); ++i)
  {
    std::copy_n(&sc.NewMoments[i * RelocationMoments::NM], RelocationMoments::NM, Moments.Of(sc.Star[i]));
  }
  Mesh.MoveVertex(v, bestP);
  X[v] = bestValue;
  return true;
}

void VertexVisit::PrepareStar(int v, const LatticePoint& p, Scratch& sc) const
{
  // The star's tets, their orientation and shape before the move.
  sc.Star = Mesh.TetsAround(v);
  const size_t n = sc.Star.size();
  sc.Sign.resize(n);
  sc.QOld.resize(n);
  for (size_t i = 0; i < n; ++i)
  {
    LatticePoint P[4];
    Corners(sc.Star[i], v, p, P);
    const i128 o = Orient(P[0], P[1], P[2], P[3]);
    sc.Sign[i] = o > 0 ? 1 : -1;
    sc.QOld[i] = Quality(P);
  }
}

int VertexVisit::ScreenStride(long long voxels) const
{
  // Candidates are screened on a subsample of the star's voxels (every s-th per axis, s chosen
  // so that enough remain); only the best few are evaluated exactly.
  int stride = std::max(1, Opt.ScreenStride);
  if (Opt.ScreenStride <= 0)
  {
    while (stride < 3 && voxels >= static_cast<long long>(Opt.ScreenVoxels) * (stride + 1) * (stride + 1) * (stride + 1))
    {
      ++stride;
    }
  }
  return stride;
}

std::vector<std::array<double, 3>> VertexVisit::Directions(const LatticePoint& p, const Scratch& sc) const
{
  // Candidate directions, in lattice units: +- the voxel gradient, +- each axis, toward the
  // star's centroid.
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
  for (int t : sc.Star)
  {
    for (int a = 0; a < 4; ++a)
    {
      const LatticePoint& q = Mesh.Vertex(Mesh.Tet(t)[a]);
      cen[0] += q.x, cen[1] += q.y, cen[2] += q.z;
    }
  }
  const double n = static_cast<double>(sc.Star.size());
  dirs.push_back({ cen[0] / (4.0 * n) - p.x, cen[1] / (4.0 * n) - p.y, cen[2] / (4.0 * n) - p.z });
  return dirs;
}

void VertexVisit::ScreenCandidates(
  int v, const LatticePoint& p, const bool fixed[3], int stride, double screenAt, Scratch& sc) const
{
  // Each direction at 0.3 of the distance that would flatten a tet of the star, then half and
  // 1.5 times the best of these; the best screened candidates kept in sc.Top, best first (ties
  // keep the earlier one: deterministic).
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
  std::vector<std::array<double, 3>> dirs = Directions(p, sc);
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
    const double tmax = Reach(v, p, d.data(), sc.Star);
    screen(d, 0.3 * tmax);
  }
  if (!top.empty())
  {
    // Coarse to fine: either side of the best step along its direction.
    const std::array<double, 3> d = bestDir;
    const double step = bestStep;
    screen(d, 0.5 * step);
    screen(d, 1.5 * step);
  }
}

void VertexVisit::Corners(int t, int v, const LatticePoint& at, LatticePoint P[4]) const
{
  for (int a = 0; a < 4; ++a)
  {
    const int w = Mesh.Tet(t)[a];
    P[a] = w == v ? at : Mesh.Vertex(w);
  }
}

// 6 sqrt(2) V / l_rms^3 in world units: 1 for the regular tet, 0 when flat.
double VertexVisit::Quality(const LatticePoint P[4]) const
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
double VertexVisit::Reach(int v, const LatticePoint& p, const double d[3], const std::vector<int>& star) const
{
  double tmax = 1e300;
  for (int t : star)
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
void VertexVisit::Gradient(const LatticePoint& p, double g[3]) const
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

double VertexVisit::Sample(const double c[3]) const
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
int VertexVisit::Others(int t, int v, double c[4]) const
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
// stored moments; s > 0: screened on every s-th voxel per axis (ScreenRaster).
bool VertexVisit::Evaluate(int v, const LatticePoint& q, bool checked, Scratch& sc, double& err, double& value,
  int stride) const
{
  const std::vector<int>& Star = sc.Star;
  const std::vector<float>& W = Moments.Weights();
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
    sc.NewMoments.resize(Star.size() * RelocationMoments::NM);
    for (size_t i = 0; i < Star.size(); ++i)
    {
      const int t = Star[i];
      double c[4];
      const int vi = Others(t, v, c);
      const double* m = Moments.Of(t);
      if (stride == 0)
      {
        LatticePoint P[4];
        Corners(t, v, q, P);
        if (!Moments.OfTet(P, &sc.NewMoments[i * RelocationMoments::NM]))
        {
          return false;
        }
        m = &sc.NewMoments[i * RelocationMoments::NM];
      }
      RelocationMoments::AddStarTerms(m, c, vi, srr, srp, spp, count);
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
  // The best value, kept within the data's range: where v's hat is small on every voxel of its
  // star (tets holding one voxel centre or none) the unconstrained value runs to many times the
  // range, and the refit, anchored to it on those tets, keeps it.
  value = std::min(Vol.Range[1], std::max(Vol.Range[0], srp / spp));
  err = srr - 2.0 * srp * value + spp * value * value;
  sc.Count = count;
  return true;
}
} // namespace art
