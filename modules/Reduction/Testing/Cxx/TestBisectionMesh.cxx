// The bisection mesh stays conforming, and the lattice raster gives each voxel to one tet.
#include "BisectionMesh.h"
#include "LeastSquaresFit.h"
#include "MeshQuality.h"
#include "ReductionFixtures.h"
#include "VoxelRaster.h"

#include <gtest/gtest.h>

#include <numeric>
#include <random>

using fixtures::Check;

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
  fixtures::ExpectEachVoxelOwnedOnce(m, dims);
}
