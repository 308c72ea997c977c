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
        Nd[f][d] = static_cast<double>(n[d]);
      }
      C[f] = off;
      Cd[f] = ToDouble(off);
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
  /// With `stride` s > 1, only the centres whose i, j and k are all multiples of s (a subsample
  /// fixed on the grid, so tets sharing a face still split it exactly).
  template <class F>
  void ForEachVoxel(const int dims[3], F&& f, int stride = 1) const
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
    const int st = std::max(1, stride);
    for (int k = RoundUp(k0, st); k <= k1; k += st)
    {
      const int sz = (k == dims[2] - 1) ? -1 : 1; // the tie direction must point into the box
      for (int j = RoundUp(j0, st); j <= j1; j += st)
      {
        const int sy = (j == dims[1] - 1) ? -1 : 1;
        // The row's span in floating point first, widened by its rounding bound and a voxel:
        // rows of the bounding box that miss the tet (most of them) cost no 128-bit product, and
        // the others start the exact search from these guesses.
        double guess[4], flo = i0 - 1.0, fhi = i1 + 1.0;
        const double js = double(int64_t(j) * S), ks = double(int64_t(k) * S);
        for (int q = 0; q < 4; ++q)
        {
          const double t1 = Nd[q][1] * js, t2 = Nd[q][2] * ks;
          const double ad = t1 + t2 + Cd[q], bd = Nd[q][0] * double(S);
          const double slack = 1e-14 * (std::fabs(t1) + std::fabs(t2) + std::fabs(Cd[q]));
          if (bd != 0)
          {
            guess[q] = -ad / bd;
            const double w = 1.0 + slack / std::fabs(bd);
            if (bd > 0)
            {
              flo = std::max(flo, guess[q] - w);
            }
            else
            {
              fhi = std::min(fhi, guess[q] + w);
            }
          }
          else if (ad < -slack)
          {
            flo = fhi + 1;
          }
        }
        if (flo > fhi || flo > i1 || fhi < i0)
        {
          continue;
        }
        i128 A[4], B[4];
        i128 lo = i0, hi = std::min(i1, dims[0] - 2);
        for (int q = 0; q < 4; ++q)
        {
          B[q] = i128(N[q][0]) * S;
          A[q] = i128(N[q][1]) * (int64_t(j) * S) + i128(N[q][2]) * (int64_t(k) * S) + C[q];
          if (B[q] > 0) // sx = +1 and n.x > 0: a zero counts as inside
          {
            lo = std::max<i128>(lo, FirstNonNegative(A[q], B[q], i0 - 1, i1 + 1, guess[q]));
          }
          else if (B[q] < 0)
          {
            hi = std::min<i128>(hi, FirstNonNegative(-A[q], -B[q], i0 - 1, i1 + 1, guess[q]) - 1);
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
          for (int i = RoundUp(ilo, st); i <= ihi; i += st)
          {
            const double s = i - ilo;
            const double lam[4] = { l[0] + s * dl[0], l[1] + s * dl[1], l[2] + s * dl[2],
              l[3] + s * dl[3] };
            f(rowBase + i, lam);
          }
        }
        const int last = dims[0] - 1; // the last column ties toward -x
        if (i1 == last && last % st == 0)
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
  static int RoundUp(int a, int s) { return s == 1 ? a : ((a + s - 1) / s) * s; } // a >= 0
  static int64_t FloorDiv(int64_t a, int64_t b) { return a >= 0 ? a / b : -((-a + b - 1) / b); }
  // The smallest x in [L, H] with a + b x >= 0 (b > 0), or L / H when it lies below / above:
  // a floating-point guess corrected by exact products (no 128-bit division per row). Clamped,
  // it bounds a row [L + 1, H - 1] exactly as the unclamped ceiling would.
  static i128 FirstNonNegative(i128 a, i128 b, int64_t L, int64_t H, double root)
  {
    double g = std::ceil(root);
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
  double Nd[4][3], Cd[4]; // N and C rounded, for the floating-point row spans
  int64_t Lo[3], Hi[3];
};
// ScreenRaster: the same scan with barycentric planes and row bounds in double precision and no
// tie rule (a voxel centre on a shared face may count in both tets or neither). For ranking
// candidates (VertexRelocator), where TetRaster then decides; several times cheaper per row.
class ScreenRaster
{
public:
  bool Setup(const LatticePoint P[4], const int dims[3])
  {
    const double S = static_cast<double>(BisectionMesh::Scale);
    double p[4][3];
    for (int a = 0; a < 4; ++a)
    {
      for (int d = 0; d < 3; ++d)
      {
        p[a][d] = static_cast<double>(P[a][d]) / S;
      }
    }
    double e[3][3];
    for (int a = 0; a < 3; ++a)
    {
      for (int d = 0; d < 3; ++d)
      {
        e[a][d] = p[a + 1][d] - p[0][d];
      }
    }
    double r[3][3];
    Cross(e[1], e[2], r[0]);
    Cross(e[2], e[0], r[1]);
    Cross(e[0], e[1], r[2]);
    const double det = e[0][0] * r[0][0] + e[0][1] * r[0][1] + e[0][2] * r[0][2];
    if (!(std::fabs(det) > 0))
    {
      return false;
    }
    for (int q = 1; q < 4; ++q)
    {
      double h = 0;
      for (int d = 0; d < 3; ++d)
      {
        G[q][d] = r[q - 1][d] / det;
        h -= G[q][d] * p[0][d];
      }
      H[q] = h;
    }
    H[0] = 1.0 - H[1] - H[2] - H[3];
    for (int d = 0; d < 3; ++d)
    {
      G[0][d] = -(G[1][d] + G[2][d] + G[3][d]);
      double lo = p[0][d], hi = p[0][d];
      for (int a = 1; a < 4; ++a)
      {
        lo = std::min(lo, p[a][d]);
        hi = std::max(hi, p[a][d]);
      }
      Lo[d] = std::max(0, static_cast<int>(std::ceil(lo - 1e-9)));
      Hi[d] = std::min(dims[d] - 1, static_cast<int>(std::floor(hi + 1e-9)));
    }
    for (int q = 0; q < 4; ++q)
    {
      InvG0[q] = G[q][0] != 0 ? 1.0 / G[q][0] : 0.0;
    }
    return true;
  }

  /// f(voxelIndex, lambda[4]) for the centres with i, j, k multiples of `stride` in the tet.
  template <class F>
  void ForEachVoxel(const int dims[3], int stride, F&& f) const
  {
    const int st = std::max(1, stride);
    auto up = [st](int a) { return ((a + st - 1) / st) * st; };
    for (int k = up(Lo[2]); k <= Hi[2]; k += st)
    {
      for (int j = up(Lo[1]); j <= Hi[1]; j += st)
      {
        double rest[4], a = Lo[0], b = Hi[0];
        for (int q = 0; q < 4; ++q)
        {
          rest[q] = G[q][1] * j + G[q][2] * k + H[q];
          if (G[q][0] > 0)
          {
            a = std::max(a, -rest[q] * InvG0[q]);
          }
          else if (G[q][0] < 0)
          {
            b = std::min(b, -rest[q] * InvG0[q]);
          }
          else if (rest[q] < -1e-12)
          {
            b = a - 1;
          }
        }
        // Clamped before the conversion: a plane nearly parallel to x gives huge bounds.
        a = std::min(a, double(Hi[0] + 1));
        b = std::max(b, double(Lo[0] - 1));
        const int i0 = up(static_cast<int>(std::ceil(a - 1e-9))), i1 = static_cast<int>(std::floor(b + 1e-9));
        const long long rowBase = static_cast<long long>(dims[0]) * (j + static_cast<long long>(dims[1]) * k);
        for (int i = i0; i <= i1; i += st)
        {
          const double lam[4] = { rest[0] + G[0][0] * i, rest[1] + G[1][0] * i, rest[2] + G[2][0] * i,
            rest[3] + G[3][0] * i };
          f(rowBase + i, lam);
        }
      }
    }
  }

private:
  static void Cross(const double a[3], const double b[3], double c[3])
  {
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
  }
  double G[4][3], H[4], InvG0[4];
  int Lo[3], Hi[3];
};

} // namespace art

#endif
