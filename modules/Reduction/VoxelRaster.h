// VoxelRaster: which voxel centres lie in a tet, found by scanning the tet's bounding box row by
// row with exact integer plane tests (not by point location). A centre on a shared face goes to
// exactly one tet: ties are broken by simulation of simplicity along the direction (1, e, e^2).
#ifndef art_VoxelRaster_h
#define art_VoxelRaster_h

#include "BisectionMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace art
{
class TetRaster
{
public:
  using i128 = __int128;

  /// Plane equations of the four faces, oriented inwards. False for a flat tet.
  bool Setup(const LatticePoint P[4])
  {
    for (int f = 0; f < 4; ++f)
    {
      const LatticePoint &a = P[(f + 1) & 3], &b = P[(f + 2) & 3], &c = P[(f + 3) & 3];
      const int64_t ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
      const int64_t vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
      int64_t n[3] = { uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx };
      i128 off = -(i128(n[0]) * a.x + i128(n[1]) * a.y + i128(n[2]) * a.z);
      i128 at = i128(n[0]) * P[f].x + i128(n[1]) * P[f].y + i128(n[2]) * P[f].z + off;
      if (at == 0)
      {
        return false;
      }
      if (at < 0)
      {
        n[0] = -n[0], n[1] = -n[1], n[2] = -n[2], off = -off, at = -at;
      }
      for (int d = 0; d < 3; ++d)
      {
        N[f][d] = n[d];
      }
      C[f] = off;
      V[f] = at;
    }
    for (int d = 0; d < 3; ++d)
    {
      int64_t lo = P[0][d], hi = P[0][d];
      for (int v = 1; v < 4; ++v)
      {
        lo = std::min(lo, P[v][d]);
        hi = std::max(hi, P[v][d]);
      }
      Lo[d] = FloorDiv(lo, BisectionMesh::Scale);
      Hi[d] = FloorDiv(hi, BisectionMesh::Scale);
    }
    return true;
  }

  /// Calls f(voxelIndex, lambda[4]) for every voxel centre of a dims[0] x dims[1] x dims[2]
  /// grid (index i + nx*(j + ny*k)) owned by this tet; lambda are its barycentric coordinates.
  template <class F>
  void ForEachVoxel(const int dims[3], F&& f) const
  {
    const int64_t S = BisectionMesh::Scale;
    const int i0 = static_cast<int>(std::max<int64_t>(0, Lo[0]));
    const int i1 = static_cast<int>(std::min<int64_t>(dims[0] - 1, Hi[0]));
    const int j0 = static_cast<int>(std::max<int64_t>(0, Lo[1]));
    const int j1 = static_cast<int>(std::min<int64_t>(dims[1] - 1, Hi[1]));
    const int k0 = static_cast<int>(std::max<int64_t>(0, Lo[2]));
    const int k1 = static_cast<int>(std::min<int64_t>(dims[2] - 1, Hi[2]));
    double invV[4];
    for (int q = 0; q < 4; ++q)
    {
      invV[q] = 1.0 / static_cast<double>(V[q]);
    }
    for (int k = k0; k <= k1; ++k)
    {
      const int sz = (k == dims[2] - 1) ? -1 : 1; // the tie direction must point into the box
      for (int j = j0; j <= j1; ++j)
      {
        const int sy = (j == dims[1] - 1) ? -1 : 1;
        i128 A[4], B[4];
        i128 lo = i0, hi = std::min(i1, dims[0] - 2);
        for (int q = 0; q < 4; ++q)
        {
          B[q] = i128(N[q][0]) * S;
          A[q] = i128(N[q][1]) * (int64_t(j) * S) + i128(N[q][2]) * (int64_t(k) * S) + C[q];
          if (B[q] > 0) // sx = +1 and n.x > 0: a zero counts as inside
          {
            lo = std::max<i128>(lo, FirstNonNegative(A[q], B[q], i0 - 1, i1 + 1));
          }
          else if (B[q] < 0)
          {
            hi = std::min<i128>(hi, FirstNonNegative(-A[q], -B[q], i0 - 1, i1 + 1) - 1);
          }
          else if (!(A[q] > 0 || (A[q] == 0 && Tie(0, N[q][1] * sy, N[q][2] * sz))))
          {
            hi = lo - 1;
          }
        }
        const long long rowBase = static_cast<long long>(dims[0]) * (j + static_cast<long long>(dims[1]) * k);
        if (lo <= hi)
        {
          const int ilo = static_cast<int>(lo), ihi = static_cast<int>(hi);
          double l[4], dl[4];
          for (int q = 0; q < 4; ++q)
          {
            l[q] = ToDouble(A[q] + B[q] * ilo) * invV[q];
            dl[q] = ToDouble(B[q]) * invV[q];
          }
          for (int i = ilo; i <= ihi; ++i)
          {
            const double s = i - ilo;
            const double lam[4] = { l[0] + s * dl[0], l[1] + s * dl[1], l[2] + s * dl[2],
              l[3] + s * dl[3] };
            f(rowBase + i, lam);
          }
        }
        const int last = dims[0] - 1; // the last column ties toward -x
        if (i1 == last)
        {
          bool in = true;
          double lam[4];
          for (int q = 0; q < 4 && in; ++q)
          {
            const i128 D = A[q] + B[q] * last;
            in = D > 0 || (D == 0 && Tie(-N[q][0], N[q][1] * sy, N[q][2] * sz));
            lam[q] = ToDouble(D) * invV[q];
          }
          if (in)
          {
            f(rowBase + last, lam);
          }
        }
      }
    }
  }

  /// Six times the tet's volume in lattice units (the same for every face).
  i128 SixVolume() const { return V[0]; }
  /// Gradient of barycentric q in voxel index units.
  void Gradient(int q, double g[3]) const
  {
    for (int d = 0; d < 3; ++d)
    {
      g[d] = static_cast<double>(N[q][d]) * static_cast<double>(BisectionMesh::Scale) /
        static_cast<double>(V[q]);
    }
  }

private:
  static int64_t FloorDiv(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
  // The smallest x in [L, H] with a + b x >= 0 (b > 0), or L / H when it lies below / above:
  // a floating-point guess corrected by exact products (no 128-bit division per row). Clamped,
  // it bounds a row [L + 1, H - 1] exactly as the unclamped ceiling would.
  static i128 FirstNonNegative(i128 a, i128 b, int64_t L, int64_t H)
  {
    double g = std::ceil(-ToDouble(a) / ToDouble(b));
    g = g >= double(L) ? (g <= double(H) ? g : double(H)) : double(L);
    i128 x = static_cast<int64_t>(g);
    while (x > L && a + b * (x - 1) >= 0)
    {
      --x;
    }
    while (x < H && a + b * x < 0)
    {
      ++x;
    }
    return x;
  }
  // Correctly rounded either way; the 64-bit conversion is inline, the 128-bit one a call.
  static double ToDouble(i128 a)
  {
    constexpr i128 lim = i128(1) << 62;
    return (a < lim && a > -lim) ? static_cast<double>(static_cast<int64_t>(a)) : static_cast<double>(a);
  }
  // Sign of the first non-zero component: is the perturbed point on the inner side?
  static bool Tie(int64_t x, int64_t y, int64_t z) { return x != 0 ? x > 0 : (y != 0 ? y > 0 : z > 0); }

  int64_t N[4][3];
  i128 C[4], V[4];
  int64_t Lo[3], Hi[3];
};
} // namespace art

#endif
