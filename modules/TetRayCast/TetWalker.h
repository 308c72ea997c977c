// TetWalker: the face-to-face walk (FaceWalk.h) in 3-D, for any ray. Its side products are the
// Pluecker products of the ray with the tet's edges (Platis & Theoharis, JGT 2003; Marmitt &
// Slusallek, EuroVis 2006), each computed from its two global vertex ids in a fixed order, so a
// face shared by two tets gets bit-identical tests on both sides and a ray through an edge or a
// vertex never jumps a gap or leaks. The products also give the barycentric weights of the exit
// point, hence its t and scalar.
#ifndef art_TetWalker_h
#define art_TetWalker_h

#include "FaceWalk.h"
#include "Ray.h"
#include "TetMesh.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace art
{
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
    return CrossesFace(v[fv[0]], v[fv[1]], v[fv[2]], sense, x);
  }
  /// The same for the face with vertices a, b, c in its tet's outward order.
  bool CrossesFace(int a, int b, int c, int sense, FaceCrossing& x) const
  {
    const double s01 = sense * Side(a, b);
    const double s12 = sense * Side(b, c);
    const double s20 = sense * Side(c, a);
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
    const Vec3 p = P[a] * wa + P[b] * wb + P[c] * wc;
    x.t = Dot(p - O, D) * InvDD;
    x.s = F[a] * wa + F[b] * wb + F[c] * wc;
    return true;
  }

  /// Walks from the entry crossing `in` of tet t, calling visit(t, in, out) for every tet crossed
  /// (a false return stops the walk). Returns the boundary exit crossing in `out`. Crossings carry
  /// t and the scalar only (TetMesh::Barycentric gives weights where a caller needs them).
  /// steps counts tets; nudges counts fallback exits. `records`: the table walked (WalkFacesWith;
  /// null: the mesh's own).
  template <class Visit>
  ART_ALWAYS_INLINE void Walk(int t, int entryFace, FaceCrossing in, Visit&& visit, FaceCrossing& out,
    std::uint64_t& steps, std::uint64_t& nudges, const TetRecord* records = nullptr) const
  {
    WalkFaces(M, *this, t, entryFace, in, visit, out, steps, nudges, records);
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
  /// The walk's exit crossing, not before tIn: the face opposite c[x], weighted W (FaceWalk.h).
  static void Exit(const Corner c[3], int x, const Corner& d, const double W[4], double tIn, FaceCrossing& out)
  {
    const int x1 = walk::Next[x], x2 = walk::Next[x1];
    Exit(c[x2], c[x1], d, W[x2], W[x1], W[3], tIn, out);
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
