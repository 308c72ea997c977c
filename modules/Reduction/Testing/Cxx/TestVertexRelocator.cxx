// Vertex relocation (VertexRelocator, ReducerOptions::RelocateVertices): on the CT the error
// falls and never rises, tets keep their orientation, box corners, edges and faces are kept,
// every voxel centre stays in exactly one tet; a sharp step pulls vertices onto it; the same
// result for any thread count; a moved mesh refuses further bisection. The screening raster and
// the strided scans it uses agree with the exact raster.
#include "BisectionMesh.h"
#include "DataLoader.h"
#include "Error.h"
#include "LeastSquaresFit.h"
#include "Progress.h"
#include "ReducerVTK.h"
#include "ReductionFixtures.h"
#include "TetReducer.h"
#include "VertexRelocator.h"
#include "VoxelRaster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <vector>

using fixtures::ExpectEachVoxelOwnedOnce;
using fixtures::SignedVolume6;

namespace
{
// A Kuhn mesh of `cubes`, bisected `rounds` times everywhere, with its least-squares fit.
void FittedMesh(const art::VoxelVolume& vol, const int cubes[3], int rounds, art::BisectionMesh& mesh,
  std::vector<double>& x)
{
  mesh.InitKuhn(vol.Dims, cubes);
  for (int r = 0; r < rounds; ++r)
  {
    const int nt = mesh.NumberOfTets();
    std::vector<uint32_t> version(nt);
    for (int t = 0; t < nt; ++t)
    {
      version[t] = mesh.Version(t);
    }
    std::vector<int> touched;
    for (int t = 0; t < nt; ++t)
    {
      if (mesh.Version(t) == version[t])
      {
        mesh.Refine(t, touched);
      }
    }
  }
  art::LeastSquaresFit fit(vol);
  std::vector<int> all(mesh.NumberOfTets());
  std::iota(all.begin(), all.end(), 0);
  fit.UpdateMoments(mesh, all);
  fit.Solve(mesh, x, 1e-10);
}

double Rms(const art::VoxelVolume& vol, const art::BisectionMesh& mesh, const std::vector<double>& x)
{
  art::LeastSquaresFit fit(vol);
  return fit.VoxelErrors(mesh, x).Rms;
}
} // namespace

TEST(VertexRelocator, LowersTheCTErrorAndKeepsAValidPartitionOfTheBox)
{
  auto img = art::LoadVolume(std::string(ART_SOURCE_DIR) + "/data/ct-head-128.mha");
  const art::VoxelVolume ct = art::VolumeFromImage(img);
  // The middle 64 x 64 of every slice (skin, bone, air and brain; a quarter of the cost).
  art::VoxelVolume vol = ct;
  vol.Dims[0] = vol.Dims[1] = 64;
  vol.Float.clear();
  vol.Double.clear();
  for (int k = 0; k < ct.Dims[2]; ++k)
  {
    for (int j = 32; j < 96; ++j)
    {
      for (int i = 32; i < 96; ++i)
      {
        const double f = ct.Value(i + ct.Dims[0] * (j + static_cast<long long>(ct.Dims[1]) * k));
        ct.DoubleValues ? vol.Double.push_back(f) : vol.Float.push_back(static_cast<float>(f));
      }
    }
  }
  vol.Validate();
  const int cubes[3] = { 4, 4, 3 };
  art::BisectionMesh mesh;
  std::vector<double> x;
  FittedMesh(vol, cubes, 3, mesh, x);
  const art::BisectionMesh before = mesh;
  const double rmsBefore = Rms(vol, mesh, x);
  art::RelocationOptions o;
  o.Sweeps = 2;
  const art::RelocationStats s = art::VertexRelocator::Relocate(mesh, vol, x, o);
  EXPECT_GT(s.Moved, mesh.NumberOfVertices() / 4);
  EXPECT_NEAR(std::sqrt(s.SseBefore / vol.NumberOfVoxels()), rmsBefore, 1e-6 * rmsBefore);
  EXPECT_LE(s.SseAfter, s.SseBefore);
  const double rmsAfter = Rms(vol, mesh, x);
  EXPECT_NEAR(std::sqrt(s.SseAfter / vol.NumberOfVoxels()), rmsAfter, 1e-6 * rmsAfter);
  EXPECT_LT(rmsAfter, 0.93 * rmsBefore) << rmsBefore << " -> " << rmsAfter;
  std::printf("CT crop: %d tets, RMS %.2f -> %.2f, %lld moves of %d vertices\n", mesh.NumberOfTets(), rmsBefore, rmsAfter, s.Moved, mesh.NumberOfVertices());

  // The global refit on the moved mesh can only lower it further.
  art::LeastSquaresFit fit(vol);
  std::vector<int> all(mesh.NumberOfTets());
  std::iota(all.begin(), all.end(), 0);
  fit.UpdateMoments(mesh, all);
  fit.Solve(mesh, x, 1e-10);
  EXPECT_LE(fit.VoxelErrors(mesh, x).Rms, rmsAfter * (1 + 1e-9));

  // Same tets, same orientation, none flat; corners fixed, box faces and edges kept.
  ASSERT_EQ(mesh.NumberOfTets(), before.NumberOfTets());
  for (int t = 0; t < mesh.NumberOfTets(); ++t)
  {
    ASSERT_EQ(mesh.Tet(t), before.Tet(t));
    const double a = SignedVolume6(before, t), b = SignedVolume6(mesh, t);
    ASSERT_NE(b, 0.0);
    ASSERT_EQ(a > 0, b > 0) << "tet " << t << " flipped";
  }
  int moved = 0;
  for (int v = 0; v < mesh.NumberOfVertices(); ++v)
  {
    const auto &p = before.Vertex(v), &q = mesh.Vertex(v);
    moved += (p.x != q.x || p.y != q.y || p.z != q.z) ? 1 : 0;
    for (int d = 0; d < 3; ++d)
    {
      const int64_t hi = (vol.Dims[d] - 1) * art::BisectionMesh::Scale;
      if (p[d] == 0 || p[d] == hi)
      {
        EXPECT_EQ(q[d], p[d]) << "vertex " << v << " left the box face";
      }
      EXPECT_GE(q[d], 0);
      EXPECT_LE(q[d], hi);
    }
  }
  EXPECT_GT(moved, mesh.NumberOfVertices() / 4);
  EXPECT_TRUE(fixtures::Check(mesh).Valid());
  ExpectEachVoxelOwnedOnce(mesh, vol.Dims);

  // Off the lattice, bisection is refused rather than made inexact.
  std::vector<int> touched;
  EXPECT_THROW(mesh.Refine(0, touched), art::Error);
}

TEST(VertexRelocator, VerticesLandOnASharpStep)
{
  // 0 below x = 10.5 voxels, 1000 above; the coarse vertices sit at x = 0, 4, 8, 12, ...: a
  // linear fit can only match the step with vertices between the voxels at 10 and 11.
  const int d[3] = { 33, 13, 13 };
  const double spacing[3] = { 1, 1, 1 }, origin[3] = { 0, 0, 0 };
  const art::VoxelVolume vol =
    art::VolumeFromImage(fixtures::Field(d, spacing, origin, [](double x, double, double) { return x > 10.5 ? 1000.0 : 0.0; }));
  const int cubes[3] = { 8, 3, 3 };
  art::BisectionMesh mesh;
  std::vector<double> x;
  FittedMesh(vol, cubes, 0, mesh, x);
  const double rmsBefore = Rms(vol, mesh, x);
  auto near = [&]() {
    int n = 0;
    for (int v = 0; v < mesh.NumberOfVertices(); ++v)
    {
      const double px = double(mesh.Vertex(v).x) / art::BisectionMesh::Scale;
      n += (px >= 9.99 && px <= 11.01) ? 1 : 0;
    }
    return n;
  };
  ASSERT_EQ(near(), 0);
  art::RelocationOptions o;
  o.Sweeps = 6;
  art::VertexRelocator::Relocate(mesh, vol, x, o);
  art::LeastSquaresFit fit(vol);
  std::vector<int> all(mesh.NumberOfTets());
  std::iota(all.begin(), all.end(), 0);
  fit.UpdateMoments(mesh, all);
  fit.Solve(mesh, x, 1e-10);
  const double rmsAfter = fit.VoxelErrors(mesh, x).Rms;
  EXPECT_LT(rmsAfter, 0.5 * rmsBefore) << rmsBefore << " -> " << rmsAfter;
  EXPECT_GE(near(), 16) << "of " << mesh.NumberOfVertices() << " vertices";
  std::printf("step: RMS %.2f -> %.2f, %d of %d vertices on the step\n", rmsBefore, rmsAfter, near(), mesh.NumberOfVertices());
  ExpectEachVoxelOwnedOnce(mesh, vol.Dims);
}

TEST(VertexRelocator, ReducerOptionIsDeterministicValidAndLowersTheError)
{
  const int d[3] = { 40, 34, 30 };
  const double spacing[3] = { 1.0, 0.8, 1.5 }, origin[3] = { 2.0, -1.0, 0.5 };
  const art::VoxelVolume vol = art::VolumeFromImage(fixtures::Field(d, spacing, origin, [](double x, double y, double z) {
    const double dx = x - 21.3, dy = y - 12.1, dz = z - 22.7;
    return dx * dx + dy * dy + dz * dz < 11.2 * 11.2 ? 1000.0 : 0.0;
  }));
  art::ReducerOptions opt;
  opt.TargetTets = 2000;
  opt.Levels = { 500 };
  const auto plain = art::TetReducer(opt).Run(vol);
  opt.RelocateVertices = true;
  const int threads = art::GetThreadCount();
  art::SetThreadCount(1);
  const auto one = art::TetReducer(opt).Run(vol);
  art::SetThreadCount(2);
  const auto two = art::TetReducer(opt).Run(vol);
  art::SetThreadCount(threads);
  ASSERT_EQ(one.size(), 2u);
  ASSERT_EQ(two.size(), 2u);
  for (int i = 0; i < 2; ++i)
  {
    EXPECT_EQ(one[i].Tets, two[i].Tets);
    EXPECT_EQ(one[i].Points, two[i].Points);
    EXPECT_EQ(one[i].Values, two[i].Values);
    EXPECT_EQ(one[i].Rms, two[i].Rms);
    fixtures::ExpectValid(one[i]);
    // Same tets as without relocation (the next level refines the unmoved mesh), lower error.
    EXPECT_EQ(one[i].NumberOfTets(), plain[i].NumberOfTets());
    EXPECT_LT(one[i].Rms, 0.9 * plain[i].Rms) << plain[i].Rms << " -> " << one[i].Rms;
  }
}

// A ball of 1000 in 0 on a 30 x 28 x 26 grid, off the voxel centres.
static art::VoxelVolume Ball()
{
  const int d[3] = { 30, 28, 26 };
  const double spacing[3] = { 1, 1, 1 }, origin[3] = { 0, 0, 0 };
  return art::VolumeFromImage(fixtures::Field(d, spacing, origin, [](double x, double y, double z) {
    const double dx = x - 14.3, dy = y - 13.6, dz = z - 12.2;
    return dx * dx + dy * dy + dz * dz < 9.3 * 9.3 ? 1000.0 : 0.0;
  }));
}

TEST(VertexRelocator, WeightedByOpacityTheWeightedErrorFalls)
{
  // A ball whose surface is what the opacity ramp (400..600) shows.
  const art::VoxelVolume vol = Ball();
  art::ReducerOptions opt;
  opt.TargetTets = 1000;
  opt.ScalarOpacity = { { 0, 0 }, { 400, 0 }, { 600, 0.8 }, { 1000, 0.8 } };
  const auto plain = art::TetReducer(opt).Run(vol).back();
  opt.RelocateVertices = true;
  const auto moved = art::TetReducer(opt).Run(vol).back();
  fixtures::ExpectValid(moved);
  ASSERT_TRUE(moved.Weighted);
  EXPECT_EQ(moved.NumberOfTets(), plain.NumberOfTets());
  EXPECT_LT(moved.WeightedRms, 0.9 * plain.WeightedRms) << plain.WeightedRms << " -> " << moved.WeightedRms;
}

TEST(VertexRelocator, ReportsItsProgressAndCanBeCancelled)
{
  // Relocation takes several times the reduction: it reports a stage of its own, up to 1, and a
  // cancel during it stops the run.
  const art::VoxelVolume vol = Ball();
  art::ReducerOptions opt;
  opt.TargetTets = 1000;
  opt.RelocateVertices = true;
  std::vector<std::pair<std::string, double>> seen;
  art::Progress p([&](double f, const std::string& stage) { seen.emplace_back(stage, f); });
  const auto out = art::TetReducer(opt).Run(vol, &p);
  ASSERT_EQ(out.size(), 1u);
  double relocated = -1;
  int relocateReports = 0;
  for (const auto& [stage, f] : seen)
  {
    if (stage == "relocate")
    {
      EXPECT_GE(f, relocated);
      relocated = f;
      ++relocateReports;
    }
  }
  EXPECT_EQ(relocated, 1.0);
  EXPECT_GT(relocateReports, 2);
  EXPECT_EQ(seen.back().first, "refit") << "the refit after relocation ends the run";
  EXPECT_EQ(seen.back().second, 1.0);

  art::Progress cancel([&](double, const std::string& stage) {
    if (stage == "relocate")
    {
      cancel.Cancel();
    }
  });
  EXPECT_THROW(art::TetReducer(opt).Run(vol, &cancel), art::Error);
}

TEST(VertexRelocator, ScreeningRasterAndSubsampleAgreeWithTheExactRaster)
{
  // Tets with corners off the lattice (as relocated ones are): the floating-point screening
  // raster finds the same voxel centres as the exact one, and a stride-s scan is the exact set
  // restricted to multiples of s.
  const int dims[3] = { 23, 19, 17 };
  const int64_t S = art::BisectionMesh::Scale;
  uint64_t seed = 12345;
  auto next = [&seed](int64_t hi) {
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<int64_t>((seed >> 11) % static_cast<uint64_t>(hi + 1));
  };
  long long total = 0;
  for (int n = 0; n < 200; ++n)
  {
    art::LatticePoint P[4];
    for (auto& p : P)
    {
      p.x = next((dims[0] - 1) * S), p.y = next((dims[1] - 1) * S), p.z = next((dims[2] - 1) * S);
    }
    art::TetRaster exact;
    art::ScreenRaster screen;
    if (!exact.Setup(P))
    {
      continue;
    }
    ASSERT_TRUE(screen.Setup(P, dims));
    std::vector<long long> a, b;
    std::vector<std::array<double, 4>> la, lb;
    exact.ForEachVoxel(dims, [&](long long idx, const double* l) {
      a.push_back(idx);
      la.push_back({ l[0], l[1], l[2], l[3] });
    });
    screen.ForEachVoxel(dims, 1, [&](long long idx, const double* l) {
      b.push_back(idx);
      lb.push_back({ l[0], l[1], l[2], l[3] });
    });
    ASSERT_EQ(a, b) << "tet " << n;
    for (size_t i = 0; i < a.size(); ++i)
    {
      for (int q = 0; q < 4; ++q)
      {
        EXPECT_NEAR(la[i][q], lb[i][q], 1e-9);
      }
    }
    total += static_cast<long long>(a.size());
    for (int st = 2; st <= 3; ++st)
    {
      std::vector<long long> sub, want;
      exact.ForEachVoxel(dims, [&](long long idx, const double*) { sub.push_back(idx); }, st);
      std::vector<long long> subScreen;
      screen.ForEachVoxel(dims, st, [&](long long idx, const double*) { subScreen.push_back(idx); });
      for (long long idx : a)
      {
        const long long i = idx % dims[0], j = (idx / dims[0]) % dims[1], k = idx / (dims[0] * dims[1]);
        if (i % st == 0 && j % st == 0 && k % st == 0)
        {
          want.push_back(idx);
        }
      }
      EXPECT_EQ(sub, want);
      EXPECT_EQ(subScreen, want);
    }
  }
  EXPECT_GT(total, 10000);
}

// A crop of the CT head, reduced with relocation to as many tets as it has voxels (render
// --tets 100%): most tets then hold one voxel centre or none, and a vertex's refitted value
// (its star's voxels, the other corners fixed) is ill-posed where its hat is small on them all.
// Every output value stays within a quarter of the data's range of it, the max error within it.
TEST(VertexRelocator, AtAsManyTetsAsVoxelsTheValuesStayBounded)
{
  auto ct = art::LoadVolume(std::string(ART_SOURCE_DIR) + "/data/ct-head-128.mha");
  const int d[3] = { 36, 36, 18 }, at[3] = { 46, 12, 20 };
  const double spacing[3] = { 1, 1, 1 }, origin[3] = { 0, 0, 0 };
  const art::VoxelVolume vol = art::VolumeFromImage(fixtures::Field(d, spacing, origin, [&](double x, double y, double z) {
    return ct->GetScalarComponentAsDouble(at[0] + int(x), at[1] + int(y), at[2] + int(z), 0);
  }));
  const double lo = vol.Range[0], hi = vol.Range[1], range = hi - lo;
  ASSERT_GT(range, 1000.0); // air to bone
  for (const bool weighted : { false, true })
  {
    art::ReducerOptions opt;
    opt.TargetTets = vol.NumberOfVoxels();
    opt.RelocateVertices = true;
    if (weighted)
    {
      opt.ScalarOpacity = { { -1024, 0 }, { -300, 0 }, { -100, 0.3 }, { 300, 0.3 }, { 500, 0.8 }, { 2700, 0.8 } };
    }
    const art::ReducedMesh m = art::TetReducer(opt).Run(vol).back();
    fixtures::ExpectValid(m);
    const auto [vmin, vmax] = std::minmax_element(m.Values.begin(), m.Values.end());
    std::printf("%s: %lld tets, values %.1f .. %.1f (data %.0f .. %.0f), RMS %.2f, max %.1f\n",
      weighted ? "weighted" : "plain", m.NumberOfTets(), *vmin, *vmax, lo, hi, m.Rms, m.Max);
    EXPECT_GE(*vmin, lo - 0.25 * range);
    EXPECT_LE(*vmax, hi + 0.25 * range);
    EXPECT_LE(m.Max, range);
  }
}
