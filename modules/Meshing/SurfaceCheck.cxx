#include "SurfaceCheck.h"

#include <tetgen.h> // Shewchuk's exact orient3d and exactinit, as TetGen ships them

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace art
{
namespace
{
using P = const double*;

int Orient(P a, P b, P c, P d)
{
  const double o = orient3d(const_cast<double*>(a), const_cast<double*>(b), const_cast<double*>(c), const_cast<double*>(d));
  return (o > 0) - (o < 0);
}

// Orientation tests inside one plane: the sign of orient3d with a fixed point off the plane.
struct Plane2
{
  double L[3];
  Plane2(P a, P b, P c, double size)
  {
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
    double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; ++k)
    {
      L[k] = a[k] + (len > 0 ? n[k] / len : (k == 0 ? 1.0 : 0.0)) * size;
    }
  }
  int O(P a, P b, P c) const { return Orient(a, b, c, L); }
  // p on the closed segment ab, given that the three are collinear.
  static bool Within(P a, P b, P p)
  {
    for (int k = 0; k < 3; ++k)
    {
      if (p[k] < std::min(a[k], b[k]) || p[k] > std::max(a[k], b[k]))
      {
        return false;
      }
    }
    return true;
  }
  bool Segments(P a, P b, P c, P d) const // closed segments ab and cd meet
  {
    const int o1 = O(a, b, c), o2 = O(a, b, d), o3 = O(c, d, a), o4 = O(c, d, b);
    if (o1 * o2 < 0 && o3 * o4 < 0)
    {
      return true;
    }
    return (o1 == 0 && Within(a, b, c)) || (o2 == 0 && Within(a, b, d)) || (o3 == 0 && Within(c, d, a)) ||
      (o4 == 0 && Within(c, d, b));
  }
  bool InTriangle(P p, P a, P b, P c) const // closed triangle
  {
    const int s1 = O(a, b, p), s2 = O(b, c, p), s3 = O(c, a, p);
    const bool pos = s1 > 0 || s2 > 0 || s3 > 0, neg = s1 < 0 || s2 < 0 || s3 < 0;
    return !(pos && neg);
  }
  bool SegmentTriangle(P p, P q, P a, P b, P c) const
  {
    return InTriangle(p, a, b, c) || InTriangle(q, a, b, c) || Segments(p, q, a, b) || Segments(p, q, b, c) ||
      Segments(p, q, c, a);
  }
  bool Triangles(const P t[3], const P u[3]) const
  {
    for (int i = 0; i < 3; ++i)
    {
      if (SegmentTriangle(t[i], t[(i + 1) % 3], u[0], u[1], u[2]))
      {
        return true;
      }
    }
    return InTriangle(u[0], t[0], t[1], t[2]);
  }
};

// The closed segment pq meets the closed triangle abc.
bool SegmentTriangle(P p, P q, P a, P b, P c, double size)
{
  const int o1 = Orient(a, b, c, p), o2 = Orient(a, b, c, q);
  if (o1 == o2 && o1 != 0)
  {
    return false;
  }
  if (o1 == 0 && o2 == 0)
  {
    return Plane2(a, b, c, size).SegmentTriangle(p, q, a, b, c);
  }
  const int s1 = Orient(p, q, a, b), s2 = Orient(p, q, b, c), s3 = Orient(p, q, c, a);
  const bool pos = s1 > 0 || s2 > 0 || s3 > 0, neg = s1 < 0 || s2 < 0 || s3 < 0;
  return !(pos && neg);
}

// Triangles t and u (corner ids ti, ui) cross or touch other than along what they share.
bool Intersect(const double* pts, const std::array<int, 3>& ti, const std::array<int, 3>& ui, double size)
{
  P t[3], u[3];
  for (int k = 0; k < 3; ++k)
  {
    t[k] = pts + 3 * ti[k];
    u[k] = pts + 3 * ui[k];
  }
  int shared = 0, st[3], su[3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      if (ti[i] == ui[j])
      {
        st[shared] = i, su[shared] = j;
        ++shared;
      }
    }
  }
  const bool coplanar = Orient(t[0], t[1], t[2], u[0]) == 0 && Orient(t[0], t[1], t[2], u[1]) == 0 &&
    Orient(t[0], t[1], t[2], u[2]) == 0;
  if (shared == 3)
  {
    return true; // the same triangle twice
  }
  if (shared == 2)
  {
    if (!coplanar)
    {
      return false;
    }
    // Folded onto each other: the corners they do not share on the same side of the edge.
    const int wt = 3 - st[0] - st[1], wu = 3 - su[0] - su[1];
    const Plane2 pl(t[0], t[1], t[2], size);
    return pl.O(t[st[0]], t[st[1]], t[wt]) * pl.O(t[st[0]], t[st[1]], u[wu]) > 0;
  }
  if (shared == 1)
  {
    const int a = st[0], b = su[0];
    P t1 = t[(a + 1) % 3], t2 = t[(a + 2) % 3], u1 = u[(b + 1) % 3], u2 = u[(b + 2) % 3];
    if (coplanar)
    {
      const Plane2 pl(t[0], t[1], t[2], size);
      return pl.SegmentTriangle(t1, t2, u[0], u[1], u[2]) || pl.SegmentTriangle(u1, u2, t[0], t[1], t[2]);
    }
    return SegmentTriangle(t1, t2, u[0], u[1], u[2], size) || SegmentTriangle(u1, u2, t[0], t[1], t[2], size);
  }
  if (coplanar)
  {
    return Plane2(t[0], t[1], t[2], size).Triangles(t, u);
  }
  for (int i = 0; i < 3; ++i)
  {
    if (SegmentTriangle(t[i], t[(i + 1) % 3], u[0], u[1], u[2], size) ||
      SegmentTriangle(u[i], u[(i + 1) % 3], t[0], t[1], t[2], size))
    {
      return true;
    }
  }
  return false;
}

void MergePoints(TriangleSurface& s, SurfaceReport& r)
{
  const size_t n = s.Points.size() / 3;
  std::vector<int> order(n);
  for (size_t i = 0; i < n; ++i)
  {
    order[i] = static_cast<int>(i);
  }
  auto key = [&](int i) { return std::make_tuple(s.Points[3 * i], s.Points[3 * i + 1], s.Points[3 * i + 2]); };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) != key(b) ? key(a) < key(b) : a < b; });
  std::vector<int> to(n);
  std::vector<double> kept;
  for (size_t k = 0; k < n; ++k)
  {
    if (k > 0 && key(order[k]) == key(order[k - 1]))
    {
      to[order[k]] = to[order[k - 1]];
      ++r.MergedPoints;
      continue;
    }
    to[order[k]] = static_cast<int>(kept.size() / 3);
    kept.insert(kept.end(), s.Points.begin() + 3 * order[k], s.Points.begin() + 3 * order[k] + 3);
  }
  s.Points.swap(kept);
  std::vector<std::array<int, 3>> tris;
  tris.reserve(s.Triangles.size());
  for (auto t : s.Triangles)
  {
    for (int& v : t)
    {
      v = to[v];
    }
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
    {
      ++r.RepeatedCorners;
      continue;
    }
    tris.push_back(t);
  }
  s.Triangles.swap(tris);
}

void CountEdges(const TriangleSurface& s, SurfaceReport& r)
{
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * s.Triangles.size());
  for (const auto& t : s.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      edges.emplace_back(std::min(a, b), std::max(a, b));
    }
  }
  std::sort(edges.begin(), edges.end());
  for (size_t i = 0; i < edges.size();)
  {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i])
    {
      ++j;
    }
    r.OpenEdges += j - i == 1 ? 1 : 0;
    r.NonManifoldEdges += j - i > 2 ? 1 : 0;
    i = j;
  }
}

void CountDegenerate(const TriangleSurface& s, double size, SurfaceReport& r)
{
  for (const auto& t : s.Triangles)
  {
    P a = &s.Points[3 * t[0]], b = &s.Points[3 * t[1]], c = &s.Points[3 * t[2]];
    bool flat = true;
    for (int k = 0; k < 3 && flat; ++k)
    {
      double q[3] = { a[0], a[1], a[2] };
      q[k] += size;
      flat = Orient(a, b, c, q) == 0;
    }
    r.Degenerate += flat ? 1 : 0;
  }
}

void CountIntersections(const TriangleSurface& s, double size, SurfaceReport& r)
{
  const size_t nt = s.Triangles.size();
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  std::vector<std::array<double, 6>> box(nt);
  for (size_t i = 0; i < nt; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      box[i][k] = 1e300, box[i][k + 3] = -1e300;
    }
    for (int v : s.Triangles[i])
    {
      for (int k = 0; k < 3; ++k)
      {
        box[i][k] = std::min(box[i][k], s.Points[3 * v + k]);
        box[i][k + 3] = std::max(box[i][k + 3], s.Points[3 * v + k]);
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], box[i][k]);
      hi[k] = std::max(hi[k], box[i][k + 3]);
    }
  }
  // About two triangles a cell.
  double ext[3], vol = 1;
  for (int k = 0; k < 3; ++k)
  {
    ext[k] = std::max(hi[k] - lo[k], 1e-12 * size);
    vol *= ext[k];
  }
  const double cell = std::cbrt(2.0 * vol / std::max<double>(nt, 1));
  int n[3];
  for (int k = 0; k < 3; ++k)
  {
    n[k] = std::clamp(static_cast<int>(ext[k] / cell) + 1, 1, 1024);
  }
  auto range = [&](size_t i, int c0[3], int c1[3]) {
    for (int k = 0; k < 3; ++k)
    {
      c0[k] = std::clamp(static_cast<int>((box[i][k] - lo[k]) / ext[k] * n[k]), 0, n[k] - 1);
      c1[k] = std::clamp(static_cast<int>((box[i][k + 3] - lo[k]) / ext[k] * n[k]), 0, n[k] - 1);
    }
  };
  std::vector<std::vector<int>> cells(static_cast<size_t>(n[0]) * n[1] * n[2]);
  for (size_t i = 0; i < nt; ++i)
  {
    int c0[3], c1[3];
    range(i, c0, c1);
    for (int z = c0[2]; z <= c1[2]; ++z)
      for (int y = c0[1]; y <= c1[1]; ++y)
        for (int x = c0[0]; x <= c1[0]; ++x)
        {
          cells[x + static_cast<size_t>(n[0]) * (y + static_cast<size_t>(n[1]) * z)].push_back(static_cast<int>(i));
        }
  }
  for (size_t c = 0; c < cells.size(); ++c)
  {
    const auto& list = cells[c];
    for (size_t a = 0; a < list.size(); ++a)
    {
      for (size_t b = a + 1; b < list.size(); ++b)
      {
        const int i = list[a], j = list[b];
        bool apart = false;
        for (int k = 0; k < 3 && !apart; ++k)
        {
          apart = box[i][k] > box[j][k + 3] || box[j][k] > box[i][k + 3];
        }
        if (apart)
        {
          continue;
        }
        // Each pair once: in the first cell of both their ranges.
        int a0[3], a1[3], b0[3], b1[3];
        range(i, a0, a1);
        range(j, b0, b1);
        const size_t first = std::max(a0[0], b0[0]) +
          static_cast<size_t>(n[0]) * (std::max(a0[1], b0[1]) + static_cast<size_t>(n[1]) * std::max(a0[2], b0[2]));
        if (first != c || !Intersect(s.Points.data(), s.Triangles[i], s.Triangles[j], size))
        {
          continue;
        }
        if (r.Intersections++ == 0)
        {
          r.FirstIntersection = { { std::min(i, j), std::max(i, j) } };
        }
      }
    }
  }
}
} // namespace

std::string SurfaceReport::Problem() const
{
  std::ostringstream ss;
  if (Triangles < 4)
  {
    ss << "holds " << Triangles << " triangle" << (Triangles == 1 ? "" : "s") << ": a closed surface needs at least 4";
  }
  else if (!Closed())
  {
    ss << "is not a closed surface: ";
    const char* sep = "";
    if (OpenEdges > 0)
    {
      ss << OpenEdges << " open edge" << (OpenEdges == 1 ? "" : "s") << " (edges of only one triangle: it has holes)";
      sep = ", ";
    }
    if (NonManifoldEdges > 0)
    {
      ss << sep << NonManifoldEdges << " edge" << (NonManifoldEdges == 1 ? "" : "s")
         << " shared by three or more triangles";
      sep = ", ";
    }
    if (Degenerate > 0)
    {
      ss << sep << Degenerate << " triangle" << (Degenerate == 1 ? "" : "s") << " of no area";
    }
    ss << "; tetrahedralize needs a closed, manifold surface (close it first, e.g. with PyMeshFix or MeshLab)";
  }
  else if (Intersections > 0)
  {
    ss << "intersects itself: " << Intersections << " pair" << (Intersections == 1 ? "" : "s")
       << " of triangles cross or touch (the first: triangles " << FirstIntersection[0] << " and "
       << FirstIntersection[1] << "); tetrahedralize needs a surface that does not (repair it first, e.g. with "
       << "PyMeshFix or MeshLab)";
  }
  return ss.str();
}

SurfaceReport CheckSurface(TriangleSurface& surface)
{
  SurfaceReport r;
  MergePoints(surface, r);
  r.Points = static_cast<long long>(surface.Points.size() / 3);
  r.Triangles = static_cast<long long>(surface.Triangles.size());
  if (r.Triangles == 0)
  {
    return r;
  }
  double m = 0, lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (size_t i = 0; i < surface.Points.size(); ++i)
  {
    m = std::max(m, std::fabs(surface.Points[i]));
    lo[i % 3] = std::min(lo[i % 3], surface.Points[i]);
    hi[i % 3] = std::max(hi[i % 3], surface.Points[i]);
  }
  const double size = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300 });
  // The static filter's bound covers the points and the points off their planes the tests use.
  const double bound = 2.0 * (m + size) + 1.0;
  exactinit(0, 0, 0, bound, bound, bound);
  CountEdges(surface, r);
  CountDegenerate(surface, size, r);
  if (!r.Closed())
  {
    return r;
  }
  CountIntersections(surface, size, r);
  double v = 0;
  for (const auto& t : surface.Triangles)
  {
    P a = &surface.Points[3 * t[0]], b = &surface.Points[3 * t[1]], c = &surface.Points[3 * t[2]];
    v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  r.Volume = std::fabs(v) / 6.0;
  return r;
}
} // namespace art
