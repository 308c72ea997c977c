// Test meshes: a box of cubes split into tets two different ways (Kuhn's 6 or the alternating 5),
// optionally with cells left out (an L-shape, a hole), and a brute-force reference caster that
// intersects every tet with the ray and integrates the union of the pieces front to back; the
// linear field, transfer function and camera the caster's tests share.
#ifndef art_MeshFixtures_h
#define art_MeshFixtures_h

#include "Camera.h"
#include "ExactIntegrator.h"
#include "TetMesh.h"
#include "TransferFunction.h"

#include <vtkCamera.h>
#include <vtkNew.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace fixtures
{
using art::Vec3;

/// A linear field: every tetrahedralisation interpolates it exactly.
inline double Linear(const Vec3& p)
{
  return 0.3 + 0.2 * p.x - 0.1 * p.y + 0.15 * p.z;
}

/// Red rises, green falls, blue constant; constant opacity 0.3 per 0.5 units.
inline art::TransferFunction LinearTF(double lo, double hi)
{
  return art::TransferFunction({ { lo, { 0, 1, 0.5 }, 0.3, 0 }, { hi, { 1, 0, 0.5 }, 0.3, 0 } }, 0.5);
}

/// A w x h view of the box b from azimuth az and elevation el (degrees), framed with a margin.
inline art::Camera ViewOf(const art::Box3& b, int w, int h, double az, double el)
{
  vtkNew<vtkCamera> cam;
  cam->SetPosition(0, -1, 0);
  cam->SetFocalPoint(0, 0, 0);
  cam->SetViewUp(0, 0, 1);
  art::Camera::Frame(cam, b, az, el, 1.3);
  return art::Camera::FromVTK(cam, w, h);
}

inline art::TetMesh GridMesh(int nx, int ny, int nz, Vec3 origin, Vec3 h,
  const std::function<double(const Vec3&)>& f, int scheme,
  const std::function<bool(int, int, int)>& keep = {}, const std::function<Vec3(const Vec3&)>& warp = {})
{
  std::vector<Vec3> pts;
  std::vector<double> val;
  auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
      {
        Vec3 p = origin + Vec3(i * h.x, j * h.y, k * h.z);
        if (warp)
          p = warp(p);
        pts.push_back(p);
        val.push_back(f(p));
      }
  std::vector<std::array<int, 4>> tets;
  static const int kuhn[6][3] = { { 1, 2, 4 }, { 1, 4, 2 }, { 2, 1, 4 }, { 2, 4, 1 }, { 4, 1, 2 }, { 4, 2, 1 } };
  static const int five[5][4] = { { 0, 1, 2, 4 }, { 3, 1, 2, 7 }, { 5, 1, 4, 7 }, { 6, 2, 4, 7 }, { 1, 2, 4, 7 } };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        if (keep && !keep(i, j, k))
          continue;
        int c[8];
        for (int b = 0; b < 8; ++b)
          c[b] = id(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1));
        if (scheme == 6)
        {
          for (const auto& p : kuhn)
            tets.push_back({ c[0], c[p[0]], c[p[0] | p[1]], c[7] });
        }
        else
        {
          const int flip = ((i + j + k) & 1) ? 1 : 0; // mirror in x on odd cubes so diagonals match
          for (const auto& t : five)
            tets.push_back({ c[t[0] ^ flip], c[t[1] ^ flip], c[t[2] ^ flip], c[t[3] ^ flip] });
        }
      }
  return art::TetMesh(std::move(pts), std::move(val), std::move(tets));
}

/// Every tet clipped by its four planes (and the ray by its [tmin, tmax]); the union of the
/// pieces integrated once, front to back.
inline art::RayAccum BruteForce(const art::TetMesh& m, const art::TransferFunction& tf, const art::Ray& r,
  double ert = 2.0)
{
  struct Piece
  {
    double t0, t1;
    std::size_t tet;
  };
  std::vector<Piece> pieces;
  for (std::size_t t = 0; t < m.NumberOfTets(); ++t)
  {
    double t0 = r.tmin, t1 = std::min(r.tmax, 1e300);
    bool ok = true;
    for (int f = 0; f < 4 && ok; ++f)
    {
      const auto pl = m.FacePlane(t, f);
      const double dn = Dot(pl.n, r.dir), dist = pl.d - Dot(pl.n, r.org);
      if (dn == 0)
        ok = dist >= 0;
      else if (dn > 0)
        t1 = std::min(t1, dist / dn);
      else
        t0 = std::max(t0, dist / dn);
    }
    if (ok && t1 > t0 + 1e-12)
      pieces.push_back({ t0, t1, t });
  }
  std::sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.t0 < b.t0; });
  art::ExactIntegrator in(tf);
  art::RayAccum acc;
  double tc = -1e300;
  const double len = Length(r.dir);
  for (const Piece& p : pieces)
  {
    if (p.t1 <= tc)
      continue;
    const double a = std::max(p.t0, tc);
    in.Integrate(m.Evaluate(p.tet, r.At(a)), m.Evaluate(p.tet, r.At(p.t1)), (p.t1 - a) * len, acc);
    tc = p.t1;
    if (acc.Alpha() >= ert)
      break;
  }
  return acc;
}
/// A smooth field for the stability tests.
inline double Wavy(const Vec3& p)
{
  return 0.5 + 0.3 * std::sin(2.1 * p.x + 0.3) * std::cos(1.7 * p.y) + 0.2 * p.z;
}

/// A 5 x 5 x 4 grid (five tets a cell) with one layer of cells squashed to 1e-7 and the rest
/// jittered: needles and slivers everywhere.
inline art::TetMesh SliverMesh()
{
  auto warp = [](const Vec3& p) {
    Vec3 q = p;
    if (p.z > 1.01)
      q.z = p.z - 0.5 + 1e-7;
    q.x += 0.03 * std::sin(7 * p.y + 3 * p.z);
    return q;
  };
  return GridMesh(5, 5, 4, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 5, {}, warp);
}
} // namespace fixtures

#endif
