// The batch triangle test written once over a lane type L (TriangleKernelsAVX2.cxx includes it,
// compiled for its instructions; another width is one more lane type). Everything here has
// internal linkage, so it never meets code compiled without those instructions. L supplies: W (lanes), D (W doubles),
// I (W 32-bit integers), Ids(ids, m) (lanes past m repeat the first), Gather(base, index),
// Coords(xyz, index) (floats widened to double), Set(x), Times3(i), Plus(i, k), Bits for the
// comparisons Lt, Gt, Eq, Ge, Le (one bit per lane) and Store(p, d).
#ifndef art_TriangleKernelsSimd_h
#define art_TriangleKernelsSimd_h

#include "TriangleKernels.h"

namespace
{
using art::BatchHits;
using art::NearestSoFar;
using art::ShearedRay;

/// Fewer triangles than this go to the scalar test: filling lanes for one or two costs more than
/// it saves.
constexpr int MinLanes = 3;

/// Tests ids[0..m) (m <= W); returns the bits of the lanes hit with t in [tmin, tmax] and their
/// t, u, v. The operations of WatertightTest.h's IntersectTriangle, in its order.
template <class L>
inline unsigned TestLanes(const ShearedRay& r, const std::uint32_t* records, const float* xyz,
  const std::uint32_t* ids, int m, double tmin, double tmax, typename L::D& th, typename L::D& uu, typename L::D& vv)
{
  using D = typename L::D;
  const auto base = L::Times4(L::Ids(ids, m));
  const auto a = L::Times3(L::Gather(records, base)), b = L::Times3(L::Gather(records, L::Plus(base, 1))),
             c = L::Times3(L::Gather(records, L::Plus(base, 2)));
  const D Ox = L::Set(r.Ox), Oy = L::Set(r.Oy), Oz = L::Set(r.Oz);
  const D Ax0 = L::Coords(xyz, L::Plus(a, r.kx)) - Ox, Ay0 = L::Coords(xyz, L::Plus(a, r.ky)) - Oy,
          Az0 = L::Coords(xyz, L::Plus(a, r.kz)) - Oz;
  const D Bx0 = L::Coords(xyz, L::Plus(b, r.kx)) - Ox, By0 = L::Coords(xyz, L::Plus(b, r.ky)) - Oy,
          Bz0 = L::Coords(xyz, L::Plus(b, r.kz)) - Oz;
  const D Cx0 = L::Coords(xyz, L::Plus(c, r.kx)) - Ox, Cy0 = L::Coords(xyz, L::Plus(c, r.ky)) - Oy,
          Cz0 = L::Coords(xyz, L::Plus(c, r.kz)) - Oz;
  const D Sx = L::Set(r.Sx), Sy = L::Set(r.Sy), Sz = L::Set(r.Sz), zero = L::Set(0.0);
  const D Ax = Ax0 - Sx * Az0, Ay = Ay0 - Sy * Az0;
  const D Bx = Bx0 - Sx * Bz0, By = By0 - Sy * Bz0;
  const D Cx = Cx0 - Sx * Cz0, Cy = Cy0 - Sy * Cz0;
  const D U = Cx * By - Cy * Bx;
  const D V = Ax * Cy - Ay * Cx;
  const D W = Bx * Ay - By * Ax;
  const unsigned negative = L::Lt(U, zero) | L::Lt(V, zero) | L::Lt(W, zero);
  const unsigned positive = L::Gt(U, zero) | L::Gt(V, zero) | L::Gt(W, zero);
  const D det = U + V + W;
  unsigned ok = ~(negative & positive) & ~L::Eq(det, zero) & ((1u << m) - 1);
  if (!ok)
  {
    return 0;
  }
  const D T = U * (Sz * Az0) + V * (Sz * Bz0) + W * (Sz * Cz0);
  th = T / det;
  ok &= L::Ge(th, L::Set(tmin)) & L::Le(th, L::Set(tmax));
  uu = V / det;
  vv = W / det;
  return ok;
}

template <class L>
void ClosestLanes(const ShearedRay& r, const std::uint32_t* records, const float* xyz, const std::uint32_t* ids,
  int n, double tmin, NearestSoFar& best)
{
  for (int k = 0; k < n; k += L::W)
  {
    const int m = n - k < L::W ? n - k : L::W;
    if (m < MinLanes)
    {
      art::TriangleKernelScalar().closest(r, records, xyz, ids + k, m, tmin, best);
      return;
    }
    typename L::D th, uu, vv;
    unsigned ok = TestLanes<L>(r, records, xyz, ids + k, m, tmin, best.t, th, uu, vv);
    if (!ok)
    {
      continue;
    }
    alignas(64) double t[L::W], u[L::W], v[L::W];
    L::Store(t, th);
    L::Store(u, uu);
    L::Store(v, vv);
    // In lane order, as the scalar test meets them: nearer, or as near and a lower record.
    for (; ok; ok &= ok - 1)
    {
      const int l = __builtin_ctz(ok);
      const long long id = ids[k + l];
      if (t[l] <= best.t && (t[l] < best.t || best.record < 0 || id < best.record))
      {
        best = NearestSoFar{ t[l], u[l], v[l], id };
      }
    }
  }
}

template <class L>
bool AnyLanes(const ShearedRay& r, const std::uint32_t* records, const float* xyz, const std::uint32_t* ids, int n,
  double tmin, double tmax)
{
  for (int k = 0; k < n; k += L::W)
  {
    if (n - k < MinLanes)
    {
      return art::TriangleKernelScalar().any(r, records, xyz, ids + k, n - k, tmin, tmax);
    }
    typename L::D th, uu, vv;
    if (TestLanes<L>(r, records, xyz, ids + k, n - k < L::W ? n - k : L::W, tmin, tmax, th, uu, vv))
    {
      return true;
    }
  }
  return false;
}

template <class L>
int AllLanes(const ShearedRay& r, const std::uint32_t* records, const float* xyz, const std::uint32_t* ids, int n,
  double tmin, double tmax, BatchHits& out)
{
  int found = 0;
  for (int k = 0; k < n; k += L::W)
  {
    if (n - k < MinLanes)
    {
      BatchHits rest;
      const int more = art::TriangleKernelScalar().all(r, records, xyz, ids + k, n - k, tmin, tmax, rest);
      for (int i = 0; i < more; ++i, ++found)
      {
        out.t[found] = rest.t[i];
        out.u[found] = rest.u[i];
        out.v[found] = rest.v[i];
        out.record[found] = rest.record[i];
      }
      return found;
    }
    typename L::D th, uu, vv;
    unsigned ok = TestLanes<L>(r, records, xyz, ids + k, n - k < L::W ? n - k : L::W, tmin, tmax, th, uu, vv);
    if (!ok)
    {
      continue;
    }
    alignas(64) double t[L::W], u[L::W], v[L::W];
    L::Store(t, th);
    L::Store(u, uu);
    L::Store(v, vv);
    for (; ok; ok &= ok - 1)
    {
      const int l = __builtin_ctz(ok);
      out.t[found] = t[l];
      out.u[found] = u[l];
      out.v[found] = v[l];
      out.record[found] = ids[k + l];
      ++found;
    }
  }
  return found;
}
} // namespace

#endif
