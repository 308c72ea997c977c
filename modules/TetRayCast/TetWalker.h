// TetWalker: face-to-face traversal of a tet mesh along one ray, never a search (Grosso, Luerig &
// Ertl 1997, sec. 5). The exit face is chosen with Pluecker side products of the tet's edges
// (Platis & Theoharis, JGT 2003; Marmitt & Slusallek, EuroVis 2006): each edge's product is computed
// from its two global vertex ids in a fixed order, so a face shared by two tets gets bit-identical
// tests on both sides and a ray through an edge or vertex never jumps a gap or leaks. The products
// also give the barycentric weights of the entry and exit points, hence their t and scalar.
// When no face passes (a ray lying in a face plane), the least-violating face is taken with its
// weights clamped into the face: the centroid nudge of the paper, as a fallback only.
#ifndef art_TetWalker_h
#define art_TetWalker_h

#include "Ray.h"
#include "TetMesh.h"

#include <algorithm>
#include <cstdint>

namespace art
{
/// A point where a ray crosses a face: ray parameter, scalar, barycentric weights in the tet.
struct FaceCrossing
{
  double t = 0, s = 0;
  double w[4] = { 0, 0, 0, 0 };
};

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
    Fill(v, f, s12 / sum, s20 / sum, s01 / sum, x);
    return true;
  }

  /// Walks from the entry crossing `in` of tet t, calling visit(t, in, out) for every tet crossed
  /// (a false return stops the walk). Returns the boundary exit crossing in `out`.
  /// steps counts tets; nudges counts fallback exits.
  template <class Visit>
  void Walk(int t, int entryFace, FaceCrossing in, Visit&& visit, FaceCrossing& out,
    std::uint64_t& steps, std::uint64_t& nudges) const
  {
    const std::size_t limit = M.NumberOfTets() + 8;
    int stuck = 0;
    // Per local vertex: global id, q = p - o and D x q. Three of the four carry over from the
    // previous tet (the shared face), so each step computes one new vertex; the side product of
    // edge (u, v), u < v, is (D x q_u) . q_v, the same bits in every tet that has the edge.
    int id[4];
    Vec3 q[4], dq[4];
    {
      const auto& v = M.Tet(t);
      for (int i = 0; i < 4; ++i)
      {
        id[i] = v[i];
        q[i] = P[v[i]] - O;
        dq[i] = Cross(D, q[i]);
      }
    }
    for (std::size_t n = 0; n < limit; ++n)
    {
      ++steps;
      double S[4][4];
      for (int i = 0; i < 4; ++i)
      {
        S[i][i] = 0;
        for (int j = i + 1; j < 4; ++j)
        {
          S[i][j] = id[i] < id[j] ? Dot(dq[i], q[j]) : -Dot(dq[j], q[i]);
          S[j][i] = -S[i][j];
        }
      }
      int best = -1;
      double bestMin = -1e300, w[3] = { 1.0 / 3, 1.0 / 3, 1.0 / 3 };
      bool proper = false;
      for (int f = 0; f < 4; ++f)
      {
        if (f == entryFace)
        {
          continue;
        }
        const int* fv = TetMesh::FaceVertex[f];
        const double a = S[fv[0]][fv[1]], b = S[fv[1]][fv[2]], c = S[fv[2]][fv[0]];
        const double lo = std::min(a, std::min(b, c)), sum = a + b + c;
        const bool ok = lo >= 0 && sum > 0;
        // A proper exit beats any fallback; among proper ones the most interior crossing wins.
        if ((ok && !proper) || (ok == proper && lo > bestMin))
        {
          proper = ok;
          best = f;
          bestMin = lo;
          const double ca = std::max(b, 0.0), cb = std::max(c, 0.0), cc = std::max(a, 0.0);
          const double cs = ca + cb + cc;
          if (cs > 0)
          {
            w[0] = ca / cs, w[1] = cb / cs, w[2] = cc / cs;
          }
          else
          {
            w[0] = w[1] = w[2] = 1.0 / 3;
          }
        }
      }
      if (!proper)
      {
        ++nudges;
      }
      {
        const int* fv = TetMesh::FaceVertex[best];
        out.w[best] = 0;
        out.w[fv[0]] = w[0], out.w[fv[1]] = w[1], out.w[fv[2]] = w[2];
        const Vec3 p = q[fv[0]] * w[0] + q[fv[1]] * w[1] + q[fv[2]] * w[2];
        out.t = std::max(Dot(p, D) * InvDD, in.t);
        out.s = F[id[fv[0]]] * w[0] + F[id[fv[1]]] * w[1] + F[id[fv[2]]] * w[2];
      }
      if (!visit(t, in, out))
      {
        return;
      }
      stuck = out.t > in.t ? 0 : stuck + 1;
      const int next = M.Neighbours(t)[best];
      if (next < 0 || stuck > 256)
      {
        return;
      }
      // Enter the neighbour through the shared face: carry the shared vertices over; the one
      // new vertex is the apex, opposite the entry face.
      const auto& nv = M.Tet(next);
      int nid[4];
      Vec3 nq[4], ndq[4];
      double nw[4];
      entryFace = 0;
      for (int i = 0; i < 4; ++i)
      {
        int j = 0;
        while (j < 4 && id[j] != nv[i])
        {
          ++j;
        }
        nid[i] = nv[i];
        if (j < 4)
        {
          nq[i] = q[j];
          ndq[i] = dq[j];
          nw[i] = out.w[j];
        }
        else
        {
          nq[i] = P[nv[i]] - O;
          ndq[i] = Cross(D, nq[i]);
          nw[i] = 0;
          entryFace = i;
        }
      }
      for (int i = 0; i < 4; ++i)
      {
        id[i] = nid[i], q[i] = nq[i], dq[i] = ndq[i], in.w[i] = nw[i];
      }
      in.t = out.t;
      in.s = out.s;
      t = next;
    }
  }

private:
  void Fill(const std::array<int, 4>& v, int f, double wa, double wb, double wc, FaceCrossing& x) const
  {
    const int* fv = TetMesh::FaceVertex[f];
    x.w[f] = 0;
    x.w[fv[0]] = wa, x.w[fv[1]] = wb, x.w[fv[2]] = wc;
    const Vec3 p = P[v[fv[0]]] * wa + P[v[fv[1]]] * wb + P[v[fv[2]]] * wc;
    x.t = Dot(p - O, D) * InvDD;
    x.s = F[v[fv[0]]] * wa + F[v[fv[1]]] * wb + F[v[fv[2]]] * wc;
  }

  const TetMesh& M;
  const Vec3* P;
  const double* F;
  Vec3 O, D;
  double InvDD;
};
} // namespace art

#endif
