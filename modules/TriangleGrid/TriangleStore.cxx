#include "TriangleStore.h"

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
#include <unordered_map>

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
  // The points less the origin, in double; in float for tracing. The double copy is kept only
  // when some point is not exactly its float.
  Exact = std::move(points);
  Xyz.assign(3 * Exact.size() + 1, 0.0f);
  Box = Box3();
  bool floats = true;
  for (size_t i = 0; i < Exact.size(); ++i)
  {
    Vec3& p = Exact[i];
    p = p - origin;
    for (int a = 0; a < 3; ++a)
    {
      Xyz[3 * i + a] = static_cast<float>(p[a]);
      floats = floats && (double(Xyz[3 * i + a]) == p[a] || !std::isfinite(p[a]));
    }
    if (IsFinite(p))
    {
      Box.Expand(Vec3(Xyz[3 * i], Xyz[3 * i + 1], Xyz[3 * i + 2]));
    }
  }
  if (floats)
  {
    Exact.clear();
    Exact.shrink_to_fit();
  }
  const long long np = static_cast<long long>(PointCount());

  // The records in input order, with each one's plane in the float geometry we trace.
  Records.clear();
  Records.reserve(triangles.size());
  std::vector<long long> kept;
  kept.reserve(triangles.size());
  std::vector<std::array<double, 4>> planes;
  planes.reserve(triangles.size());
  Dropped = 0;
  for (size_t i = 0; i < triangles.size(); ++i)
  {
    const auto& t = triangles[i];
    bool ok = true;
    Vec3 q[3];
    for (int k = 0; k < 3 && ok; ++k)
    {
      ok = t[k] >= 0 && t[k] < np;
      if (ok)
      {
        const float* p = Xyz.data() + 3 * t[k];
        q[k] = Vec3(p[0], p[1], p[2]);
        ok = IsFinite(q[k]);
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
    planes.push_back({ u.x, u.y, u.z, Dot(u, q[0]) });
    Records.push_back({ { static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]),
                          static_cast<std::uint32_t>(t[2]) },
      TriangleRecord::NoPlane });
    kept.push_back(original[i]);
  }
  Records.shrink_to_fit();
  Original.Assign(kept);
  FindPlanes(planes);
}

void TriangleStore::FindPlanes(const std::vector<std::array<double, 4>>& planes)
{
  // Coplanar triangles get equal keys: normal and offset quantised (1e-6 of the scene). A plane
  // met by two or more triangles gets a record, taken from the first of them.
  const double diag = std::max(Box.Diagonal(), 1e-300);
  struct KeyHash
  {
    size_t operator()(const std::array<long long, 4>& k) const
    {
      std::uint64_t h = 1469598103934665603ull;
      for (long long v : k)
      {
        h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
      }
      return static_cast<size_t>(h ^ (h >> 29));
    }
  };
  std::unordered_map<std::array<long long, 4>, std::uint32_t, KeyHash> first; // key -> first record
  first.reserve(planes.size());
  PlaneList.clear();
  Alone = 0;
  for (size_t r = 0; r < planes.size(); ++r)
  {
    const auto& p = planes[r];
    const std::array<long long, 4> key = { std::llround(p[0] * 1e6), std::llround(p[1] * 1e6),
      std::llround(p[2] * 1e6), std::llround(p[3] / diag * 1e6) };
    const auto ins = first.emplace(key, static_cast<std::uint32_t>(r));
    if (ins.second)
    {
      ++Alone;
      continue;
    }
    TriangleRecord& head = Records[ins.first->second];
    if (head.plane == TriangleRecord::NoPlane)
    {
      const auto& q = planes[ins.first->second];
      head.plane = static_cast<std::uint32_t>(PlaneList.size());
      PlaneList.push_back({ { float(q[0]), float(q[1]), float(q[2]) }, float(q[3]) });
      --Alone;
    }
    Records[r].plane = head.plane;
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
  return Records.size() * sizeof(TriangleRecord) + PlaneList.size() * sizeof(PlaneRecord) +
    Xyz.size() * sizeof(float) + Exact.size() * sizeof(Vec3) + Original.MemoryBytes();
}
} // namespace art
