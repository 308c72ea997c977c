// Shared helpers for the TriangleGrid tests: every accelerator kind, simple meshes, random rays.
#ifndef art_TriangleTestUtil_h
#define art_TriangleTestUtil_h

#include "Accelerator.h"

#include <memory>
#include <random>
#include <vector>

namespace arttest
{
inline std::vector<art::AcceleratorOptions> AllKinds()
{
  std::vector<art::AcceleratorOptions> v(6);
  v[0].kind = art::AcceleratorKind::BruteForce;
  v[1].kind = art::AcceleratorKind::UniformGrid;
  v[2].kind = art::AcceleratorKind::RecursiveGrid;
  v[3].kind = art::AcceleratorKind::RecursiveGrid;
  v[3].topLevelGrid = false;
  v[3].subdivisions = 2;
  v[3].voxelThreshold = 4;
  v[4].kind = art::AcceleratorKind::Octree;
  v[5].kind = art::AcceleratorKind::Octree;
  v[5].voxelThreshold = 2;
  return v;
}

/// An axis-aligned box [lo, hi] as 12 triangles per face split n x n (closed, shared vertices).
inline std::shared_ptr<art::TriangleStore> BoxMesh(const art::Vec3& lo, const art::Vec3& hi, int n)
{
  std::vector<art::Vec3> pts;
  std::vector<std::array<long long, 3>> tris;
  auto idx = [&](const art::Vec3& p) {
    for (size_t i = 0; i < pts.size(); ++i)
    {
      if (pts[i] == p)
      {
        return static_cast<long long>(i);
      }
    }
    pts.push_back(p);
    return static_cast<long long>(pts.size() - 1);
  };
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = 0; side < 2; ++side)
    {
      const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
      for (int i = 0; i < n; ++i)
      {
        for (int j = 0; j < n; ++j)
        {
          auto P = [&](int ii, int jj) {
            art::Vec3 p;
            p[axis] = side ? hi[axis] : lo[axis];
            p[a1] = lo[a1] + (hi[a1] - lo[a1]) * ii / n;
            p[a2] = lo[a2] + (hi[a2] - lo[a2]) * jj / n;
            return idx(p);
          };
          tris.push_back({ P(i, j), P(i + 1, j), P(i + 1, j + 1) });
          tris.push_back({ P(i, j), P(i + 1, j + 1), P(i, j + 1) });
        }
      }
    }
  }
  return std::make_shared<art::TriangleStore>(pts, tris);
}

inline art::Vec3 RandomUnit(std::mt19937_64& g)
{
  std::normal_distribution<double> n;
  for (;;)
  {
    art::Vec3 v(n(g), n(g), n(g));
    if (art::Length(v) > 1e-6)
    {
      return art::Normalize(v);
    }
  }
}
} // namespace arttest

#endif
