// WatertightTest: the watertight ray/triangle test of Woop, Benthin & Wald, "Watertight
// Ray/Triangle Intersection" (JCGT 2(1), 2013), in double precision on the store's float vertices
// (one triangle; TriangleKernels.h tests a voxel's triangles in batches), plus what every
// accelerator's traversal shares per ray: the set-up, the coplanar cull and a small mailbox.
#ifndef art_WatertightTest_h
#define art_WatertightTest_h

#include "Box3.h"
#include "Ray.h"
#include "TriangleKernels.h"
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
  ShearedRay s; ///< what the triangle test needs

  explicit RayPrep(const Ray& r)
  {
    for (int a = 0; a < 3; ++a)
    {
      org[a] = r.org[a];
      dir[a] = r.dir[a];
      inv[a] = 1.0 / dir[a]; // +-0 gives +-inf, which the slab and DDA code expect
    }
    const double ax = std::fabs(dir[0]), ay = std::fabs(dir[1]), az = std::fabs(dir[2]);
    const int kz = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (dir[kz] < 0)
    {
      std::swap(kx, ky); // keep the winding, so the sign of det says which side was hit
    }
    // 1 / dir[kz] is inv[kz]: one division fewer per ray.
    s = ShearedRay{ org[kx], org[ky], org[kz], dir[kx] / dir[kz], dir[ky] / dir[kz], inv[kz], kx, ky, kz };
  }

  /// 1 / |dir| (only all-hits queries need it).
  double InvLength() const { return 1.0 / std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]); }

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
inline bool IntersectTriangle(const ShearedRay& r, const float* xyz, const TriangleRecord& t, double tmin,
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

/// A batch one triangle at a time (TriangleKernels.h's scalar kernel; inlined into the queries
/// for batches too small for the wide kernels). Closest keeps the nearest hit with t in
/// [tmin, best.t], of equal t the lowest record.
inline void ClosestOfBatch(const ShearedRay& r, const TriangleRecord* rec, const float* xyz, const std::uint32_t* ids,
  int n, double tmin, NearestSoFar& best)
{
  for (int k = 0; k < n; ++k)
  {
    double t, u, v;
    const long long id = ids[k];
    if (IntersectTriangle(r, xyz, rec[id], tmin, best.t, t, u, v) && (t < best.t || best.record < 0 || id < best.record))
    {
      best = NearestSoFar{ t, u, v, id };
    }
  }
}

inline bool AnyOfBatch(const ShearedRay& r, const TriangleRecord* rec, const float* xyz, const std::uint32_t* ids, int n,
  double tmin, double tmax)
{
  for (int k = 0; k < n; ++k)
  {
    double t, u, v;
    if (IntersectTriangle(r, xyz, rec[ids[k]], tmin, tmax, t, u, v))
    {
      return true;
    }
  }
  return false;
}

inline int AllOfBatch(const ShearedRay& r, const TriangleRecord* rec, const float* xyz, const std::uint32_t* ids, int n,
  double tmin, double tmax, BatchHits& out)
{
  int found = 0;
  for (int k = 0; k < n; ++k)
  {
    if (IntersectTriangle(r, xyz, rec[ids[k]], tmin, tmax, out.t[found], out.u[found], out.v[found]))
    {
      out.record[found++] = ids[k];
    }
  }
  return found;
}

/// Culls the triangles of a shared plane with one ray/plane distance: when the ray crosses the
/// plane outside [lo, hi] (by more than a margin of 1e-5 of the scene's diagonal, far above the
/// coplanarity tolerance and the float plane's rounding), none of them can be hit in [lo, hi].
/// The crossing tp = num / den is kept as num sign(den) and |den|, so that a test against a
/// shrinking hi is two products and no division: tp > hi + M / |den| is num s > hi |den| + M.
/// A ray parallel to the plane (den = 0) culls nothing.
class PlaneCull
{
public:
  PlaneCull(const TriangleStore& s, const RayPrep& p)
    : Planes(s.Planes().data())
    , P(p)
    , Margin(1e-5 * s.Bounds().Diagonal())
  {
  }
  bool Outside(std::uint32_t plane, double lo, double hi)
  {
    if (plane == TriangleRecord::NoPlane)
    {
      return false;
    }
    if (plane != Last)
    {
      Last = plane;
      const PlaneRecord& pl = Planes[plane];
      const double den = double(pl.n[0]) * P.dir[0] + double(pl.n[1]) * P.dir[1] + double(pl.n[2]) * P.dir[2];
      const double num = double(pl.d) - (double(pl.n[0]) * P.org[0] + double(pl.n[1]) * P.org[1] + double(pl.n[2]) * P.org[2]);
      AbsDen = std::fabs(den);
      Num = den > 0 ? num : (den < 0 ? -num : 0.0);
    }
    else if (hi == Hi)
    {
      return Out; // the next triangle of the same plane
    }
    Hi = hi;
    Out = Num > hi * AbsDen + Margin || Num < lo * AbsDen - Margin;
    return Out;
  }

private:
  const PlaneRecord* Planes;
  const RayPrep& P;
  double Margin;
  std::uint32_t Last = TriangleRecord::NoPlane;
  double Num = 0, AbsDen = 0, Hi = 0;
  bool Out = false;
};

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
