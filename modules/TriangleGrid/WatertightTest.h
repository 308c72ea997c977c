// WatertightTest: the watertight ray/triangle test of Woop, Benthin & Wald, "Watertight
// Ray/Triangle Intersection" (JCGT 2(1), 2013), in double precision on the store's float vertices,
// plus the per-ray set-up and a small mailbox shared by every accelerator's traversal.
#ifndef art_WatertightTest_h
#define art_WatertightTest_h

#include "Box3.h"
#include "Ray.h"
#include "TriangleStore.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace art
{
/// Per-ray constants: the shear of Woop et al. (section 3), the reciprocal direction for the DDA,
/// and origin and direction as plain arrays (indexed by axis in the inner loops).
struct RayPrep
{
  double org[3], dir[3], inv[3];
  int kx = 0, ky = 1, kz = 2;
  double Ox = 0, Oy = 0, Oz = 0; ///< the origin permuted: org[kx], org[ky], org[kz]
  double Sx = 0, Sy = 0, Sz = 1;
  double invLen = 1; ///< 1 / |dir|

  explicit RayPrep(const Ray& r)
  {
    for (int a = 0; a < 3; ++a)
    {
      org[a] = r.org[a];
      dir[a] = r.dir[a];
      inv[a] = 1.0 / dir[a]; // +-0 gives +-inf, which the slab and DDA code expect
    }
    const double ax = std::fabs(dir[0]), ay = std::fabs(dir[1]), az = std::fabs(dir[2]);
    kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (dir[kz] < 0)
    {
      std::swap(kx, ky); // keep the winding, so the sign of det says which side was hit
    }
    Ox = org[kx];
    Oy = org[ky];
    Oz = org[kz];
    Sx = dir[kx] / dir[kz];
    Sy = dir[ky] / dir[kz];
    Sz = 1.0 / dir[kz];
    invLen = 1.0 / std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  }

  /// Clips [tmin, tmax] to the box as Box3::Clip does (a zero direction component keeps the
  /// interval when the origin lies within that slab). False when the ray misses it.
  bool Clip(const Box3& b, double tmin, double tmax, double& t0, double& t1) const
  {
    t0 = tmin;
    t1 = tmax;
    for (int a = 0; a < 3; ++a)
    {
      if (dir[a] == 0.0)
      {
        if (org[a] < b.lo[a] || org[a] > b.hi[a])
        {
          return false;
        }
        continue;
      }
      double ta = (b.lo[a] - org[a]) * inv[a], tb = (b.hi[a] - org[a]) * inv[a];
      if (ta > tb)
      {
        std::swap(ta, tb);
      }
      t0 = std::max(t0, ta);
      t1 = std::min(t1, tb);
      if (!(t0 <= t1))
      {
        return false;
      }
    }
    return true;
  }
};

/// Tests one record against the store's float vertices `xyz`; accepts t in [tmin, tmax]. u, v weight vertices 1 and 2.
/// Edge functions are computed per vertex pair from per-vertex values, so the two triangles of a
/// shared edge get exactly opposite values and a ray can never pass between them. The module is
/// compiled with -ffp-contract=off so no fused multiply-add breaks that symmetry.
inline bool IntersectTriangle(const RayPrep& r, const float* xyz, const TriangleRecord& t, double tmin,
  double tmax, double& tHit, double& u, double& v)
{
  const float *A = xyz + 3 * size_t(t.v[0]), *B = xyz + 3 * size_t(t.v[1]), *C = xyz + 3 * size_t(t.v[2]);
  const double Ax0 = double(A[r.kx]) - r.Ox, Ay0 = double(A[r.ky]) - r.Oy, Az0 = double(A[r.kz]) - r.Oz;
  const double Bx0 = double(B[r.kx]) - r.Ox, By0 = double(B[r.ky]) - r.Oy, Bz0 = double(B[r.kz]) - r.Oz;
  const double Cx0 = double(C[r.kx]) - r.Ox, Cy0 = double(C[r.ky]) - r.Oy, Cz0 = double(C[r.kz]) - r.Oz;
  const double Ax = Ax0 - r.Sx * Az0, Ay = Ay0 - r.Sy * Az0;
  const double Bx = Bx0 - r.Sx * Bz0, By = By0 - r.Sy * Bz0;
  const double Cx = Cx0 - r.Sx * Cz0, Cy = Cy0 - r.Sy * Cz0;
  const double U = Cx * By - Cy * Bx;
  const double V = Ax * Cy - Ay * Cx;
  const double W = Bx * Ay - By * Ax;
  if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0))
  {
    return false;
  }
  const double det = U + V + W;
  if (det == 0.0)
  {
    return false; // the ray lies in the triangle's plane, or the triangle is degenerate
  }
  const double T = U * (r.Sz * Az0) + V * (r.Sz * Bz0) + W * (r.Sz * Cz0);
  const double th = T / det;
  if (!(th >= tmin && th <= tmax))
  {
    return false;
  }
  tHit = th;
  u = V / det;
  v = W / det;
  return true;
}

/// A direct-mapped mailbox (one per ray): skips re-testing a triangle met in the previous voxels.
/// A collision only costs a repeated test; queries are correct without it.
struct Mailbox
{
  static constexpr int Slots = 32;
  std::uint32_t id[Slots];
  Mailbox() { std::memset(id, 0xff, sizeof(id)); }
  /// True when `t` was already tested; records it otherwise.
  bool Seen(std::uint32_t t)
  {
    std::uint32_t& s = id[t & (Slots - 1)];
    if (s == t)
    {
      return true;
    }
    s = t;
    return false;
  }
};
} // namespace art

#endif
