// The bisection mesh stays conforming, and the lattice raster gives each voxel to one tet.
#include "BisectionMesh.h"
#include "LeastSquaresFit.h"
#include "MeshQuality.h"
#include "VoxelRaster.h"

#include <gtest/gtest.h>

#include <numeric>
#include <random>

namespace
{
art::QualityReport Check(const art::BisectionMesh& m)
{
  std::vector<double> p;
  for (int v = 0; v < m.NumberOfVertices(); ++v)
  {
    const auto& q = m.Vertex(v);
    p.insert(p.end(), { double(q.x), double(q.y), double(q.z) });
  }
  std::vector<int> t;
  for (int i = 0; i < m.NumberOfTets(); ++i)
  {
    auto v = m.Tet(i);
    // MeasureQuality wants positive orientation; Maubach order has either sign.
    const auto &a = m.Vertex(v[0]), &b = m.Vertex(v[1]), &c = m.Vertex(v[2]), &d = m.Vertex(v[3]);
    const double e[3][3] = { { double(b.x - a.x), double(b.y - a.y), double(b.z - a.z) },
      { double(c.x - a.x), double(c.y - a.y), double(c.z - a.z) },
      { double(d.x - a.x), double(d.y - a.y), double(d.z - a.z) } };
    const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
      e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    EXPECT_NE(det, 0.0);
    if (det < 0)
    {
      std::swap(v[1], v[2]);
    }
    t.insert(t.end(), v.begin(), v.end());
  }
  return art::MeasureQuality(p.data(), m.NumberOfVertices(), t.data(), m.NumberOfTets());
}
} // namespace

TEST(BisectionMesh, KuhnCoarseMeshIsConforming)
{
  const int dims[3] = { 20, 17, 9 }, cubes[3] = { 3, 2, 2 };
  art::BisectionMesh m;
  m.InitKuhn(dims, cubes);
  EXPECT_EQ(m.NumberOfTets(), 6 * 12);
  const auto q = Check(m);
  EXPECT_TRUE(q.Valid()) << q.Summary();
  EXPECT_NEAR(q.Volume, 19.0 * 16 * 8 * std::pow(double(art::BisectionMesh::Scale), 3), 1e-6 * q.Volume);
}

TEST(BisectionMesh, RandomRefinementStaysConformingWithBoundedShapes)
{
  const int dims[3] = { 40, 40, 40 }, cubes[3] = { 2, 2, 2 };
  art::BisectionMesh m;
  m.InitKuhn(dims, cubes);
  std::mt19937 rng(7);
  std::vector<int> touched;
  for (int i = 0; i < 3000; ++i)
  {
    // Concentrate on one corner so the closure has to cross many generations.
    const int t = std::uniform_int_distribution<int>(0, m.NumberOfTets() - 1)(rng);
    const auto& p = m.Vertex(m.Tet(t)[0]);
    if (p.x + p.y + p.z < 50 * art::BisectionMesh::Scale || i % 5 == 0)
    {
      m.Refine(t, touched);
    }
  }
  const auto q = Check(m);
  EXPECT_GT(m.NumberOfTets(), 3000);
  EXPECT_TRUE(q.Valid()) << q.Summary();
  EXPECT_NEAR(q.Volume, 39.0 * 39 * 39 * std::pow(double(art::BisectionMesh::Scale), 3), 1e-6 * q.Volume);
  // Kuhn tets bisected by Maubach's rule keep to a few similarity classes: no slivers.
  EXPECT_GT(q.MinDihedralDegrees, 30.0) << q.Summary();
  EXPECT_GT(q.MinRadiusRatio, 0.5) << q.Summary();
}

TEST(VoxelRaster, EveryVoxelCentreBelongsToExactlyOneTet)
{
  const int dims[3] = { 23, 18, 11 }, cubes[3] = { 3, 2, 1 };
  art::BisectionMesh m;
  m.InitKuhn(dims, cubes);
  std::vector<int> touched;
  for (int i = 0; i < 400; ++i)
  {
    m.Refine((i * 7919) % m.NumberOfTets(), touched);
  }
  std::vector<int> owner(dims[0] * dims[1] * dims[2], 0);
  for (int t = 0; t < m.NumberOfTets(); ++t)
  {
    art::LatticePoint P[4];
    for (int a = 0; a < 4; ++a)
    {
      P[a] = m.Vertex(m.Tet(t)[a]);
    }
    art::TetRaster r;
    ASSERT_TRUE(r.Setup(P));
    r.ForEachVoxel(dims, [&](long long idx, const double* l) {
      ++owner[idx];
      EXPECT_NEAR(l[0] + l[1] + l[2] + l[3], 1.0, 1e-12);
      for (int a = 0; a < 4; ++a)
      {
        EXPECT_GE(l[a], -1e-12);
      }
    });
  }
  for (size_t i = 0; i < owner.size(); ++i)
  {
    ASSERT_EQ(owner[i], 1) << "voxel " << i;
  }
}
