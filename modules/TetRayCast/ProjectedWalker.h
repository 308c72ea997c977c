// ProjectedWalker: the face-to-face walk (FaceWalk.h; Grosso, Luerig & Ertl 1997, sec. 5) for the
// primary rays of one camera, in the camera's projection. Rays from a common eye E have side
// products D.((a-E) x (b-E)) = Dz za zb orient2d(a', b', p) with a' the vertex projected onto the
// plane z = 1 of the view and p the pixel (Platis & Theoharis 2003 in screen space): with every
// vertex in front of the eye the 2-D signs decide the exit face, and the 2-D weights lambda_i give
// the world weights as lambda_i / z_i renormalised (perspective-correct interpolation). A parallel
// camera's projection is affine: the same 2-D products, weights as they are, t from the depth.
// The vertices are projected once per frame (ProjectedView); a step then costs two subtractions
// per corner and two products per side instead of TetWalker's 3-D cross and dot products.
// The projection rounds the vertices in a rotated frame: a ray exactly in a face plane or through
// an edge (an axis-aligned view of a grid), where TetWalker's products come out exactly zero,
// would get products of random sign. So a 2-D product within its rounding bound is replaced by
// TetWalker's 3-D one for that edge (rare: the ray within ~1e-13 of an edge).
#ifndef art_ProjectedWalker_h
#define art_ProjectedWalker_h

#include "AdaptiveRTTetRayCastModule.h"
#include "Camera.h"
#include "TetWalker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace art
{
/// A camera's view of a mesh's vertices: for perspective (x/z, y/z, 1/z, f/z), for parallel
/// (x, y, z, f), in an orthonormal right-handed frame with z along the view direction.
class ADAPTIVERTTETRAYCAST_EXPORT ProjectedView
{
public:
  struct Vertex
  {
    double x, y, m, n;
  };

  /// Projects every vertex of m for cam (in parallel). Valid() is false for a perspective camera
  /// with any vertex behind, at or too close to the eye's plane: then the signs of the 2-D
  /// products are not the ray's, and the 3-D TetWalker must walk.
  ProjectedView(const TetMesh& m, const Camera& cam);

  bool Valid() const { return Ok; }
  /// Largest |x| + |y| of a projected vertex (perspective), or |x| + |y| + |z| (parallel).
  double Extent() const { return Amax; }
  /// Can ray r walk in this view? Only the camera's own rays: from the eye (perspective) or along
  /// the view direction (parallel), as Camera::Generate makes them.
  bool Fits(const Ray& r) const
  {
    return Ok && (Parallel ? r.dir.x == Fwd.x && r.dir.y == Fwd.y && r.dir.z == Fwd.z
                           : r.org.x == Eye.x && r.org.y == Eye.y && r.org.z == Eye.z);
  }

  const TetMesh& Mesh() const { return M; }
  const Vertex* Vertices() const { return V.data(); }
  bool IsParallel() const { return Parallel; }
  const Vec3& Position() const { return Eye; }
  /// The view frame: Right x Up = Forward.
  const Vec3& Right() const { return R; }
  const Vec3& Up() const { return U; }
  const Vec3& Forward() const { return Fwd; }

private:
  const TetMesh& M;
  std::vector<Vertex> V;
  Vec3 Eye, R, U, Fwd;
  double Amax = 0;
  bool Parallel = false, Ok = false;
};

class ProjectedWalker
{
public:
  /// For a ray the view Fits().
  ProjectedWalker(const ProjectedView& v, const Ray& r)
    : M(v.Mesh()), V(v.Vertices()), P(v.Mesh().PointsArray().data()), O(r.org), D(r.dir),
      Persp(!v.IsParallel())
  {
    const double dz = Dot(r.dir, v.Forward());
    InvDz = 1.0 / dz;
    // Rounding bound of a 2-D product (a generous multiple of a first-order error analysis):
    // perspective coordinates carry ~eps B^2 (B bounds |x| + |y| of vertices and pixel), parallel
    // ones ~eps B (B bounds the vertices' and origin's distances from the eye).
    constexpr double eps = 1.1102230246251565e-16;
    if (Persp)
    {
      Px = Dot(r.dir, v.Right()) * InvDz, Py = Dot(r.dir, v.Up()) * InvDz;
      const double b = std::max({ 1.0, v.Extent(), std::fabs(Px) + std::fabs(Py) });
      Eps = 1024 * eps * b * b * b;
    }
    else
    {
      const Vec3 q = r.org - v.Position();
      Px = Dot(q, v.Right()), Py = Dot(q, v.Up()), Z0 = Dot(q, v.Forward());
      const double b = std::max(v.Extent(), std::fabs(Px) + std::fabs(Py) + std::fabs(Z0));
      Eps = 256 * eps * b * b;
    }
  }

  /// As TetWalker::Walk, with the same crossings up to round-off.
  template <class Visit>
  ART_ALWAYS_INLINE void Walk(int t, int entryFace, FaceCrossing in, Visit&& visit, FaceCrossing& out,
    std::uint64_t& steps, std::uint64_t& nudges, const TetRecord* records = nullptr) const
  {
    WalkFaces(M, *this, t, entryFace, in, visit, out, steps, nudges, records);
  }

  /// As TetWalker::Crosses, with the walk's 2-D products: an entry found here is the one the walk
  /// itself would take (and costs 30% less than the 3-D test).
  bool Crosses(int t, int f, int sense, FaceCrossing& x) const
  {
    const auto& v = M.Tet(t);
    const int* fv = TetMesh::FaceVertex[f];
    return CrossesFace(v[fv[0]], v[fv[1]], v[fv[2]], sense, x);
  }
  /// The same for the face with vertices a, b, c in its tet's outward order.
  bool CrossesFace(int ia, int ib, int ic, int sense, FaceCrossing& x) const
  {
    const Corner a = MakeCorner(ia), b = MakeCorner(ib), c = MakeCorner(ic);
    const double s01 = sense * Side(a, b), s12 = sense * Side(b, c), s20 = sense * Side(c, a);
    if (s01 < 0 || s12 < 0 || s20 < 0 || !(s01 + s12 + s20 > 0))
    {
      return false;
    }
    FaceExit(a, b, c, s12, s20, s01, -std::numeric_limits<double>::infinity(), x);
    return true;
  }

  // The walk's geometry (see TetWalker).
  /// A vertex relative to the pixel, with its perspective (or depth) and scalar terms.
  struct Corner
  {
    int id = -1;
    double x = 0, y = 0, m = 0, n = 0;
  };
  Corner MakeCorner(int id) const
  {
    const ProjectedView::Vertex& p = V[id];
    return { id, p.x - Px, p.y - Py, p.m, p.n };
  }
  /// orient2d of the edge u -> v about the pixel, positive factors (Dz zu zv) dropped. Unlike the
  /// 3-D product it needs no global id order for a face shared by two tets to get the same bits
  /// from both: products commute and rounding is symmetric, so v -> u gives exactly the negated
  /// value (up to the sign of a zero, which no test looks at). Within the rounding bound, the 3-D
  /// product in id order.
  double Side(const Corner& u, const Corner& v) const
  {
    const double s = u.x * v.y - u.y * v.x;
    if (__builtin_expect(std::fabs(s) <= Eps, 0))
    {
      return Exact(u, v);
    }
    return s;
  }
  /// The walk's exit crossing, not before tIn: the face opposite c[x] with screen weights W
  /// (FaceWalk.h; W[x] = 0, W[3] for d), perspective-correct. Sums run over the four corners in
  /// this order, ((0 + 1) + (2 + 3)), as a vector of them would add them.
  void Exit(const Corner c[3], int x, const Corner& d, const double W[4], double tIn, FaceCrossing& out) const
  {
    (void)x;
    const double l = (W[0] + W[1]) + (W[2] + W[3]);
    const double wm = (W[0] * c[0].m + W[1] * c[1].m) + (W[2] * c[2].m + W[3] * d.m);
    const double wn = (W[0] * c[0].n + W[1] * c[1].n) + (W[2] * c[2].n + W[3] * d.n);
    if (!(l > 0))
    {
      const int x1 = walk::Next[x], x2 = walk::Next[x1];
      FaceExit(c[x2], c[x1], d, 1.0, 1.0, 1.0, tIn, out);
      return;
    }
    Crossing(l, wm, wn, tIn, out);
  }
  /// The crossing from the weights' sum l and their sums with m and n.
  void Crossing(double l, double wm, double wn, double tIn, FaceCrossing& out) const
  {
    if (Persp)
    {
      // World weights lambda_i / z_i: the depth is sum(lambda) / sum(lambda_i / z_i).
      const double inv = 1.0 / wm;
      out.t = std::max(l * inv * InvDz, tIn);
      out.s = wn * inv;
    }
    else
    {
      const double inv = 1.0 / l;
      out.t = std::max((wm * inv - Z0) * InvDz, tIn);
      out.s = wn * inv;
    }
  }
  /// Screen weights wu, ww, wd (>= 0, not normalised) to the crossing of face (u, w, d).
  void FaceExit(const Corner& u, const Corner& w, const Corner& d, double wu, double ww, double wd,
    double tIn, FaceCrossing& out) const
  {
    double l = wu + ww + wd;
    if (!(l > 0))
    {
      wu = ww = wd = 1.0, l = 3.0;
    }
    Crossing(l, wu * u.m + ww * w.m + wd * d.m, wu * u.n + ww * w.n + wd * d.n, tIn, out);
  }

  // What a walk of its own (ProjectedWalkAvx2.h) needs besides the above.
  const ProjectedView::Vertex* Vertices() const { return V; }
  double PixelX() const { return Px; }
  double PixelY() const { return Py; }
  /// Side's rounding bound: a product within it is taken by Exact.
  double Bound() const { return Eps; }
  /// TetWalker::Side(u, v) scaled to the 2-D products: divided by Dz zu zv (perspective) or Dz.
  __attribute__((noinline)) double Exact(const Corner& u, const Corner& v) const
  {
    const int lo = std::min(u.id, v.id), hi = std::max(u.id, v.id);
    const double s = Dot(Cross(D, P[lo] - O), P[hi] - O) * (Persp ? InvDz * u.m * v.m : InvDz);
    return u.id < v.id ? s : -s;
  }

private:
  const TetMesh& M;
  const ProjectedView::Vertex* V;
  const Vec3* P;
  Vec3 O, D;
  double Px = 0, Py = 0, InvDz = 1, Z0 = 0, Eps = 0;
  bool Persp;
};
} // namespace art

#endif
