#include "MeshQuality.h"

#include "ParallelTiles.h"
#include "Vec3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <vector>

namespace art
{
std::string QualityReport::Summary() const
{
  char b[400];
  std::snprintf(b, sizeof b,
    "%lld tets, %lld inverted, %lld interior faces, %lld boundary, %lld open, %lld over-shared; "
    "dihedral %.2f..%.2f deg; radius ratio min %.3f mean %.3f",
    Tets, Inverted, InteriorFaces, BoundaryFaces, OpenFaces, OverSharedFaces, MinDihedralDegrees,
    MaxDihedralDegrees, MinRadiusRatio, MeanRadiusRatio);
  return b;
}

namespace
{
struct Shape
{
  double vol, minDih, maxDih, rr;
};

// Signed volume, dihedral extremes and radius ratio (3 r / R) of one tet.
Shape ShapeOf(const Vec3 p[4])
{
  const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0], e3 = p[3] - p[0];
  const double vol = Dot(Cross(e1, e2), e3) / 6.0;
  // Face f is opposite vertex f; its normal pointed away from vertex f.
  Vec3 n[4];
  double area = 0;
  for (int f = 0; f < 4; ++f)
  {
    const Vec3 &a = p[(f + 1) & 3], &b = p[(f + 2) & 3], &c = p[(f + 3) & 3];
    Vec3 nn = Cross(b - a, c - a);
    if (Dot(nn, p[f] - a) > 0)
    {
      nn = -nn;
    }
    area += 0.5 * Length(nn);
    n[f] = Normalize(nn);
  }
  double mn = 180, mx = 0;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = i + 1; j < 4; ++j)
    {
      const double c = std::max(-1.0, std::min(1.0, -Dot(n[i], n[j])));
      const double d = std::acos(c) * 180.0 / M_PI;
      mn = std::min(mn, d);
      mx = std::max(mx, d);
    }
  }
  // Circumradius: |a|^2 (b x c) + |b|^2 (c x a) + |c|^2 (a x b) over 12 V.
  const Vec3 cc = Cross(e2, e3) * Dot(e1, e1) + Cross(e3, e1) * Dot(e2, e2) + Cross(e1, e2) * Dot(e3, e3);
  const double R = vol != 0 ? Length(cc) / (12.0 * std::fabs(vol)) : std::numeric_limits<double>::infinity();
  const double r = area > 0 ? 3.0 * std::fabs(vol) / area : 0.0;
  return { vol, mn, mx, std::isfinite(R) && R > 0 ? 3.0 * r / R : 0.0 };
}

// The shapes' figures into q: inverted count (volume below volEps), total volume, extremes, mean.
void SummarizeShapes(const std::vector<Shape>& shape, double volEps, QualityReport& q)
{
  q.MinDihedralDegrees = 180;
  q.MinRadiusRatio = 1;
  double rrSum = 0;
  for (const Shape& s : shape)
  {
    q.Inverted += s.vol <= volEps ? 1 : 0;
    q.Volume += s.vol;
    q.MinDihedralDegrees = std::min(q.MinDihedralDegrees, s.minDih);
    q.MaxDihedralDegrees = std::max(q.MaxDihedralDegrees, s.maxDih);
    q.MinRadiusRatio = std::min(q.MinRadiusRatio, s.rr);
    rrSum += s.rr;
  }
  q.MeanRadiusRatio = shape.empty() ? 0.0 : rrSum / static_cast<double>(shape.size());
}

// A face with one tet is on the boundary when every point lies on one side of its plane: the
// reducer's meshes fill a box turned and sheared by the volume's direction matrix, so its faces
// are those of a convex hull, not of the points' axis-aligned box (a rotated volume's outer
// faces all counted as cracks). The points' extent along each face normal is cached; a mesh
// has few normal directions on its outside.
class HullTest
{
public:
  HullTest(const double* points, long long numPoints, double eps) : P(points), N(numPoints), Eps(eps) {}

  bool operator()(const std::array<int, 3>& f)
  {
    const Vec3 a(P + 3 * static_cast<long long>(f[0]));
    Vec3 n = Cross(Vec3(P + 3 * static_cast<long long>(f[1])) - a, Vec3(P + 3 * static_cast<long long>(f[2])) - a);
    const double len = Length(n);
    if (!(len > 0))
    {
      return false;
    }
    n = n * (1.0 / len);
    // One sign per direction, so a box's opposite faces share their extent.
    const int big = std::fabs(n.x) >= std::fabs(n.y) && std::fabs(n.x) >= std::fabs(n.z) ? 0
      : std::fabs(n.y) >= std::fabs(n.z)                                               ? 1
                                                                                         : 2;
    if ((big == 0 ? n.x : big == 1 ? n.y : n.z) < 0)
    {
      n = n * -1.0;
    }
    const std::pair<double, double>& e = ExtentAlong(n);
    const double d = Dot(n, a);
    return std::fabs(d - e.first) <= Eps || std::fabs(d - e.second) <= Eps;
  }

private:
  const std::pair<double, double>& ExtentAlong(const Vec3& n)
  {
    const std::array<long long, 3> key = { std::llround(n.x * 1e9), std::llround(n.y * 1e9), std::llround(n.z * 1e9) };
    auto it = Extent.find(key);
    if (it == Extent.end())
    {
      double mn = std::numeric_limits<double>::infinity(), mx = -mn;
      for (long long v = 0; v < N; ++v)
      {
        const double d = Dot(n, Vec3(P + 3 * v));
        mn = std::min(mn, d);
        mx = std::max(mx, d);
      }
      it = Extent.emplace(key, std::make_pair(mn, mx)).first;
    }
    return it->second;
  }

  const double* P;
  long long N;
  double Eps;
  std::map<std::array<long long, 3>, std::pair<double, double>> Extent;
};

// Interior (two tets), boundary (one, on the hull), open (one, inside) and over-shared faces.
void CountFaces(const double* points, long long numPoints, const int* tets, long long numTets, double eps,
  QualityReport& q)
{
  std::vector<std::array<int, 3>> faces;
  faces.reserve(static_cast<size_t>(4 * numTets));
  for (long long t = 0; t < numTets; ++t)
  {
    for (int f = 0; f < 4; ++f)
    {
      std::array<int, 3> k = { tets[4 * t + ((f + 1) & 3)], tets[4 * t + ((f + 2) & 3)], tets[4 * t + ((f + 3) & 3)] };
      std::sort(k.begin(), k.end());
      faces.push_back(k);
    }
  }
  std::sort(faces.begin(), faces.end());
  HullTest onHull(points, numPoints, eps);
  for (size_t i = 0; i < faces.size();)
  {
    size_t j = i;
    while (j < faces.size() && faces[j] == faces[i])
    {
      ++j;
    }
    const size_t n = j - i;
    if (n == 2)
    {
      ++q.InteriorFaces;
    }
    else if (n > 2)
    {
      ++q.OverSharedFaces;
    }
    else
    {
      ++(onHull(faces[i]) ? q.BoundaryFaces : q.OpenFaces);
    }
    i = j;
  }
}
} // namespace

QualityReport MeasureQuality(const double* points, long long numPoints, const int* tets, long long numTets)
{
  QualityReport q;
  q.Tets = numTets;
  if (numTets == 0 || numPoints == 0)
  {
    return q;
  }
  Vec3 lo(points), hi(points);
  for (long long i = 1; i < numPoints; ++i)
  {
    lo = Min(lo, Vec3(points + 3 * i));
    hi = Max(hi, Vec3(points + 3 * i));
  }
  const double size = Length(hi - lo);
  std::vector<Shape> shape(static_cast<size_t>(numTets));
  ForEachRange(numTets, 1024, [&](long long t0, long long t1, Counters&) {
    for (long long t = t0; t < t1; ++t)
    {
      Vec3 p[4];
      for (int a = 0; a < 4; ++a)
      {
        p[a] = Vec3(points + 3 * static_cast<long long>(tets[4 * t + a]));
      }
      shape[t] = ShapeOf(p);
    }
  });
  SummarizeShapes(shape, 1e-12 * size * size * size, q);
  CountFaces(points, numPoints, tets, numTets, 1e-9 * size, q);
  return q;
}
} // namespace art
