// TetWalker: face-to-face traversal of a tet mesh along one ray, never a search (Grosso, Luerig &
// Ertl 1997, sec. 5). The exit face is chosen with Pluecker side products of the tet's edges
// (Platis & Theoharis, JGT 2003; Marmitt & Slusallek, EuroVis 2006): each edge's product is computed
// from its two global vertex ids in a fixed order, so a face shared by two tets gets bit-identical
// tests on both sides and a ray through an edge or vertex never jumps a gap or leaks. The products
// also give the barycentric weights of the exit point, hence its t and scalar.
// When no face passes (a ray lying in a face plane), the least-violating face is taken with its
// weights clamped into the face: the centroid nudge of the paper, as a fallback only.
#ifndef art_TetWalker_h
#define art_TetWalker_h

#include "Ray.h"
#include "TetMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace art
{
/// A point where a ray crosses a face: ray parameter and scalar.
struct FaceCrossing
{
  double t = 0, s = 0;
};

/// Meshes with more tets than this walk with jumps rather than lookups (WalkFaces). Set between
/// the meshes measured: 200k tets (10 MB walked, in the cache) and 4.3M (170 MB, not).
constexpr std::size_t SpeculativeWalkTets = std::size_t(1) << 20;

/// The face-to-face walk shared by TetWalker and ProjectedWalker: Geo supplies the corners, the
/// side products and the exit crossing (see TetWalker's geometry members), the walk the rest.
/// Which face the ray leaves by is as random as a coin. Without Speculate, everything that
/// depends on it is looked up by its index (tables and masks, no jumps to mispredict); with
/// Speculate it is chosen by jumps, which lets the processor fetch the next tet and its corners
/// from memory before this step is decided, right about half the time, which is what counts
/// once the mesh is far larger than the caches. Measured with the projected walk, both forms in
/// one process: lookups 5-16% faster on the 10k-200k tet CT meshes, jumps 10-18% on the 4.3M.
/// `links` is the table of face links walked: the mesh's own, or one where links into tets the
/// caller skips are -1, so the walk stops before them as at the boundary.
template <bool Speculate, class Geo, class Visit>
void WalkFacesWith(const TetMesh& M, const Geo& g, int t, int entryFace, FaceCrossing in,
  Visit&& visit, FaceCrossing& out, std::uint64_t& steps, std::uint64_t& nudges,
  const std::array<int, 4>* links)
{
  const std::size_t limit = M.NumberOfTets() + 8;
  int stuck = 0;
  // The entry face (a, b, c) in the current tet's outward order, with the side products of its
  // edges (all <= 0: the ray goes in). Each step adds the apex d: three new products decide
  // the exit among the faces (c b d), (a c d), (b a d), and that face, reversed, is the next
  // tet's entry face, so nothing is searched or recomputed.
  // Four corner slots: a, b, c point at the entry face's; the fourth takes each new apex, and the
  // vertex a step leaves behind frees its slot (pointers move, corners do not).
  using Corner = typename Geo::Corner;
  Corner cs[4];
  Corner *ia = &cs[0], *ib = &cs[1], *ic = &cs[2], *id = &cs[3];
  double eab, ebc, eca;
  {
    const auto& v = M.Tet(t);
    const int* fv = TetMesh::FaceVertex[entryFace];
    cs[0] = g.MakeCorner(v[fv[0]]), cs[1] = g.MakeCorner(v[fv[1]]), cs[2] = g.MakeCorner(v[fv[2]]);
    eab = g.Side(cs[0], cs[1]), ebc = g.Side(cs[1], cs[2]), eca = g.Side(cs[2], cs[0]);
  }
  // A mesh larger than the caches waits on memory at every step: the next tet is one of this
  // one's neighbours, so their rows are fetched while this step computes (measured 15% faster on
  // the full-resolution CT; on meshes that fit in cache it only costs).
  const bool prefetch = M.NumberOfTets() > TetMesh::LocalityThreshold;
  for (std::size_t n = 0; n < limit; ++n)
  {
    ++steps;
    const auto& v = M.Tet(t);
    if (prefetch)
    {
      for (int l : links[t])
      {
        const std::size_t nb = static_cast<std::size_t>(TetMesh::LinkTet(std::max(l, 0)));
        __builtin_prefetch(&M.Tet(nb));
        __builtin_prefetch(&links[nb]);
      }
    }
    *id = g.MakeCorner(v[entryFace]);
    const Corner &a = *ia, &b = *ib, &c = *ic, &d = *id;
    const double pa = g.Side(a, d), pb = g.Side(b, d), pc = g.Side(c, d);
    // Outward edge products of each candidate face (entry edge first); a face's vertices weigh
    // the products of their opposite edges. Face A, opposite a: (c, b, d) with (-ebc, pb, -pc);
    // B: (a, c, d) with (-eca, pc, -pa); C: (b, a, d) with (-eab, pa, -pb). Without Speculate
    // they are looked up by the face's index in vals.
    auto face = [&](int k, double* f) {
      f[0] = k == 0 ? -ebc : (k == 1 ? -eca : -eab);
      f[1] = k == 0 ? pb : (k == 1 ? pc : pa);
      f[2] = k == 0 ? -pc : (k == 1 ? -pa : -pb);
    };
    const double vals[13] = { eab, ebc, eca, -eab, -ebc, -eca, pa, pb, pc, -pa, -pb, -pc, 0.0 };
    // The signs of pa, pb, pc name the exit face (A: pb >= 0 >= pc, B: pc >= 0 >= pa,
    // C: pa >= 0 >= pb; 3: none). Only a strictly interior crossing is taken on that word; a
    // crossing on an edge or vertex (a zero product) or a failed test goes to the full rule: a
    // proper exit beats any fallback, among proper ones the most interior wins, and with none
    // the least-violating face is taken, its weights clamped into it.
    // The word is read from the sign bits: a -0 then counts as negative, but a zero product
    // fails the strict test below whichever face the word names, or does not enter its face.
    static constexpr int byCode[8] = { 3, 1, 0, 1, 2, 2, 0, 3 };
    int x = byCode[7 ^ (std::signbit(pa) << 2 | std::signbit(pb) << 1 | std::signbit(pc))];
    double e[3] = { 0, 0, 0 };
    if constexpr (Speculate)
    {
      if (x < 3)
      {
        face(x, e);
      }
    }
    else
    {
      static constexpr signed char faceOf[4][3] = { { 4, 7, 11 }, { 5, 8, 9 }, { 3, 6, 10 }, { 12, 12, 12 } };
      e[0] = vals[faceOf[x][0]], e[1] = vals[faceOf[x][1]], e[2] = vals[faceOf[x][2]];
    }
    if (!(std::min(e[0], std::min(e[1], e[2])) > 0))
    {
      double bestLo = -1e300;
      bool proper = false;
      for (int k = 0; k < 3; ++k)
      {
        double f[3];
        face(k, f);
        const double lo = std::min(f[0], std::min(f[1], f[2]));
        const bool ok = lo >= 0 && f[0] + f[1] + f[2] > 0;
        if ((ok && !proper) || (ok == proper && lo > bestLo))
        {
          proper = ok;
          bestLo = lo;
          x = k;
        }
      }
      nudges += proper ? 0 : 1;
      x = x < 3 ? x : 0; // every product NaN (coordinates near 1e150): any face, never past the tables
      face(x, e);
    }
    // The exit face as (u, w, d): (c b d), (a c d) or (b a d); u <- e[1], w <- e[2], d <- e[0];
    // it is opposite the vertex a, b or c, whose slot in this tet names the link to the next.
    const Corner* u;
    const Corner* w;
    int opp;
    Corner* const cp[4] = { ia, ib, ic, id };
    if constexpr (Speculate)
    {
      u = x == 0 ? &c : (x == 1 ? &a : &b);
      w = x == 0 ? &b : (x == 1 ? &c : &a);
      opp = x == 0 ? a.id : (x == 1 ? b.id : c.id);
    }
    else
    {
      static constexpr signed char uOf[3] = { 2, 0, 1 }, wOf[3] = { 1, 2, 0 };
      u = cp[uOf[x]], w = cp[wOf[x]], opp = cp[x]->id;
    }
    g.Exit(*u, *w, d, std::max(e[1], 0.0), std::max(e[2], 0.0), std::max(e[0], 0.0), in.t, out);
    if (!visit(t, in, out))
    {
      return;
    }
    stuck = out.t > in.t ? 0 : stuck + 1;
    const int* fv = TetMesh::FaceVertex[entryFace];
    int slot;
    if constexpr (Speculate)
    {
      slot = v[fv[0]] == opp ? fv[0] : (v[fv[1]] == opp ? fv[1] : fv[2]);
    }
    else
    {
      const int m0 = -int(v[fv[0]] == opp), m1 = -int(v[fv[1]] == opp) & ~m0;
      slot = (fv[0] & m0) | (fv[1] & m1) | (fv[2] & ~(m0 | m1));
    }
    const int link = links[t][slot];
    if (link < 0 || stuck > 256)
    {
      return;
    }
    // The exit face reversed is the next tet's entry face, outward for that tet: (c, d, b) with
    // products (pc, -pb, ebc), (a, d, c) with (pa, -pc, eca), or (a, b, d) with (eab, pb, -pa);
    // the corner left behind frees its slot for the next apex.
    if constexpr (Speculate)
    {
      if (x == 0)
      {
        const double nab = pc, nbc = -pb, nca = ebc;
        eab = nab, ebc = nbc, eca = nca;
        ia = cp[2], ib = cp[3], ic = cp[1], id = cp[0];
      }
      else if (x == 1)
      {
        eab = pa, ebc = -pc;
        std::swap(ib, id);
      }
      else
      {
        ebc = pb, eca = -pa;
        std::swap(ic, id);
      }
    }
    else
    {
      static constexpr signed char nextE[3][3] = { { 8, 10, 1 }, { 6, 11, 2 }, { 0, 7, 9 } };
      static constexpr signed char nextC[3][4] = { { 2, 3, 1, 0 }, { 0, 3, 2, 1 }, { 0, 1, 3, 2 } };
      eab = vals[nextE[x][0]], ebc = vals[nextE[x][1]], eca = vals[nextE[x][2]];
      ia = cp[nextC[x][0]], ib = cp[nextC[x][1]], ic = cp[nextC[x][2]], id = cp[nextC[x][3]];
    }
    t = TetMesh::LinkTet(link);
    entryFace = TetMesh::LinkFace(link);
    in = out;
  }
}

template <class Geo, class Visit>
void WalkFaces(const TetMesh& M, const Geo& g, int t, int entryFace, FaceCrossing in, Visit&& visit,
  FaceCrossing& out, std::uint64_t& steps, std::uint64_t& nudges, const std::array<int, 4>* links)
{
  links = links ? links : M.LinkRows();
  if (M.NumberOfTets() > SpeculativeWalkTets)
  {
    WalkFacesWith<true>(M, g, t, entryFace, in, visit, out, steps, nudges, links);
  }
  else
  {
    WalkFacesWith<false>(M, g, t, entryFace, in, visit, out, steps, nudges, links);
  }
}

class TetWalker
{
public:
  TetWalker(const TetMesh& m, const Ray& r)
    : M(m), P(m.PointsArray().data()), F(m.Scalars().data()), O(r.org), D(r.dir),
      InvDD(1.0 / Dot(r.dir, r.dir))
  {
  }

  /// Side product of the ray with the edge from vertex u to vertex v (global ids).
  double Side(int u, int v) const
  {
    if (u < v)
    {
      return Dot(Cross(D, P[u] - O), P[v] - O);
    }
    return -Dot(Cross(D, P[v] - O), P[u] - O);
  }

  /// Does the ray cross face f of tet t inward (sense -1) or outward (+1)? Fills the crossing.
  bool Crosses(int t, int f, int sense, FaceCrossing& x) const
  {
    const auto& v = M.Tet(t);
    const int* fv = TetMesh::FaceVertex[f];
    const double s01 = sense * Side(v[fv[0]], v[fv[1]]);
    const double s12 = sense * Side(v[fv[1]], v[fv[2]]);
    const double s20 = sense * Side(v[fv[2]], v[fv[0]]);
    if (s01 < 0 || s12 < 0 || s20 < 0)
    {
      return false;
    }
    const double sum = s01 + s12 + s20;
    if (!(sum > 0))
    {
      return false;
    }
    const double wa = s12 / sum, wb = s20 / sum, wc = s01 / sum;
    const Vec3 p = P[v[fv[0]]] * wa + P[v[fv[1]]] * wb + P[v[fv[2]]] * wc;
    x.t = Dot(p - O, D) * InvDD;
    x.s = F[v[fv[0]]] * wa + F[v[fv[1]]] * wb + F[v[fv[2]]] * wc;
    return true;
  }

  /// Walks from the entry crossing `in` of tet t, calling visit(t, in, out) for every tet crossed
  /// (a false return stops the walk). Returns the boundary exit crossing in `out`. Crossings carry
  /// t and the scalar only (TetMesh::Barycentric gives weights where a caller needs them).
  /// steps counts tets; nudges counts fallback exits. `links`: the table walked (WalkFacesWith;
  /// null: the mesh's own).
  template <class Visit>
  void Walk(int t, int entryFace, FaceCrossing in, Visit&& visit, FaceCrossing& out,
    std::uint64_t& steps, std::uint64_t& nudges, const std::array<int, 4>* links = nullptr) const
  {
    WalkFaces(M, *this, t, entryFace, in, visit, out, steps, nudges, links);
  }

  // The walk's geometry (WalkFaces): what the walk keeps of a vertex, the side product of two of
  // them, and the exit crossing from the clamped edge products of the exit face.
  /// A vertex as the walk sees it: global id, scalar, ray parameter, q = p - o and D x q.
  struct Corner
  {
    int id = -1;
    double f = 0, t = 0; ///< scalar, and the ray parameter of the vertex's projection on the ray
    Vec3 q, dq;
  };
  Corner MakeCorner(int id) const
  {
    const Vec3 q = P[id] - O;
    return { id, F[id], Dot(q, D) * InvDD, q, Cross(D, q) };
  }
  /// Side(u, v) from the carried D x q: the same bits as Side(u.id, v.id).
  static double Side(const Corner& u, const Corner& v)
  {
    return u.id < v.id ? Dot(u.dq, v.q) : -Dot(v.dq, u.q);
  }
  /// The crossing of face (u, w, d) weighted wu, ww, wd (>= 0, not normalised), not before tIn.
  static void Exit(const Corner& u, const Corner& w, const Corner& d, double wu, double ww, double wd,
    double tIn, FaceCrossing& out)
  {
    const double sum = wu + ww + wd;
    if (sum > 0)
    {
      const double inv = 1.0 / sum;
      wu *= inv, ww *= inv, wd *= inv;
    }
    else
    {
      wu = ww = wd = 1.0 / 3;
    }
    out.t = std::max(u.t * wu + w.t * ww + d.t * wd, tIn);
    out.s = u.f * wu + w.f * ww + d.f * wd;
  }

private:
  const TetMesh& M;
  const Vec3* P;
  const double* F;
  Vec3 O, D;
  double InvDD;
};
} // namespace art

#endif
