// ProjectedWalkAvx2: the face-to-face walk (FaceWalk.h) of a ProjectedWalker with AVX2, SIMD across
// a tet's corners. The entry face's three corners sit in the lanes of four registers (x, y, m, n)
// and their edge products in a fifth, so a step is three products in one, the exit weights by a
// permutation, the crossing's sums by horizontal adds and the new entry face by blends: no
// spilled arrays, no jump on the exit. It computes what the portable walk computes, the same
// products and the sums in the same order, so the two give the same bits (tested).
#ifndef art_ProjectedWalkAvx2_h
#define art_ProjectedWalkAvx2_h

#include "ProjectedWalker.h"

#if defined(__GNUC__) && defined(__x86_64__)
#define ART_HAVE_AVX2_WALK 1
#include <immintrin.h>

#define ART_AVX2_INLINE inline __attribute__((always_inline, target("avx2")))

namespace art
{
namespace avx2
{
/// Lane tables for the exit opposite corner x (0..2): the permutation that puts p[x+2] in lane
/// x+1, p[x+1] in lane x+2 and e[x] in lane 3 (as 32-bit indices), the signs that make them the
/// weights, and the lane of corner x.
struct ExitLanes
{
  alignas(32) int perm[3][8];
  alignas(32) int permE[3][8];
  alignas(32) double sign[3][4];
  alignas(32) std::int64_t lane[3][4];
};
inline const ExitLanes& Lanes()
{
  static const ExitLanes t = [] {
    ExitLanes l{};
    for (int x = 0; x < 3; ++x)
    {
      const int x1 = walk::Next[x], x2 = walk::Next[x1];
      int from[4] = { 0, 1, 2, 3 };
      from[x1] = x2, from[x2] = x1;
      int fromE[4] = { 0, 1, 2, x };
      for (int k = 0; k < 4; ++k)
      {
        l.perm[x][2 * k] = 2 * from[k], l.perm[x][2 * k + 1] = 2 * from[k] + 1;
        l.permE[x][2 * k] = 2 * fromE[k], l.permE[x][2 * k + 1] = 2 * fromE[k] + 1;
        l.lane[x][k] = k == x ? -1 : 0;
      }
      l.sign[x][x] = 0.0, l.sign[x][x1] = -1.0, l.sign[x][x2] = 1.0, l.sign[x][3] = -1.0;
    }
    return l;
  }();
  return t;
}

/// ExitBySigns from the products' sign mask (bit k: lane k negative).
constexpr signed char ExitByMask[8] = { 3, 1, 2, 1, 0, 0, 2, 3 };

/// v's doubles moved by a table of 32-bit lane indices. (Helpers rather than lambdas: a lambda
/// does not take its function's target.)
ART_AVX2_INLINE __m256d Permuted(__m256d v, const int* idx)
{
  return _mm256_castsi256_pd(
    _mm256_permutevar8x32_epi32(_mm256_castpd_si256(v), _mm256_load_si256(reinterpret_cast<const __m256i*>(idx))));
}

/// The corner lanes as scalar corners, for the rare paths that work on them one by one.
ART_AVX2_INLINE void Corners(__m256d X, __m256d Y, __m256d M, __m256d N, const int id[4], ProjectedWalker::Corner c[3])
{
  alignas(32) double x[4], y[4], m[4], n[4];
  _mm256_store_pd(x, X), _mm256_store_pd(y, Y), _mm256_store_pd(m, M), _mm256_store_pd(n, N);
  for (int k = 0; k < 3; ++k)
  {
    c[k] = { id[k], x[k], y[k], m[k], n[k] };
  }
}

/// The entry face's corners id[0..2] in lanes 0..2 of X, Y (relative to the pixel), M and N, lane
/// 3 zero, and in E the side product of the edge opposite each, as MakeCorner and Side make them:
/// the three vertices transposed, then the products of the corners rotated by one and by two.
ART_AVX2_INLINE void EntryFace(const ProjectedWalker& g, const int id[4], __m256d& X, __m256d& Y, __m256d& M,
  __m256d& N, __m256d& E)
{
  const ProjectedView::Vertex* V = g.Vertices();
  const __m256d a = _mm256_loadu_pd(&V[id[0]].x), b = _mm256_loadu_pd(&V[id[1]].x), c = _mm256_loadu_pd(&V[id[2]].x);
  const __m256d zero = _mm256_setzero_pd();
  const __m256d ab0 = _mm256_unpacklo_pd(a, b), ab1 = _mm256_unpackhi_pd(a, b); // x x m m, y y n n
  const __m256d c0 = _mm256_unpacklo_pd(c, zero), c1 = _mm256_unpackhi_pd(c, zero);
  const __m256d PX = _mm256_blend_pd(_mm256_set1_pd(g.PixelX()), zero, 8);
  const __m256d PY = _mm256_blend_pd(_mm256_set1_pd(g.PixelY()), zero, 8);
  X = _mm256_sub_pd(_mm256_permute2f128_pd(ab0, c0, 0x20), PX);
  Y = _mm256_sub_pd(_mm256_permute2f128_pd(ab1, c1, 0x20), PY);
  M = _mm256_permute2f128_pd(ab0, c0, 0x31);
  N = _mm256_permute2f128_pd(ab1, c1, 0x31);
  // e[k] = Side(c[k+1], c[k+2]) = x[k+1] y[k+2] - y[k+1] x[k+2]; lane 3: 0.
  const __m256d X1 = _mm256_permute4x64_pd(X, 0xC9), X2 = _mm256_permute4x64_pd(X, 0xD2);
  const __m256d Y1 = _mm256_permute4x64_pd(Y, 0xC9), Y2 = _mm256_permute4x64_pd(Y, 0xD2);
  E = _mm256_sub_pd(_mm256_mul_pd(X1, Y2), _mm256_mul_pd(Y1, X2));
  const __m256d ABS = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffffLL));
  const int nearZero = _mm256_movemask_pd(_mm256_cmp_pd(_mm256_and_pd(E, ABS), _mm256_set1_pd(g.Bound()), _CMP_LE_OQ)) & 7;
  if (__builtin_expect(nearZero != 0, 0))
  {
    ProjectedWalker::Corner cs[3];
    Corners(X, Y, M, N, id, cs);
    alignas(32) double e[4];
    _mm256_store_pd(e, E);
    for (int k = 0; k < 3; ++k)
    {
      if (nearZero & (1 << k))
      {
        e[k] = g.Exact(cs[walk::Next[k]], cs[walk::Next[walk::Next[k]]]);
      }
    }
    E = _mm256_load_pd(e);
  }
}
} // namespace avx2

/// As WalkFacesWith<false> with a ProjectedWalker, the same crossings bit for bit.
template <class Visit>
ART_AVX2_INLINE void WalkProjectedAvx2(const TetMesh& M, const ProjectedWalker& g, int t, int entryFace,
  FaceCrossing in, Visit&& visit, FaceCrossing& exit, std::uint64_t& steps, std::uint64_t& nudges,
  const TetRecord* records)
{
  using Corner = ProjectedWalker::Corner;
  const avx2::ExitLanes& L = avx2::Lanes();
  const std::size_t limit = M.NumberOfTets() + 8;
  std::uint64_t n = 0, nudged = 0;
  FaceCrossing out = exit;
  // The entry face's corners in lanes 0..2, their ids, and e[k] of the edge opposite corner k.
  int cid[4];
  __m256d X, Y, Mv, Nv, E;
  {
    const auto& v = records[t].v;
    const int* fv = TetMesh::FaceVertex[entryFace];
    cid[0] = v[fv[0]], cid[1] = v[fv[1]], cid[2] = v[fv[2]], cid[3] = -1;
    avx2::EntryFace(g, cid, X, Y, Mv, Nv, E);
  }
  const __m256d PX = _mm256_set1_pd(g.PixelX()), PY = _mm256_set1_pd(g.PixelY()), EPS = _mm256_set1_pd(g.Bound());
  const __m256d ABS = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7fffffffffffffffLL));
  const __m256d NEG = _mm256_castsi256_pd(_mm256_set1_epi64x(static_cast<long long>(0x8000000000000000ULL)));
  const __m256d ZERO = _mm256_setzero_pd();
  const ProjectedView::Vertex* V = g.Vertices();
  const bool prefetch = M.NumberOfTets() > TetMesh::LocalityThreshold;
  int stuck = 0;
  while (n < limit)
  {
    ++n;
    const TetRecord& rec = records[t];
    if (prefetch)
    {
      walk::PrefetchNeighbours(records, rec);
    }
    const int id = rec.v[entryFace];
    const double* vp = &V[id].x;
    const __m256d DX = _mm256_sub_pd(_mm256_broadcast_sd(vp), PX), DY = _mm256_sub_pd(_mm256_broadcast_sd(vp + 1), PY);
    const __m256d DM = _mm256_broadcast_sd(vp + 2), DN = _mm256_broadcast_sd(vp + 3);
    __m256d P = _mm256_sub_pd(_mm256_mul_pd(X, DY), _mm256_mul_pd(Y, DX));
    const int nearZero = _mm256_movemask_pd(_mm256_cmp_pd(_mm256_and_pd(P, ABS), EPS, _CMP_LE_OQ)) & 7;
    if (__builtin_expect(nearZero != 0, 0))
    {
      // Products within their rounding bound: the 3-D ones, as ProjectedWalker::Side takes them.
      Corner c[3];
      avx2::Corners(X, Y, Mv, Nv, cid, c);
      const Corner d = g.MakeCorner(id);
      alignas(32) double p[4];
      _mm256_store_pd(p, P);
      for (int k = 0; k < 3; ++k)
      {
        if (nearZero & (1 << k))
        {
          p[k] = g.Exact(c[k], d);
        }
      }
      P = _mm256_load_pd(p);
    }
    // The exit weights: p[x+2] and p[x+1] moved to lanes x+1 and x+2 (Q), e[x] to lane 3, signed.
    int x = avx2::ExitByMask[_mm256_movemask_pd(P) & 7];
    __m256d W = ZERO, Q = ZERO;
    bool proper = x < 3;
    if (proper)
    {
      Q = avx2::Permuted(P, L.perm[x]);
      W = _mm256_mul_pd(_mm256_blend_pd(Q, avx2::Permuted(E, L.permE[x]), 8), _mm256_load_pd(L.sign[x]));
      const int need = 15 & ~(1 << x);
      proper = (_mm256_movemask_pd(_mm256_cmp_pd(W, ZERO, _CMP_GT_OQ)) & need) == need;
    }
    if (__builtin_expect(!proper, 0))
    {
      alignas(32) double p[4], e[4], w[3];
      _mm256_store_pd(p, P), _mm256_store_pd(e, E);
      x = FallbackExit(e, p, w, nudged);
      alignas(32) double lanes[4];
      lanes[x] = 0.0, lanes[walk::Next[x]] = w[2], lanes[walk::Next[walk::Next[x]]] = w[1], lanes[3] = w[0];
      W = _mm256_load_pd(lanes);
      Q = avx2::Permuted(P, L.perm[x]);
    }
    // The crossing: sums over the corners, ((0 + 1) + (2 + 3)), d in lane 3.
    const __m256d WM = _mm256_mul_pd(W, _mm256_blend_pd(Mv, DM, 8)), WN = _mm256_mul_pd(W, _mm256_blend_pd(Nv, DN, 8));
    const __m256d H1 = _mm256_hadd_pd(W, WM), H2 = _mm256_hadd_pd(WN, WN);
    const __m128d S1 = _mm_add_pd(_mm256_castpd256_pd128(H1), _mm256_extractf128_pd(H1, 1));
    const __m128d S2 = _mm_add_pd(_mm256_castpd256_pd128(H2), _mm256_extractf128_pd(H2, 1));
    const double l = _mm_cvtsd_f64(S1);
    if (__builtin_expect(!(l > 0), 0))
    {
      Corner c[3];
      avx2::Corners(X, Y, Mv, Nv, cid, c);
      const int x1 = walk::Next[x], x2 = walk::Next[x1];
      g.FaceExit(c[x2], c[x1], g.MakeCorner(id), 1.0, 1.0, 1.0, in.t, out);
    }
    else
    {
      g.Crossing(l, _mm_cvtsd_f64(_mm_unpackhi_pd(S1, S1)), _mm_cvtsd_f64(S2), in.t, out);
    }
    if (!visit(t, in, out))
    {
      break;
    }
    stuck = out.t > in.t ? 0 : stuck + 1;
    const int link = rec.link[walk::SlotOf(rec, cid[x])];
    if (link < 0 || stuck > 256)
    {
      break;
    }
    // The exit face reversed, corner x replaced by d: e[x] stays, e[x+1] = p[x+2], e[x+2] = -p[x+1].
    const __m256d lane = _mm256_castsi256_pd(_mm256_load_si256(reinterpret_cast<const __m256i*>(L.lane[x])));
    X = _mm256_blendv_pd(X, DX, lane), Y = _mm256_blendv_pd(Y, DY, lane);
    Mv = _mm256_blendv_pd(Mv, DM, lane), Nv = _mm256_blendv_pd(Nv, DN, lane);
    E = _mm256_blendv_pd(_mm256_mul_pd(Q, _mm256_xor_pd(_mm256_load_pd(L.sign[x]), NEG)), E, lane);
    cid[x] = id;
    t = TetMesh::LinkTet(link);
    entryFace = TetMesh::LinkFace(link);
    in = out;
  }
  exit = out, steps += n, nudges += nudged;
}
} // namespace art

#endif
#endif
