#include "TetMesh.h"
#include "ArrayChoice.h"
#include "Morton.h"
#include "ParallelTiles.h"

#include "Error.h"

#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkCellData.h>
#include <vtkCellTypes.h>
#include <vtkGenericCell.h>
#include <vtkCellDataToPointData.h>
#include <vtkDataSetTriangleFilter.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSMPTools.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdint>
#include <cmath>
#include <numeric>
#include <tuple>

#include <unistd.h>

namespace art
{
constexpr int TetMesh::FaceVertex[4][3];

TetMesh::TetMesh(std::vector<Vec3> points, std::vector<double> scalars, std::vector<std::array<int, 4>> tets)
  : Points(std::move(points))
  , Values(std::move(scalars))
  , Tets(std::move(tets))
{
  const int np = static_cast<int>(Points.size());
  if (Values.size() != Points.size())
  {
    throw Error("point scalars do not match the points (" + std::to_string(Values.size()) + " values for " +
      std::to_string(np) + " points)");
  }
  if (Tets.empty())
  {
    throw Error("mesh has no tetrahedra");
  }
  if (Tets.size() >= (std::size_t(1) << 29))
  {
    throw Error("mesh has " + std::to_string(Tets.size()) + " tetrahedra; at most 2^29 are supported");
  }
  for (std::size_t i = 0; i < Points.size(); ++i)
  {
    if (!IsFinite(Points[i]) || !std::isfinite(Values[i]))
    {
      throw Error("point " + std::to_string(i) + " has a non-finite coordinate or scalar");
    }
  }
  for (std::size_t t = 0; t < Tets.size(); ++t)
  {
    for (int id : Tets[t])
    {
      if (id < 0 || id >= np)
      {
        throw Error("tet " + std::to_string(t) + " refers to point " + std::to_string(id) + " of " + std::to_string(np));
      }
    }
  }
  if (Tets.size() > LocalityThreshold)
  {
    SortForLocality();
  }
  Range[0] = *std::min_element(Values.begin(), Values.end());
  Range[1] = *std::max_element(Values.begin(), Values.end());
  const std::size_t nt = Tets.size();
  const long long grain = 1 << 14; // chunks start at multiples of it: one slot each where needed

  // Vertex -> incident tets in ascending order (CSR), for the vertex gradients and the face links:
  // about 20 tets per vertex to look through instead of a sort of all 4n faces (3x faster on the
  // CT's 4.3 M full-resolution tets, and none of the sort's 20 bytes per face).
  std::vector<int> first(Points.size() + 1, 0), incident(4 * nt);
  for (const auto& v : Tets)
  {
    for (int id : v)
    {
      ++first[id + 1];
    }
  }
  std::partial_sum(first.begin(), first.end(), first.begin());
  {
    std::vector<int> next(first.begin(), first.end() - 1);
    for (std::size_t t = 0; t < nt; ++t)
    {
      for (int id : Tets[t])
      {
        incident[next[id]++] = static_cast<int>(t);
      }
    }
  }

  Interp.resize(nt);
  std::vector<double> volume(nt);
  std::vector<double> longest(static_cast<std::size_t>((nt + grain - 1) / grain), 0.0);
  ForEachRange(static_cast<long long>(nt), grain, [&](long long b, long long e, Counters&) {
    double L = 0;
    for (long long t = b; t < e; ++t)
    {
      auto& v = Tets[t];
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
      // Linear interpolant by Cramer's rule; a flat tet keeps a constant (its mean).
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
    longest[static_cast<std::size_t>(b / grain)] = L;
  });
  LongestEdge = longest.empty() ? 0.0 : *std::max_element(longest.begin(), longest.end());
  // Volume-weighted mean of the incident tets' gradients, summed in ascending tet order.
  Gradients.assign(Points.size(), Vec3());
  ForEachRange(static_cast<long long>(Points.size()), grain, [&](long long b, long long e, Counters&) {
    for (long long i = b; i < e; ++i)
    {
      Vec3 g;
      double w = 0;
      for (int k = first[i]; k < first[i + 1]; ++k)
      {
        const auto& c = Interp[incident[k]];
        const double vol = volume[incident[k]];
        g += Vec3(c[1], c[2], c[3]) * vol;
        w += vol;
      }
      if (w > 0)
      {
        Gradients[i] = g / w;
      }
    }
  });
  for (const Vec3& p : Points)
  {
    Box.Expand(p);
  }

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
    for (int k = first[i]; k < first[i + 1]; ++k)
    {
      const int t = incident[k];
      if (k > first[i] && incident[k - 1] == t) // a tet listed twice repeats vertex i
      {
        continue;
      }
      for (int f = 0; f < 4; ++f)
      {
        const int* fv = FaceVertex[f];
        const int x = Tets[t][fv[0]], y = Tets[t][fv[1]], z = Tets[t][fv[2]];
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
        Links[pa / 4][pa % 4] = pb;
        Links[pb / 4][pb % 4] = pa;
      }
      r = e;
    }
    return { -1, 0 };
  };
  Links.assign(nt, { -1, -1, -1, -1 });
  std::atomic<bool> inconsistent{ false };
  ForEachRange(static_cast<long long>(Points.size()), grain, [&](long long b, long long e, Counters&) {
    std::vector<LocalFace> faces;
    for (long long i = b; i < e; ++i)
    {
      if (linkFaces(static_cast<int>(i), faces).first >= 0)
      {
        inconsistent = true;
      }
    }
  });
  if (inconsistent)
  {
    // The first inconsistency in vertex order, so the message is the same on every run.
    std::vector<LocalFace> faces;
    for (int i = 0; i < np; ++i)
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
  for (std::size_t t = 0; t < nt; ++t)
  {
    for (int f = 0; f < 4; ++f)
    {
      if (Links[t][f] < 0)
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
    const auto& v = Tets[Boundary[b][0]];
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
    const int third = Tets[qb[0]][FaceVertex[qb[1]][(q.k + 2) % 3]];
    const Plane& pl = BPlanes[p.face];
    if (Dot(pl.n, Points[third]) - pl.d > eps)
    {
      Convex = false;
    }
    i = j;
  }
  if (Convex && !Boundary.empty())
  {
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
  order.resize(Tets.size());
  for (std::size_t t = 0; t < Tets.size(); ++t)
  {
    auto& v = Tets[t];
    for (int& id : v)
    {
      id = newId[id];
    }
    order[t] = { code((Points[v[0]] + Points[v[1]] + Points[v[2]] + Points[v[3]]) * 0.25), static_cast<int>(t) };
  }
  vtkSMPTools::Sort(order.begin(), order.end());
  std::vector<std::array<int, 4>> tets(Tets.size());
  for (std::size_t t = 0; t < order.size(); ++t)
  {
    tets[t] = Tets[order[t].second];
  }
  Tets.swap(tets);
}

void TetMesh::Barycentric(std::size_t t, const Vec3& p, double w[4]) const
{
  const auto& v = Tets[t];
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
    const int next = LinkTet(Links[t][k]);
    if (next < 0)
    {
      break;
    }
    t = next;
  }
  for (std::size_t u = 0; u < Tets.size(); ++u)
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
  const auto& v = Tets[t];
  const Vec3& p0 = Points[v[FaceVertex[f][0]]];
  const Vec3 n = Normalize(Cross(Points[v[FaceVertex[f][1]]] - p0, Points[v[FaceVertex[f][2]]] - p0));
  return { n, Dot(n, p0) };
}

void TetMesh::CheckFullResolutionFits(long long tets, double machineBytes, const std::string& file)
{
  if (tets >= (1LL << 29))
  {
    throw Error("volume too large for full-resolution tets (" + std::to_string(tets) +
        " tets, at most 2^29); reduce it first (--tets N or --max-error E)",
      file);
  }
  // About 160 bytes per tet with its share of the vertices (measured: 660 MB for the 4.3 M tets of
  // the 128 x 128 x 54 CT). Past the machine's memory the build would be killed without a word.
  const double need = 160.0 * tets;
  if (machineBytes > 0 && need > 0.8 * machineBytes)
  {
    char msg[200];
    std::snprintf(msg, sizeof msg,
      "full-resolution tets of this volume (%lld) need about %.3g GB, more than this machine's %.3g GB allows; "
      "reduce it first (--tets N or --max-error E)",
      tets, need / 1e9, machineBytes / 1e9);
    throw Error(msg, file);
  }
}

TetMesh TetMesh::FromImage(vtkImageData* image, const std::string& file)
{
  vtkDataArray* s = image ? image->GetPointData()->GetScalars() : nullptr;
  int d[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(d);
  }
  if (!s)
  {
    throw Error("volume has no point scalars", file);
  }
  if (d[0] < 2 || d[1] < 2 || d[2] < 2)
  {
    throw Error("volume of " + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " + std::to_string(d[2]) +
        " voxels has no cells to tetrahedralise (at least 2 x 2 x 2 voxels are needed)",
      file);
  }
  const long long np = static_cast<long long>(d[0]) * d[1] * d[2];
  const long long nt = 5 * (d[0] - 1LL) * (d[1] - 1) * (d[2] - 1);
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
  CheckFullResolutionFits(nt, pages > 0 && pageSize > 0 ? double(pages) * pageSize : 0.0, file);
  std::vector<Vec3> pts(np);
  std::vector<double> val(np);
  const int* e = image->GetExtent(); // indices start at the extent's first corner
  for (int k = 0, id = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i, ++id)
      {
        double p[3];
        image->TransformContinuousIndexToPhysicalPoint(e[0] + i, e[2] + j, e[4] + k, p); // origin, spacing, direction
        pts[id] = Vec3(p);
        val[id] = s->GetComponent(id, 0);
      }
  static const int five[5][4] = { { 0, 1, 2, 4 }, { 3, 1, 2, 7 }, { 5, 1, 4, 7 }, { 6, 2, 4, 7 }, { 1, 2, 4, 7 } };
  std::vector<std::array<int, 4>> tets;
  tets.reserve(5 * (d[0] - 1LL) * (d[1] - 1) * (d[2] - 1));
  for (int k = 0; k + 1 < d[2]; ++k)
    for (int j = 0; j + 1 < d[1]; ++j)
      for (int i = 0; i + 1 < d[0]; ++i)
      {
        int c[8];
        for (int b = 0; b < 8; ++b)
        {
          c[b] = ((k + ((b >> 2) & 1)) * d[1] + j + ((b >> 1) & 1)) * d[0] + i + (b & 1);
        }
        const int flip = (i + j + k) & 1; // mirror odd cells in x so shared face diagonals agree
        for (const auto& t : five)
        {
          tets.push_back({ c[t[0] ^ flip], c[t[1] ^ flip], c[t[2] ^ flip], c[t[3] ^ flip] });
        }
      }
  try
  {
    return TetMesh(std::move(pts), std::move(val), std::move(tets));
  }
  catch (const Error& e)
  {
    throw Error(e.problem(), file);
  }
}

namespace
{
// Keeps the points with to[i] == i, in input order, and renumbers each tet's ids i through to[i]
// (a kept point); ids out of range stay, for the constructor to name.
void KeepPoints(std::vector<Vec3>& pts, std::vector<double>& val, std::vector<std::array<int, 4>>& tets,
  const std::vector<int>& to)
{
  const std::size_t np = pts.size();
  std::vector<int> index(np, -1);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < np; ++i)
  {
    if (to[i] == static_cast<int>(i))
    {
      index[i] = static_cast<int>(kept);
      pts[kept] = pts[i], val[kept] = val[i];
      ++kept;
    }
  }
  pts.resize(kept), val.resize(kept);
  for (auto& t : tets)
  {
    for (int& id : t)
    {
      id = id >= 0 && id < static_cast<int>(np) ? index[to[id]] : id;
    }
  }
}

// Points no tet uses (left over by a clip or threshold filter, or stray) are dropped, in order:
// they would widen the bounds a camera frames, and a NaN among them would refuse the mesh.
// Returns how many went; ids out of range are left for the constructor to name.
std::size_t DropUnusedPoints(std::vector<Vec3>& pts, std::vector<double>& val, std::vector<std::array<int, 4>>& tets)
{
  const std::size_t np = pts.size();
  std::vector<int> to(np, -1);
  for (const auto& t : tets)
  {
    for (int v : t)
    {
      if (v < 0 || static_cast<std::size_t>(v) >= np)
      {
        return 0;
      }
      to[v] = v;
    }
  }
  const std::size_t dropped = static_cast<std::size_t>(std::count(to.begin(), to.end(), -1));
  if (dropped > 0)
  {
    KeepPoints(pts, val, tets, to);
  }
  return dropped;
}

// Points equal in position and scalar become one (exported meshes often give every cell its own
// points). Without shared faces each tet would be a piece of its own, found through the boundary
// grid at every step; points that differ in the scalar (a field discontinuous across a face) stay
// apart. Returns how many points went.
std::size_t MergeDuplicatePoints(std::vector<Vec3>& pts, std::vector<double>& val, std::vector<std::array<int, 4>>& tets)
{
  const std::size_t np = pts.size();
  for (std::size_t i = 0; i < np; ++i)
  {
    if (!IsFinite(pts[i]) || !std::isfinite(val[i]))
    {
      return 0; // no order to sort by; the constructor names the point
    }
  }
  std::vector<int> order(np);
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](int i) { return std::make_tuple(pts[i].x, pts[i].y, pts[i].z, val[i]); };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) != key(b) ? key(a) < key(b) : a < b; });
  std::vector<int> to(np);
  std::size_t merged = 0;
  for (std::size_t k = 0; k < np; ++k)
  {
    const bool same = k > 0 && key(order[k]) == key(order[k - 1]);
    to[order[k]] = same ? to[order[k - 1]] : order[k];
    merged += same ? 1 : 0;
  }
  if (merged == 0)
  {
    return 0;
  }
  KeepPoints(pts, val, tets, to); // the first of each group
  return merged;
}
} // namespace

TetMesh TetMesh::FromVTK(vtkUnstructuredGrid* grid, const std::string& array, std::string* note, const std::string& file)
{
  if (!grid || grid->GetNumberOfCells() == 0)
  {
    throw Error("mesh has no cells", file);
  }
  // A surface or a line set saved as a grid has nothing to cast through: say what it holds.
  // Cells of lower dimension beside 3-D ones are left out, with a note.
  vtkIdType lower = 0;
  {
    vtkNew<vtkCellTypes> types;
    grid->GetCellTypes(types);
    bool anyLower = false;
    bool low[256] = {};
    vtkNew<vtkGenericCell> cell;
    for (vtkIdType k = 0; k < types->GetNumberOfTypes(); ++k)
    {
      const unsigned char type = types->GetCellType(k);
      cell->SetCellType(type);
      low[type] = cell->GetCellDimension() < 3;
      anyLower = anyLower || low[type];
    }
    for (vtkIdType c = 0; anyLower && c < grid->GetNumberOfCells(); ++c)
    {
      lower += low[grid->GetCellType(c)] ? 1 : 0;
    }
  }
  if (lower == grid->GetNumberOfCells())
  {
    throw Error("holds no 3-D cells (its " + std::to_string(lower) +
        " cells are surface, line or vertex cells): a tet mesh is needed; a surface renders from .vtp, .ply, .obj or .stl",
      file);
  }
  // The scalars are chosen, and cell scalars averaged to the points, on the cells as given: after
  // tetrahedralising, a cell's weight at a corner would depend on how many tets it became.
  vtkSmartPointer<vtkUnstructuredGrid> ug = grid;
  std::string notes = lower > 0 ? std::to_string(lower) + " cells that are not 3-D were left out" : "";
  vtkDataArray* s = ChooseArray(ug->GetPointData(), array);
  if (!s)
  {
    // Cell scalars (common in simulation output) are averaged to the points by VTK's
    // vtkCellDataToPointData, since the walk interpolates linearly inside each tet.
    vtkCellData* cd = ug->GetCellData();
    vtkDataArray* cs = ChooseArray(cd, array);
    if (!cs || !cs->GetName())
    {
      throw Error(array.empty() ? "mesh has no point or cell scalars"
                                : "mesh has no point or cell array '" + array + "' (it has: " +
            ArrayNames({ ug->GetPointData(), cd }) + ")",
        file);
    }
    if (cs->GetNumberOfComponents() != 1)
    {
      throw Error("cell array '" + std::string(cs->GetName()) + "' has " + std::to_string(cs->GetNumberOfComponents()) +
          " components; rendering needs one (pick another with --array)",
        file);
    }
    vtkNew<vtkCellDataToPointData> toPoints;
    toPoints->SetInputData(ug);
    toPoints->ProcessAllArraysOff();
    toPoints->AddCellDataArray(cs->GetName());
    toPoints->Update();
    const std::string name = cs->GetName();
    ug = vtkUnstructuredGrid::SafeDownCast(toPoints->GetOutput());
    s = ug->GetPointData()->GetArray(name.c_str());
    notes += (notes.empty() ? "" : "; ") + ("cell scalars '" + name + "' were averaged to the points");
  }
  if (s->GetNumberOfComponents() != 1)
  {
    throw Error("point array '" + std::string(s->GetName() ? s->GetName() : "") + "' has " +
        std::to_string(s->GetNumberOfComponents()) + " components; rendering needs one (pick another with --array)",
      file);
  }
  bool allTets = true;
  for (vtkIdType c = 0; c < ug->GetNumberOfCells() && allTets; ++c)
  {
    allTets = ug->GetCellType(c) == VTK_TETRA;
  }
  if (!allTets)
  {
    // The chosen array rides through as the active scalars.
    auto withScalars = vtkSmartPointer<vtkUnstructuredGrid>::New();
    withScalars->ShallowCopy(ug);
    withScalars->GetPointData()->SetScalars(s);
    vtkNew<vtkDataSetTriangleFilter> tri;
    tri->SetInputData(withScalars);
    tri->TetrahedraOnlyOn();
    tri->Update();
    ug = tri->GetOutput();
    notes = "non-tetrahedral cells were tetrahedralised (" + std::to_string(grid->GetNumberOfCells()) + " cells -> " +
      std::to_string(ug->GetNumberOfCells()) + " tets)" + (notes.empty() ? "" : "; " + notes);
    if (ug->GetNumberOfCells() == 0)
    {
      throw Error("mesh has no 3D cells to tetrahedralise", file);
    }
    s = ug->GetPointData()->GetScalars();
  }
  if (note)
  {
    *note += std::string(note->empty() || notes.empty() ? "" : "; ") + notes;
  }
  const vtkIdType np = ug->GetNumberOfPoints();
  std::vector<Vec3> pts(np);
  std::vector<double> val(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    ug->GetPoint(i, p);
    pts[i] = Vec3(p);
    val[i] = s->GetComponent(i, 0);
  }
  std::vector<std::array<int, 4>> tets;
  tets.reserve(ug->GetNumberOfCells());
  vtkIdType n;
  const vtkIdType* ids;
  for (vtkIdType c = 0; c < ug->GetNumberOfCells(); ++c)
  {
    if (ug->GetCellType(c) != VTK_TETRA)
    {
      continue;
    }
    ug->GetCellPoints(c, n, ids);
    tets.push_back({ static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]),
      static_cast<int>(ids[3]) });
  }
  const std::size_t unused = DropUnusedPoints(pts, val, tets);
  if (unused > 0 && note)
  {
    *note += std::string(note->empty() ? "" : "; ") + std::to_string(unused) + " points no tet uses were dropped";
  }
  const std::size_t merged = MergeDuplicatePoints(pts, val, tets);
  if (merged > 0 && note)
  {
    *note += std::string(note->empty() ? "" : "; ") + std::to_string(merged) +
      " duplicate points (same position and scalar) were merged, so their tets share faces";
  }
  try
  {
    return TetMesh(std::move(pts), std::move(val), std::move(tets));
  }
  catch (const Error& e)
  {
    throw Error(e.problem(), file);
  }
}
} // namespace art
