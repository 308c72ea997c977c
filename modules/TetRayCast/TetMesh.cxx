#include "TetMesh.h"
#include "Morton.h"
#include "ParallelTiles.h"

#include "Error.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <tuple>

namespace art
{
namespace
{
constexpr long long Grain = 1 << 14; // parallel chunks start at multiples of it: one slot each where needed
}

constexpr int TetMesh::FaceVertex[4][3];

TetMesh::TetMesh(std::vector<Vec3> points, std::vector<double> scalars, std::vector<std::array<int, 4>> tets)
  : Points(std::move(points))
  , Values(std::move(scalars))
{
  CheckInput(tets);
  TetRecords.resize(tets.size());
  for (std::size_t t = 0; t < tets.size(); ++t)
  {
    TetRecords[t].v = tets[t];
    TetRecords[t].link = { -1, -1, -1, -1 };
  }
  std::vector<std::array<int, 4>>().swap(tets);
  if (TetRecords.size() > LocalityThreshold)
  {
    SortForLocality();
  }
  Range[0] = *std::min_element(Values.begin(), Values.end());
  Range[1] = *std::max_element(Values.begin(), Values.end());
  for (const Vec3& p : Points)
  {
    Box.Expand(p);
  }
  const VertexTets vt = IncidentTets();
  const std::vector<double> volume = OrientAndInterpolate();
  VertexGradients(vt, volume);
  LinkFaces(vt, volume);
  FindBoundary();
  LinkBoundaryEdges();
}

void TetMesh::CheckInput(const std::vector<std::array<int, 4>>& tets) const
{
  const int np = static_cast<int>(Points.size());
  if (Values.size() != Points.size())
  {
    throw Error("point scalars do not match the points (" + std::to_string(Values.size()) + " values for " +
      std::to_string(np) + " points)");
  }
  if (tets.empty())
  {
    throw Error("mesh has no tetrahedra");
  }
  if (tets.size() >= (std::size_t(1) << 29))
  {
    throw Error("mesh has " + std::to_string(tets.size()) + " tetrahedra; at most 2^29 are supported");
  }
  for (std::size_t i = 0; i < Points.size(); ++i)
  {
    if (!IsFinite(Points[i]))
    {
      throw Error("point " + std::to_string(i) + " has a NaN or infinite coordinate");
    }
  }
  // A masked field (NaN outside a region, as simulations and ParaView's filters leave it): where,
  // how many and what to do, not only an index into a mesh the user never numbered.
  const auto notFinite = [](double v) { return !std::isfinite(v); };
  const auto bad = std::find_if(Values.begin(), Values.end(), notFinite);
  if (bad != Values.end())
  {
    const std::size_t i = bad - Values.begin();
    const long long count = std::count_if(bad, Values.end(), notFinite);
    char at[160];
    std::snprintf(at, sizeof at, "x, y, z = %.6g, %.6g, %.6g", Points[i].x, Points[i].y, Points[i].z);
    throw Error(std::to_string(count) + (count > 1 ? " points have" : " point has") + " a NaN or infinite scalar (the first at " +
      at + "); rendering needs finite values: replace them (e.g. ParaView's Calculator, numpy.nan_to_num) or cut "
      "those cells away (ParaView's Threshold)");
  }
  for (std::size_t t = 0; t < tets.size(); ++t)
  {
    for (int id : tets[t])
    {
      if (id < 0 || id >= np)
      {
        throw Error("tet " + std::to_string(t) + " refers to point " + std::to_string(id) + " of " + std::to_string(np));
      }
    }
  }
}

TetMesh::VertexTets TetMesh::IncidentTets() const
{
  // About 20 tets per vertex to look through, for the gradients and the face links, instead of a
  // sort of all 4n faces (and none of the sort's 20 bytes per face).
  VertexTets vt;
  vt.First.assign(Points.size() + 1, 0);
  vt.Tets.resize(4 * TetRecords.size());
  for (const auto& r : TetRecords)
  {
    for (int id : r.v)
    {
      ++vt.First[id + 1];
    }
  }
  std::partial_sum(vt.First.begin(), vt.First.end(), vt.First.begin());
  std::vector<int> next(vt.First.begin(), vt.First.end() - 1);
  for (std::size_t t = 0; t < TetRecords.size(); ++t)
  {
    for (int id : TetRecords[t].v)
    {
      vt.Tets[next[id]++] = static_cast<int>(t);
    }
  }
  return vt;
}

std::vector<double> TetMesh::OrientAndInterpolate()
{
  // Each tet positively oriented, its linear interpolant by Cramer's rule (a flat tet keeps a
  // constant, its mean), its volume, and the longest edge of all.
  const std::size_t nt = TetRecords.size();
  Interp.resize(nt);
  std::vector<double> volume(nt);
  std::vector<double> longest(static_cast<std::size_t>((nt + Grain - 1) / Grain), 0.0);
  ForEachRange(static_cast<long long>(nt), Grain, [&](long long b, long long e, Counters&) {
    double L = 0;
    for (long long t = b; t < e; ++t)
    {
      auto& v = TetRecords[t].v;
      Vec3 e1 = Points[v[1]] - Points[v[0]], e2 = Points[v[2]] - Points[v[0]], e3 = Points[v[3]] - Points[v[0]];
      double det = Dot(e1, Cross(e2, e3));
      if (det < 0)
      {
        std::swap(v[0], v[1]);
        std::swap(e1, e2);
        e3 = Points[v[3]] - Points[v[0]];
        e1 = Points[v[1]] - Points[v[0]];
        e2 = Points[v[2]] - Points[v[0]];
        det = -det;
      }
      const double f0 = Values[v[0]];
      Vec3 g;
      if (det > 0)
      {
        g = (Cross(e2, e3) * (Values[v[1]] - f0) + Cross(e3, e1) * (Values[v[2]] - f0) +
              Cross(e1, e2) * (Values[v[3]] - f0)) / det;
      }
      const double a = det > 0 ? f0 - Dot(g, Points[v[0]])
                               : 0.25 * (f0 + Values[v[1]] + Values[v[2]] + Values[v[3]]);
      Interp[t] = { a, g.x, g.y, g.z };
      volume[t] = det / 6.0;
      for (int i = 0; i < 4; ++i)
      {
        for (int j = i + 1; j < 4; ++j)
        {
          L = std::max(L, Length(Points[v[i]] - Points[v[j]]));
        }
      }
    }
    longest[static_cast<std::size_t>(b / Grain)] = L;
  });
  LongestEdge = longest.empty() ? 0.0 : *std::max_element(longest.begin(), longest.end());
  return volume;
}

void TetMesh::VertexGradients(const VertexTets& vt, const std::vector<double>& volume)
{
  // Volume-weighted mean of the incident tets' gradients, summed in ascending tet order.
  Gradients.assign(Points.size(), Vec3());
  ForEachRange(static_cast<long long>(Points.size()), Grain, [&](long long b, long long e, Counters&) {
    for (long long i = b; i < e; ++i)
    {
      Vec3 g;
      double w = 0;
      for (int k = vt.First[i]; k < vt.First[i + 1]; ++k)
      {
        const auto& c = Interp[vt.Tets[k]];
        const double vol = volume[vt.Tets[k]];
        g += Vec3(c[1], c[2], c[3]) * vol;
        w += vol;
      }
      if (w > 0)
      {
        Gradients[i] = g / w;
      }
    }
  });
}

void TetMesh::LinkFaces(const VertexTets& vt, const std::vector<double>& volume)
{
  // Face neighbours, vertex by vertex: the faces whose lowest vertex is i come from i's incident
  // tets, and equal faces among those few are the shared ones. Each face belongs to one vertex,
  // so each link is written once, from whichever thread takes that vertex.
  struct LocalFace
  {
    int b, c, ref; // the face's other two vertices (sorted) and 4 tet + face
    bool odd;      // the face's outward order is an odd permutation of (i, b, c)
    bool operator<(const LocalFace& o) const { return std::tie(b, c, ref) < std::tie(o.b, o.c, o.ref); }
  };
  // Links vertex i's faces; returns the first inconsistent run of equal faces (empty when none).
  auto linkFaces = [&](int i, std::vector<LocalFace>& faces) -> std::pair<int, int> {
    faces.clear();
    for (int k = vt.First[i]; k < vt.First[i + 1]; ++k)
    {
      const int t = vt.Tets[k];
      if (k > vt.First[i] && vt.Tets[k - 1] == t) // a tet listed twice repeats vertex i
      {
        continue;
      }
      const auto& v = TetRecords[t].v;
      for (int f = 0; f < 4; ++f)
      {
        const int* fv = FaceVertex[f];
        const int x = v[fv[0]], y = v[fv[1]], z = v[fv[2]];
        if (std::min(x, std::min(y, z)) != i)
        {
          continue;
        }
        const bool odd = (((x > y) + (x > z) + (y > z)) & 1) != 0;
        const int hi = std::max(x, std::max(y, z)), mid = x + y + z - i - hi;
        faces.push_back({ mid, hi, 4 * t + f, odd });
      }
    }
    std::sort(faces.begin(), faces.end());
    for (std::size_t r = 0; r < faces.size();)
    {
      std::size_t e = r + 1;
      while (e < faces.size() && faces[e].b == faces[r].b && faces[e].c == faces[r].c)
      {
        ++e;
      }
      // Two tets on one side of their face overlap; a flat tet (zero volume, as Delaunay meshes
      // of lattice points have) has no side, so it links either way.
      if (e - r > 2 || (e - r == 2 && faces[r].odd == faces[r + 1].odd && volume[faces[r].ref / 4] > 0 &&
                         volume[faces[r + 1].ref / 4] > 0))
      {
        return { static_cast<int>(r), static_cast<int>(e - r) };
      }
      if (e - r == 2)
      {
        const int pa = faces[r].ref, pb = faces[r + 1].ref;
        TetRecords[pa / 4].link[pa % 4] = pb;
        TetRecords[pb / 4].link[pb % 4] = pa;
      }
      r = e;
    }
    return { -1, 0 };
  };
  std::atomic<bool> inconsistent{ false };
  ForEachRange(static_cast<long long>(Points.size()), Grain, [&](long long b, long long e, Counters&) {
    std::vector<LocalFace> faces;
    for (long long i = b; i < e; ++i)
    {
      if (linkFaces(static_cast<int>(i), faces).first >= 0)
      {
        inconsistent = true;
      }
    }
  });
  if (!inconsistent)
  {
    return;
  }
  // The first inconsistency in vertex order, so the message is the same on every run.
  std::vector<LocalFace> faces;
  for (int i = 0; i < static_cast<int>(Points.size()); ++i)
  {
    const auto [r, n] = linkFaces(i, faces);
    if (r < 0)
    {
      continue;
    }
    const int ta = faces[r].ref / 4;
    if (n > 2)
    {
      throw Error("inconsistent neighbours: a face of tet " + std::to_string(ta) + " is shared by " +
        std::to_string(n) + " tets");
    }
    throw Error("inconsistent neighbours: tets " + std::to_string(ta) + " and " +
      std::to_string(faces[r + 1].ref / 4) + " lie on the same side of their shared face (overlap)");
  }
}

void TetMesh::FindBoundary()
{
  for (std::size_t t = 0; t < TetRecords.size(); ++t)
  {
    for (int f = 0; f < 4; ++f)
    {
      if (TetRecords[t].link[f] < 0)
      {
        Boundary.push_back({ static_cast<int>(t), f });
      }
    }
  }
  BPlanes.reserve(Boundary.size());
  for (const auto& b : Boundary)
  {
    BPlanes.push_back(FacePlane(b[0], b[1]));
  }
}

void TetMesh::LinkBoundaryEdges()
{
  // Boundary edge adjacency, and convexity: every boundary dihedral convex, one boundary shell.
  struct EdgeKey
  {
    int a, b, face, k;
    bool operator<(const EdgeKey& o) const { return std::tie(a, b) < std::tie(o.a, o.b); }
  };
  std::vector<EdgeKey> edges;
  edges.reserve(3 * Boundary.size());
  for (std::size_t b = 0; b < Boundary.size(); ++b)
  {
    const auto& v = TetRecords[Boundary[b][0]].v;
    const auto& fv = FaceVertex[Boundary[b][1]];
    for (int k = 0; k < 3; ++k)
    {
      const int x = v[fv[k]], y = v[fv[(k + 1) % 3]];
      edges.push_back({ std::min(x, y), std::max(x, y), static_cast<int>(b), k });
    }
  }
  vtkSMPTools::Sort(edges.begin(), edges.end());
  BoundaryAdj.assign(Boundary.size(), { -1, -1, -1 });
  const double eps = 1e-9 * std::max(Box.Diagonal(), 1e-300);
  for (std::size_t i = 0; i < edges.size();)
  {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b)
    {
      ++j;
    }
    if (j - i != 2)
    {
      Convex = false; // open or non-manifold boundary
      i = j;
      continue;
    }
    const EdgeKey &p = edges[i], &q = edges[i + 1];
    BoundaryAdj[p.face][p.k] = q.face;
    BoundaryAdj[q.face][q.k] = p.face;
    // q's third vertex must not lie in front of p's plane.
    const auto& qb = Boundary[q.face];
    const int third = TetRecords[qb[0]].v[FaceVertex[qb[1]][(q.k + 2) % 3]];
    const Plane& pl = BPlanes[p.face];
    if (Dot(pl.n, Points[third]) - pl.d > eps)
    {
      Convex = false;
    }
    i = j;
  }
  if (!Convex || Boundary.empty())
  {
    return;
  }
  // One shell: every boundary face reached from the first across edges.
  std::vector<char> seen(Boundary.size(), 0);
  std::vector<int> stack{ 0 };
  seen[0] = 1;
  std::size_t count = 1;
  while (!stack.empty())
  {
    const int b = stack.back();
    stack.pop_back();
    for (int n : BoundaryAdj[b])
    {
      if (n >= 0 && !seen[n])
      {
        seen[n] = 1;
        ++count;
        stack.push_back(n);
      }
    }
  }
  Convex = count == Boundary.size();
}

void TetMesh::SortForLocality()
{
  // A ray walks to face neighbours in every direction; in input order (x fastest for a volume)
  // a step in z jumps megabytes. Z-order of points and of tet centroids keeps neighbours close.
  Box3 box;
  for (const Vec3& p : Points)
  {
    box.Expand(p);
  }
  auto code = [&](const Vec3& p) { return MortonCode(p, box); };
  std::vector<std::pair<std::uint64_t, int>> order(Points.size());
  for (std::size_t i = 0; i < Points.size(); ++i)
  {
    order[i] = { code(Points[i]), static_cast<int>(i) };
  }
  vtkSMPTools::Sort(order.begin(), order.end());
  std::vector<int> newId(Points.size());
  std::vector<Vec3> pts(Points.size());
  std::vector<double> val(Points.size());
  for (std::size_t i = 0; i < order.size(); ++i)
  {
    newId[order[i].second] = static_cast<int>(i);
    pts[i] = Points[order[i].second];
    val[i] = Values[order[i].second];
  }
  Points.swap(pts);
  Values.swap(val);
  order.resize(TetRecords.size());
  for (std::size_t t = 0; t < TetRecords.size(); ++t)
  {
    auto& v = TetRecords[t].v;
    for (int& id : v)
    {
      id = newId[id];
    }
    order[t] = { code((Points[v[0]] + Points[v[1]] + Points[v[2]] + Points[v[3]]) * 0.25), static_cast<int>(t) };
  }
  vtkSMPTools::Sort(order.begin(), order.end());
  std::vector<TetRecord> tets(TetRecords.size());
  for (std::size_t t = 0; t < order.size(); ++t)
  {
    tets[t] = TetRecords[order[t].second];
  }
  TetRecords.swap(tets);
}

void TetMesh::Barycentric(std::size_t t, const Vec3& p, double w[4]) const
{
  const auto& v = TetRecords[t].v;
  const Vec3 &a = Points[v[0]], e1 = Points[v[1]] - a, e2 = Points[v[2]] - a, e3 = Points[v[3]] - a, x = p - a;
  const double vol = Dot(e1, Cross(e2, e3));
  if (!(std::fabs(vol) > 0))
  {
    w[0] = w[1] = w[2] = w[3] = 0.25;
    return;
  }
  w[1] = Dot(x, Cross(e2, e3)) / vol;
  w[2] = Dot(e1, Cross(x, e3)) / vol;
  w[3] = Dot(e1, Cross(e2, x)) / vol;
  w[0] = 1.0 - w[1] - w[2] - w[3];
}

int TetMesh::Locate(const Vec3& p) const
{
  const double tol = -1e-12;
  auto inside = [&](std::size_t t, int* beyond) {
    double w[4];
    Barycentric(t, p, w);
    const int k = static_cast<int>(std::min_element(w, w + 4) - w);
    if (beyond)
    {
      *beyond = k;
    }
    return w[k] >= tol;
  };
  if (!Box.Contains(p))
  {
    return -1;
  }
  int t = 0;
  for (int step = 0; step < 100000; ++step)
  {
    int k;
    if (inside(t, &k))
    {
      return t;
    }
    const int next = LinkTet(TetRecords[t].link[k]);
    if (next < 0)
    {
      break;
    }
    t = next;
  }
  for (std::size_t u = 0; u < TetRecords.size(); ++u)
  {
    if (inside(u, nullptr))
    {
      return static_cast<int>(u);
    }
  }
  return -1;
}

TetMesh::Plane TetMesh::FacePlane(std::size_t t, int f) const
{
  const auto& v = TetRecords[t].v;
  const Vec3& p0 = Points[v[FaceVertex[f][0]]];
  const Vec3 n = Normalize(Cross(Points[v[FaceVertex[f][1]]] - p0, Points[v[FaceVertex[f][2]]] - p0));
  return { n, Dot(n, p0) };
}
} // namespace art
