#include "TriangleStore.h"
#include "Morton.h"

#include "Error.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolygon.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace art
{
TriangleStore::TriangleStore(
  std::vector<Vec3> points, const std::vector<std::array<long long, 3>>& triangles, const Vec3& origin)
{
  std::vector<long long> original(triangles.size());
  std::iota(original.begin(), original.end(), 0LL);
  Build(std::move(points), triangles, original, origin);
}

void TriangleStore::Build(std::vector<Vec3> points, const std::vector<std::array<long long, 3>>& triangles,
  const std::vector<long long>& original, const Vec3& origin)
{
  Pts = std::move(points);
  for (Vec3& p : Pts)
  {
    p = p - origin;
  }
  const long long np = static_cast<long long>(Pts.size());
  Box = Box3();
  for (const Vec3& p : Pts)
  {
    if (IsFinite(p))
    {
      Box.Expand(Vec3(float(p.x), float(p.y), float(p.z)));
    }
  }
  const double diag = std::max(Box.Diagonal(), 1e-300);

  // Candidate triangles with their plane, in the float geometry we will actually trace.
  struct Cand
  {
    size_t src;
    double n[3], d;
    long long key[4];
  };
  std::vector<Cand> cands;
  cands.reserve(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i)
  {
    const auto& t = triangles[i];
    bool ok = true;
    Vec3 q[3];
    for (int k = 0; k < 3 && ok; ++k)
    {
      ok = t[k] >= 0 && t[k] < np && IsFinite(Pts[t[k]]);
      if (ok)
      {
        const Vec3& p = Pts[t[k]];
        q[k] = Vec3(float(p.x), float(p.y), float(p.z));
      }
    }
    if (!ok)
    {
      ++Dropped;
      continue;
    }
    const Vec3 n = Cross(q[1] - q[0], q[2] - q[0]);
    const double len = Length(n);
    if (!(len > 0.0))
    {
      ++Dropped; // zero area: no ray can hit it, and it has no plane
      continue;
    }
    Vec3 u = n / len;
    // Canonical sign: the largest component positive, so opposite windings share a plane.
    const int a = std::fabs(u.x) >= std::fabs(u.y) ? (std::fabs(u.x) >= std::fabs(u.z) ? 0 : 2)
                                                   : (std::fabs(u.y) >= std::fabs(u.z) ? 1 : 2);
    if (u[a] < 0)
    {
      u = -u;
    }
    Cand c;
    c.src = i;
    c.n[0] = u.x;
    c.n[1] = u.y;
    c.n[2] = u.z;
    c.d = Dot(u, q[0]);
    // Coplanar triangles get equal keys: normal and offset quantised (1e-6 of the scene).
    c.key[0] = std::llround(u.x * 1e6);
    c.key[1] = std::llround(u.y * 1e6);
    c.key[2] = std::llround(u.z * 1e6);
    c.key[3] = std::llround(c.d / diag * 1e6);
    cands.push_back(c);
  }
  std::stable_sort(cands.begin(), cands.end(), [](const Cand& x, const Cand& y) {
    return std::tie(x.key[0], x.key[1], x.key[2], x.key[3]) < std::tie(y.key[0], y.key[1], y.key[2], y.key[3]);
  });
  // Coplanar runs stay together, and the runs are laid out along a Morton curve (by the centroid of
  // a run's first triangle), so triangles that are near in space are near in memory: a ray's tests
  // in one voxel then touch neighbouring cache lines.
  {
    std::vector<std::pair<std::uint64_t, size_t>> runs; // (morton, first index)
    for (size_t i = 0; i < cands.size(); ++i)
    {
      if (i > 0 && std::equal(cands[i].key, cands[i].key + 4, cands[i - 1].key))
      {
        continue;
      }
      const auto& t = triangles[cands[i].src];
      Vec3 centroid;
      for (int a = 0; a < 3; ++a)
      {
        centroid[a] = (float(Pts[t[0]][a]) + float(Pts[t[1]][a]) + float(Pts[t[2]][a])) / 3.0;
      }
      runs.emplace_back(MortonCode(centroid, Box), i);
    }
    std::stable_sort(runs.begin(), runs.end());
    std::vector<Cand> ordered;
    ordered.reserve(cands.size());
    for (const auto& r : runs)
    {
      size_t i = r.second;
      do
      {
        ordered.push_back(cands[i++]);
      } while (i < cands.size() && std::equal(cands[i].key, cands[i].key + 4, cands[i - 1].key));
    }
    cands.swap(ordered);
  }

  Records.resize(cands.size());
  Boxes.resize(cands.size());
  Original.resize(cands.size());
  PlaneList.clear();
  for (size_t r = 0; r < cands.size(); ++r)
  {
    const Cand& c = cands[r];
    const bool newPlane = r == 0 ||
      std::tie(c.key[0], c.key[1], c.key[2], c.key[3]) !=
        std::tie(cands[r - 1].key[0], cands[r - 1].key[1], cands[r - 1].key[2], cands[r - 1].key[3]);
    if (newPlane)
    {
      PlaneList.push_back({ { c.n[0], c.n[1], c.n[2] }, c.d });
    }
    else
    {
      Records[r - 1].flags |= TriangleRecord::SharedPlane;
    }
    TriangleRecord& rec = Records[r];
    TriangleBox& b = Boxes[r];
    rec = TriangleRecord{};
    const auto& t = triangles[c.src];
    for (int k = 0; k < 3; ++k)
    {
      rec.v[k] = static_cast<std::uint32_t>(t[k]);
      for (int a = 0; a < 3; ++a)
      {
        rec.p[k][a] = static_cast<float>(Pts[t[k]][a]);
      }
    }
    for (int a = 0; a < 3; ++a)
    {
      b.lo[a] = std::min({ rec.p[0][a], rec.p[1][a], rec.p[2][a] });
      b.hi[a] = std::max({ rec.p[0][a], rec.p[1][a], rec.p[2][a] });
    }
    rec.plane = static_cast<std::uint32_t>(PlaneList.size() - 1);
    const double* n = c.n;
    const int dom = std::fabs(n[0]) >= std::fabs(n[1]) ? (std::fabs(n[0]) >= std::fabs(n[2]) ? 0 : 2)
                                                       : (std::fabs(n[1]) >= std::fabs(n[2]) ? 1 : 2);
    rec.flags |= static_cast<std::uint32_t>(dom) << 2;
    if (std::fabs(n[dom]) == 1.0)
    {
      rec.flags |= TriangleRecord::AxisPlane;
    }
    Original[r] = original[c.src];
  }
}

Vec3 TriangleStore::OriginFor(const Box3& b)
{
  const Vec3 c = b.Center();
  // A float keeps 24 bits of |p - origin|: about 6e-8 of it. Taken from the origin, a scene whose
  // centre lies far beyond its size loses that much of |c|, not of its size (at 1e7 with 1e4 across,
  // whole units: a 0.3-wide triangle was missed); from the centre, at most half its diagonal.
  return std::max(std::fabs(c.x), std::max(std::fabs(c.y), std::fabs(c.z))) > b.Diagonal() ? c : Vec3();
}

TriangleStore TriangleStore::FromPolyData(vtkPolyData* pd, const Vec3& origin)
{
  if (!pd)
  {
    throw Error("no polydata given to the triangle store");
  }
  std::vector<Vec3> pts(static_cast<size_t>(pd->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    pts[i] = Vec3(pd->GetPoint(i));
  }
  std::vector<std::array<long long, 3>> tris;
  std::vector<long long> original;
  const vtkIdType nverts = pd->GetNumberOfVerts(), nlines = pd->GetNumberOfLines();
  const vtkIdType npolys = pd->GetNumberOfPolys();
  // Cell ids in vtkPolyData run over verts, lines, polys, strips in that order.
  vtkIdType cellId = nverts + nlines;
  auto polys = pd->GetPolys();
  auto ids = vtkSmartPointer<vtkIdList>::New();
  auto poly = vtkSmartPointer<vtkPolygon>::New();
  auto out = vtkSmartPointer<vtkIdList>::New();
  for (polys->InitTraversal(); polys->GetNextCell(ids); ++cellId)
  {
    const vtkIdType n = ids->GetNumberOfIds();
    if (n == 3)
    {
      tris.push_back({ ids->GetId(0), ids->GetId(1), ids->GetId(2) });
      original.push_back(cellId);
    }
    else if (n == 4)
    {
      // Quads: a fan from corner 0 (a planar quad's two diagonals give the same surface), unless
      // the 4-gon is concave (a VTK_POLYGON of 4 points, as an unstructured grid may hold one):
      // then only the fan from its reflex corner stays inside it; the one from corner 0 covered
      // the notch, so lines through the notch hit the cell.
      Vec3 q[4], normal;
      for (int k = 0; k < 4; ++k)
      {
        q[k] = Vec3(pd->GetPoint(ids->GetId(k)));
      }
      for (int k = 0; k < 4; ++k)
      {
        normal = normal + Cross(q[k], q[(k + 1) % 4]); // Newell's normal
      }
      int from = 0;
      for (int k = 0; k < 4; ++k)
      {
        if (Dot(Cross(q[k] - q[(k + 3) % 4], q[(k + 1) % 4] - q[k]), normal) < 0)
        {
          from = k; // the reflex corner (a simple 4-gon has at most one)
          break;
        }
      }
      for (int k = 1; k <= 2; ++k)
      {
        tris.push_back({ ids->GetId(from), ids->GetId((from + k) % 4), ids->GetId((from + k + 1) % 4) });
        original.push_back(cellId);
      }
    }
    else if (n > 4)
    {
      // General polygons may be non-convex: ear-cut through vtkPolygon.
      poly->GetPointIds()->DeepCopy(ids);
      poly->GetPoints()->SetNumberOfPoints(n);
      for (vtkIdType k = 0; k < n; ++k)
      {
        poly->GetPoints()->SetPoint(k, pd->GetPoint(ids->GetId(k)));
      }
      out->Reset();
      if (poly->Triangulate(out) && out->GetNumberOfIds() % 3 == 0)
      {
        for (vtkIdType k = 0; k < out->GetNumberOfIds(); k += 3)
        {
          tris.push_back({ ids->GetId(out->GetId(k)), ids->GetId(out->GetId(k + 1)), ids->GetId(out->GetId(k + 2)) });
          original.push_back(cellId);
        }
      }
      else
      {
        for (vtkIdType k = 1; k + 1 < n; ++k)
        {
          tris.push_back({ ids->GetId(0), ids->GetId(k), ids->GetId(k + 1) });
          original.push_back(cellId);
        }
      }
    }
  }
  cellId = nverts + nlines + npolys;
  auto strips = pd->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(ids); ++cellId)
  {
    for (vtkIdType k = 0; k + 2 < ids->GetNumberOfIds(); ++k)
    {
      // Alternate the winding so every strip triangle faces the same way.
      if (k % 2 == 0)
      {
        tris.push_back({ ids->GetId(k), ids->GetId(k + 1), ids->GetId(k + 2) });
      }
      else
      {
        tris.push_back({ ids->GetId(k + 1), ids->GetId(k), ids->GetId(k + 2) });
      }
      original.push_back(cellId);
    }
  }
  TriangleStore s;
  s.Build(std::move(pts), tris, original, origin);
  return s;
}

size_t TriangleStore::MemoryBytes() const
{
  return Records.size() * sizeof(TriangleRecord) + Boxes.size() * sizeof(TriangleBox) +
    PlaneList.size() * sizeof(PlaneRecord) + Pts.size() * sizeof(Vec3) + Original.size() * sizeof(long long);
}
} // namespace art
