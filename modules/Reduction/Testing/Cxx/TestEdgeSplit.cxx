// Free edge bisection (BisectionMesh::SplitEdge) and the reducer's error-driven edge choice
// (ReducerOptions::Refinement::EdgeSplit), midpoints and quarter points: conformity, exact voxel ownership, nesting,
// determinism, a ramp kept to round-off, and a lower error than newest-vertex bisection on a jump.
#include "BisectionMesh.h"
#include "DataLoader.h"
#include "Error.h"
#include "MeshQuality.h"
#include "LeastSquaresFit.h"
#include "ParallelTiles.h"
#include "ReducerVTK.h"
#include "ReductionFixtures.h"
#include "TetReducer.h"
#include "VoxelRaster.h"

#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

using fixtures::Check;
using fixtures::ExpectValid;
using fixtures::SignedVolume6;

namespace
{
vtkSmartPointer<vtkImageData> Field(const int d[3], const std::function<double(double, double, double)>& f)
{
  static const double spacing[3] = { 1.0, 0.8, 1.5 }, origin[3] = { 2.0, -1.0, 0.5 };
  return fixtures::Field(d, spacing, origin, f);
}

art::ReducerOptions EdgeOptions()
{
  art::ReducerOptions opt;
  opt.Refine = art::ReducerOptions::Refinement::EdgeSplit;
  return opt;
}

// A sphere of value 1000 in 0, slightly off the grid: surfaces in every direction.
double Ball(double x, double y, double z)
{
  const double dx = x - 23.3, dy = y - 14.1, dz = z - 24.7;
  return dx * dx + dy * dy + dz * dz < 13.2 * 13.2 ? 1000.0 : 0.0;
}
} // namespace

TEST(EdgeSplit, RandomEdgeSplitsStayConformingAndOwnEveryVoxelOnce)
{
  const int dims[3] = { 33, 27, 19 }, cubes[3] = { 2, 2, 1 };
  art::BisectionMesh m;
  m.InitKuhn(dims, cubes);
  std::mt19937 rng(11);
  std::vector<int> touched;
  int splits = 0, quarterSplits = 0;
  for (int i = 0; i < 1500; ++i)
  {
    const int t = std::uniform_int_distribution<int>(0, m.NumberOfTets() - 1)(rng);
    const int e = std::uniform_int_distribution<int>(0, 5)(rng);
    const int a = m.Tet(t)[art::BisectionMesh::EdgeCorners[e][0]], b = m.Tet(t)[art::BisectionMesh::EdgeCorners[e][1]];
    const int quarters = std::uniform_int_distribution<int>(1, 3)(rng);
    if (m.EdgeLength2(a, b) < 1.0 || !m.CanSplitEdge(a, b, quarters))
    {
      continue;
    }
    quarterSplits += quarters != 2 ? 1 : 0;
    std::vector<int> star;
    m.TetsWithEdge(a, b, star);
    std::vector<double> sign;
    for (int s : star)
    {
      sign.push_back(SignedVolume6(m, s));
    }
    const int before = m.NumberOfTets();
    touched.clear();
    m.SplitEdge(a, b, touched, quarters);
    ++splits;
    ASSERT_EQ(m.NumberOfTets(), before + static_cast<int>(star.size()));
    ASSERT_EQ(touched.size(), 2 * star.size());
    // The child keeping a has t = quarters / 4 of its parent's volume, the other 1 - t; same sign.
    for (size_t k = 0; k < star.size(); ++k)
    {
      EXPECT_EQ(SignedVolume6(m, touched[2 * k]), 0.25 * quarters * sign[k]);
      EXPECT_EQ(SignedVolume6(m, touched[2 * k + 1]), 0.25 * (4 - quarters) * sign[k]);
    }
    EXPECT_EQ(m.Parents(m.NumberOfVertices() - 1)[0], std::min(a, b));
  }
  EXPECT_GT(splits, 1000);
  EXPECT_GT(quarterSplits, 300);
  // Extend puts a new vertex on its edge's interpolant: a linear field stays exact.
  auto ramp = [](const art::LatticePoint& p) { return 0.5 * p.x - 2.0 * p.y + 0.125 * p.z + 3.0; };
  std::vector<double> x;
  for (int v = 0; v < m.NumberOfVertices() && m.Parents(v)[0] < 0; ++v)
  {
    x.push_back(ramp(m.Vertex(v)));
  }
  art::LeastSquaresFit::Extend(m, x);
  ASSERT_EQ(x.size(), size_t(m.NumberOfVertices()));
  for (int v = 0; v < m.NumberOfVertices(); ++v)
  {
    ASSERT_NEAR(x[v], ramp(m.Vertex(v)), 1e-6) << "vertex " << v;
  }
  const auto q = Check(m);
  EXPECT_TRUE(q.Valid()) << q.Summary();
  EXPECT_NEAR(q.Volume, 32.0 * 26 * 18 * std::pow(double(art::BisectionMesh::Scale), 3), 1e-9 * q.Volume);
  fixtures::ExpectEachVoxelOwnedOnce(m, dims);
  // Maubach's tags no longer hold once free splits were made.
  EXPECT_THROW(m.Refine(0, touched), art::Error);
}

TEST(EdgeSplit, SplittingBelowTheLatticeIsRefused)
{
  const int dims[3] = { 2, 2, 2 }, cubes[3] = { 1, 1, 1 };
  art::BisectionMesh m;
  m.InitKuhn(dims, cubes);
  std::vector<int> touched;
  // Halve the x edge from corner 0 until its length is one lattice step.
  int a = 0, b = 1;
  for (int i = 0; i < art::BisectionMesh::ScaleBits; ++i)
  {
    ASSERT_TRUE(m.CanSplitEdge(a, b));
    m.SplitEdge(a, b, touched);
    b = m.NumberOfVertices() - 1;
  }
  EXPECT_FALSE(m.CanSplitEdge(a, b));
  EXPECT_THROW(m.SplitEdge(a, b, touched), art::Error);
  EXPECT_TRUE(Check(m).Valid());
}

TEST(EdgeSplit, LinearRampStaysExactAfterRefinement)
{
  const int d[3] = { 30, 26, 18 };
  // A ramp plus a small bump so refinement happens; the ramp part must stay exact: on a pure
  // ramp the refined fit is compared below.
  auto ramp = [](double x, double y, double z) { return 3 * x - 2 * y + 0.25 * z - 5; };
  auto opt = EdgeOptions();
  opt.SolverTolerance = 1e-14;
  opt.CoarseTets = 6;
  opt.TargetTets = 300;
  const auto vol = art::VolumeFromImage(Field(d, ramp));
  const auto out = art::TetReducer(opt).Run(vol);
  ASSERT_FALSE(out.empty());
  const double range = vol.Range[1] - vol.Range[0];
  EXPECT_LT(out.back().Rms, 1e-11 * range);
  for (long long v = 0; v < out.back().NumberOfVertices(); ++v)
  {
    const double* p = &out.back().Points[3 * v];
    EXPECT_NEAR(out.back().Values[v], ramp(p[0], p[1], p[2]), 1e-9 * range);
  }
  // With a bump the mesh refines by edge splits, and a ramp added to the field changes nothing but
  // the values by the ramp: the error of f + ramp equals that of f.
  auto bump = [](double x, double y, double z) { return 50 * std::exp(-0.02 * ((x - 14) * (x - 14) + (y - 8) * (y - 8) + (z - 12) * (z - 12))); };
  auto sum = [&](double x, double y, double z) { return bump(x, y, z) + ramp(x, y, z); };
  opt.TargetTets = 600;
  opt.SolverTolerance = 1e-12;
  const auto a = art::TetReducer(opt).Run(art::VolumeFromImage(Field(d, bump)));
  const auto b = art::TetReducer(opt).Run(art::VolumeFromImage(Field(d, sum)));
  ASSERT_GE(a.back().NumberOfTets(), 570);
  EXPECT_NEAR(a.back().Rms, b.back().Rms, 1e-6 * a.back().Rms);
  ExpectValid(b.back());
}

TEST(EdgeSplit, NestedLevelsMeetBudgetsAndTheErrorFalls)
{
  const int d[3] = { 48, 36, 40 };
  auto opt = EdgeOptions();
  opt.Levels = { 150, 600, 2400 };
  opt.TargetTets = 6000;
  const auto out = art::TetReducer(opt).Run(art::VolumeFromImage(Field(d, Ball)));
  ASSERT_EQ(out.size(), 4u);
  for (size_t i = 0; i < out.size(); ++i)
  {
    const long long want = out[i].TargetTets;
    EXPECT_NEAR(double(out[i].NumberOfTets()), double(want), 0.05 * want) << "level " << i;
    ExpectValid(out[i]);
    if (i > 0)
    {
      EXPECT_LT(out[i].Rms, out[i - 1].Rms) << "level " << i;
      // Nested: the coarser level's vertices come first, unchanged.
      const auto& p = out[i - 1].Points;
      ASSERT_GT(out[i].Points.size(), p.size());
      EXPECT_TRUE(std::equal(p.begin(), p.end(), out[i].Points.begin())) << "level " << i;
    }
  }
}

TEST(EdgeSplit, LowerErrorThanBisectionOnASharpSurface)
{
  const int d[3] = { 48, 36, 40 };
  const auto vol = art::VolumeFromImage(Field(d, Ball));
  art::ReducerOptions bis;
  bis.Levels = { 1000, 3000 };
  bis.TargetTets = 8000;
  auto edge = bis;
  edge.Refine = art::ReducerOptions::Refinement::EdgeSplit;
  const auto a = art::TetReducer(bis).Run(vol);
  const auto b = art::TetReducer(edge).Run(vol);
  ASSERT_EQ(a.size(), 3u);
  ASSERT_EQ(b.size(), 3u);
  for (size_t i = 0; i < a.size(); ++i)
  {
    EXPECT_LT(b[i].Rms, a[i].Rms) << "level " << i << ": " << b[i].NumberOfTets() << " vs " << a[i].NumberOfTets();
    std::printf("[ info ] ball, %lld tets: RMS edge split %.2f, bisection %.2f (%lld tets)\n", b[i].NumberOfTets(),
      b[i].Rms, a[i].Rms, a[i].NumberOfTets());
  }
}

TEST(EdgeSplit, DeterministicForAnyThreadCount)
{
  auto vol = art::LoadVolume(std::string(ART_SOURCE_DIR) + "/data/ct-head-128.mha");
  auto opt = EdgeOptions();
  opt.TargetTets = 2500;
  ExpectValid(fixtures::ExpectSameForOneAndTwoThreads(opt, art::VolumeFromImage(vol)));
}
