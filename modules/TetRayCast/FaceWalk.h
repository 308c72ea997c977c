// FaceWalk: face-to-face traversal of a tet mesh along one ray, never a search (Grosso, Luerig &
// Ertl 1997, sec. 5). The exit face is chosen with side products of the ray and the tet's edges
// (Platis & Theoharis, JGT 2003; Marmitt & Slusallek, EuroVis 2006): entering through face
// (a, b, c), three products with the apex d decide the exit among the three other faces, and that
// face, reversed, is the next tet's entry face, so nothing is searched or recomputed. The
// products also weigh the exit point's corners, hence its ray parameter and scalar. The geometry
// (3-D Pluecker products in TetWalker, 2-D ones in a camera's projection in ProjectedWalker) is a
// template parameter; the walk, its records and its stability fallback (ExitFallback.h) are here.
#ifndef art_FaceWalk_h
#define art_FaceWalk_h

#include "ExitFallback.h"
#include "TetMesh.h"

#include <cmath>
#include <cstdint>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#if defined(__GNUC__)
#define ART_ALWAYS_INLINE __attribute__((always_inline))
#else
#define ART_ALWAYS_INLINE
#endif

namespace art
{
/// A point where a ray crosses a face: ray parameter and scalar.
struct FaceCrossing
{
  double t = 0, s = 0;
};

/// Meshes with more tets than this walk with jumps rather than lookups (WalkFaces): far larger
/// than the caches, the processor fetching the next tet before a step is decided pays.
constexpr std::size_t SpeculativeWalkTets = std::size_t(1) << 20;

namespace walk
{
/// The slot (0-3) of vertex `id` in record r, which holds it.
inline int SlotOf(const TetRecord& r, int id)
{
#if defined(__SSE2__)
  const __m128i v = _mm_load_si128(reinterpret_cast<const __m128i*>(r.v.data()));
  const int mask = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(v, _mm_set1_epi32(id))));
  return __builtin_ctz(static_cast<unsigned>(mask) | 8u);
#else
  return r.v[0] == id ? 0 : (r.v[1] == id ? 1 : (r.v[2] == id ? 2 : 3));
#endif
}

/// The exit face the signs of the apex products p name (ExitFallback.h's numbering: the face
/// opposite corner k leaves when p[k+1] >= 0 >= p[k+2]), 3 for none. Read from the sign bits, a
/// -0 counts as negative; a zero product fails the strict test that follows whichever face this
/// names.
inline int ExitBySigns(const double p[3])
{
  static constexpr signed char byCode[8] = { 3, 1, 0, 1, 2, 2, 0, 3 };
  return byCode[7 ^ (std::signbit(p[0]) << 2 | std::signbit(p[1]) << 1 | std::signbit(p[2]))];
}

constexpr int Next[4] = { 1, 2, 0, 1 };

/// Asks the cache for the records of r's neighbours. A link is 4 * tet + face, so the byte
/// 8 * link into the table lies in that tet's 32-byte record: one load and one prefetch a face.
/// A boundary link (-1) names a byte before the table; a prefetch never faults.
inline void PrefetchNeighbours(const TetRecord* records, const TetRecord& r)
{
  const std::uintptr_t base = reinterpret_cast<std::uintptr_t>(records);
  for (int l : r.link)
  {
    __builtin_prefetch(reinterpret_cast<const void*>(base + static_cast<std::uintptr_t>(std::intptr_t(l) * 8)));
  }
}
} // namespace walk

/// The face-to-face walk shared by TetWalker and ProjectedWalker: Geo supplies the corners, the
/// side products and the exit crossing (TetWalker's geometry members), the walk the rest.
/// Walks from the entry crossing `in` of tet t through its face entryFace, calling
/// visit(t, in, out) for every tet crossed (false stops the walk); `out` ends as the last exit.
/// `records` is the table walked: the mesh's own, or one whose links into tets the caller skips
/// are -1, so the walk stops before them as at the boundary. steps counts tets, nudges fallback
/// exits.
/// Which face the ray leaves by is as random as a coin. Without Speculate, what depends on it is
/// looked up by its index (no jump to mispredict); with Speculate it is chosen by jumps, so the
/// processor fetches the next tet from memory before the step is decided, right half the time,
/// which pays once the mesh is far larger than the caches. Both give the same bits.
template <bool Speculate, class Geo, class Visit>
ART_ALWAYS_INLINE inline void WalkFacesWith(const TetMesh& M, const Geo& g, int t, int entryFace, FaceCrossing in,
  Visit&& visit, FaceCrossing& exit, std::uint64_t& steps, std::uint64_t& nudges, const TetRecord* records)
{
  using Corner = typename Geo::Corner;
  // Counters and the crossing in locals (written back at the end): through the references the
  // compiler would store them at every step.
  std::uint64_t n = 0, nudged = 0;
  FaceCrossing out = exit;
  struct WriteBack
  {
    FaceCrossing &to, &from;
    std::uint64_t &steps, &n, &nudges, &nudged;
    ~WriteBack() { to = from, steps += n, nudges += nudged; }
  } back{ exit, out, steps, n, nudges, nudged };
  const std::size_t limit = M.NumberOfTets() + 8;
  // The entry face's corners c[0..2] in the current tet's outward order, and e[k] the side product
  // of the edge opposite c[k] (c[k+1] -> c[k+2]); all <= 0, the ray goes in.
  Corner c[3];
  double e[3];
  {
    const auto& v = records[t].v;
    const int* fv = TetMesh::FaceVertex[entryFace];
    c[0] = g.MakeCorner(v[fv[0]]), c[1] = g.MakeCorner(v[fv[1]]), c[2] = g.MakeCorner(v[fv[2]]);
    e[0] = g.Side(c[1], c[2]), e[1] = g.Side(c[2], c[0]), e[2] = g.Side(c[0], c[1]);
  }
  // A mesh larger than the caches waits on memory at every step: the next tet is one of this
  // one's neighbours, so their records are fetched while this step computes.
  const bool prefetch = M.NumberOfTets() > TetMesh::LocalityThreshold;
  int stuck = 0;
  // One step with the exit face opposite c[x] (x a compile-time constant with Speculate): the
  // exit crossing, the visit, then the exit face reversed, c[x] replaced by d, is the entry face
  // of the tet across it: e[x] stays, the others are the apex products. False: the walk ends.
  auto step = [&](auto x, const TetRecord& rec, const Corner& d, const double p[3], const double W[4])
                ART_ALWAYS_INLINE {
    const int x1 = walk::Next[x], x2 = walk::Next[x1];
    g.Exit(c, x, d, W, in.t, out);
    if (!visit(t, in, out))
    {
      return false;
    }
    stuck = out.t > in.t ? 0 : stuck + 1;
    const int link = rec.link[walk::SlotOf(rec, c[x].id)];
    if (link < 0 || stuck > 256)
    {
      return false;
    }
    const double e1 = p[x2], e2 = -p[x1];
    e[x1] = e1, e[x2] = e2;
    c[x] = d;
    t = TetMesh::LinkTet(link);
    entryFace = TetMesh::LinkFace(link);
    in = out;
    return true;
  };
  for (; n < limit;)
  {
    ++n;
    const TetRecord& rec = records[t];
    if (prefetch)
    {
      walk::PrefetchNeighbours(records, rec);
    }
    const Corner d = g.MakeCorner(rec.v[entryFace]);
    const double p[3] = { g.Side(c[0], d), g.Side(c[1], d), g.Side(c[2], d) };
    // The exit face's corner weights W, one per corner c[0..2] and d (W[3]), each the product of
    // its opposite edge in the face; the corner left behind, c[x], weighs 0. Only a strictly
    // interior crossing is taken on the signs' word; an edge, a vertex or a failed test goes to
    // the fallback.
    int x = walk::ExitBySigns(p);
    double W[4];
    if (x < 3)
    {
      const int x1 = walk::Next[x], x2 = walk::Next[x1];
      W[x] = 0.0, W[x1] = -p[x2], W[x2] = p[x1], W[3] = -e[x];
    }
    if (__builtin_expect(!(x < 3 && W[3] > 0 && W[walk::Next[x]] > 0 && W[walk::Next[walk::Next[x]]] > 0), 0))
    {
      double w[3];
      x = FallbackExit(e, p, w, nudged);
      const int x1 = walk::Next[x], x2 = walk::Next[x1];
      W[x] = 0.0, W[x1] = w[2], W[x2] = w[1], W[3] = w[0];
    }
    bool on;
    if constexpr (Speculate)
    {
      on = x == 0 ? step(std::integral_constant<int, 0>(), rec, d, p, W)
                  : (x == 1 ? step(std::integral_constant<int, 1>(), rec, d, p, W)
                            : step(std::integral_constant<int, 2>(), rec, d, p, W));
    }
    else
    {
      on = step(x, rec, d, p, W);
    }
    if (!on)
    {
      return;
    }
  }
}

/// WalkFacesWith in the form that suits the mesh's size; `records` null: the mesh's own.
template <class Geo, class Visit>
ART_ALWAYS_INLINE inline void WalkFaces(const TetMesh& M, const Geo& g, int t, int entryFace, FaceCrossing in, Visit&& visit,
  FaceCrossing& out, std::uint64_t& steps, std::uint64_t& nudges, const TetRecord* records)
{
  records = records ? records : M.Records();
  if (M.NumberOfTets() > SpeculativeWalkTets)
  {
    WalkFacesWith<true>(M, g, t, entryFace, in, visit, out, steps, nudges, records);
  }
  else
  {
    WalkFacesWith<false>(M, g, t, entryFace, in, visit, out, steps, nudges, records);
  }
}
} // namespace art

#endif
