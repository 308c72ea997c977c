// Anisotropic refinement (MMG3D to the Hessian metric, ReducerOptions::Refinement::Anisotropic):
// tets long along a plane step and thin across it, far below bisection's error at equal tets;
// a ramp kept to round-off; faces hugging a sphere; budgets met within 5%; valid, conforming
// meshes; the same mesh for one thread and two; the metric's Hessian exact on a quadratic.
#include "HessianMetric.h"
#include "MmgRemesher.h"
#include "ReducerVTK.h"
#include "ReductionFixtures.h"
#include "SymmetricEigen3.h"
#include "TetReducer.h"

#include <vtkImageData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <vector>

using fixtures::ExpectValid;

namespace
{
art::VoxelVolume Volume(const int d[3], const std::function<double(double, double, double)>& f)
{
  static const double spacing[3] = { 1.0, 1.0, 1.0 }, origin[3] = { 0.0, 0.0, 0.0 };
  return art::VolumeFromImage(fixtures::Field(d, spacing, origin, f));
}

art::ReducerOptions Anisotropic(long long tets)
{
  art::ReducerOptions opt;
  opt.Refine = art::ReducerOptions::Refinement::Anisotropic;
  opt.TargetTets = tets;
  return opt;
}

// A step of 1000 across a tilted plane through the middle of a 40^3 volume.
const double N[3] = { 0.8, 0.5, 0.33 };
double Step(double x, double y, double z)
{
  const double l = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
  return (N[0] * (x - 19.6) + N[1] * (y - 19.3) + N[2] * (z - 19.4)) / l > 0 ? 1000.0 : 0.0;
}

// Mean, over the tets whose centroid lies within `band` of the plane, of their extent along it
// over their extent across it.
double AlongOverAcross(const art::ReducedMesh& m, double band)
{
  const double l = std::sqrt(N[0] * N[0] + N[1] * N[1] + N[2] * N[2]);
  const double n[3] = { N[0] / l, N[1] / l, N[2] / l };
  // Two unit tangents of the plane.
  double t1[3] = { n[1], -n[0], 0 };
  const double l1 = std::sqrt(t1[0] * t1[0] + t1[1] * t1[1]);
  t1[0] /= l1, t1[1] /= l1;
  const double t2[3] = { n[1] * t1[2] - n[2] * t1[1], n[2] * t1[0] - n[0] * t1[2], n[0] * t1[1] - n[1] * t1[0] };
  double sum = 0;
  int count = 0;
  for (long long t = 0; t < m.NumberOfTets(); ++t)
  {
    double lo[3] = { 1e30, 1e30, 1e30 }, hi[3] = { -1e30, -1e30, -1e30 }, c = 0;
    for (int a = 0; a < 4; ++a)
    {
      const double* p = &m.Points[3 * static_cast<size_t>(m.Tets[4 * t + a])];
      const double q[3] = { p[0] - 19.6, p[1] - 19.3, p[2] - 19.4 };
      const double proj[3] = { n[0] * q[0] + n[1] * q[1] + n[2] * q[2], t1[0] * q[0] + t1[1] * q[1] + t1[2] * q[2],
        t2[0] * q[0] + t2[1] * q[1] + t2[2] * q[2] };
      for (int d = 0; d < 3; ++d)
      {
        lo[d] = std::min(lo[d], proj[d]);
        hi[d] = std::max(hi[d], proj[d]);
      }
      c += 0.25 * proj[0];
    }
    if (std::fabs(c) < band)
    {
      sum += std::max(hi[1] - lo[1], hi[2] - lo[2]) / std::max(hi[0] - lo[0], 1e-9);
      ++count;
    }
  }
  return count ? sum / count : 0.0;
}

void ExpectWithinFivePercent(const art::ReducedMesh& m, long long budget)
{
  EXPECT_LE(std::fabs(double(m.NumberOfTets() - budget)), 0.05 * budget)
    << m.NumberOfTets() << " tets for a budget of " << budget;
}
} // namespace

TEST(Anisotropic, HessianOfAQuadraticIsExact)
{
  // f = x^2 + 3 y^2 - 2 z^2 + x y: the Hessian is constant, |H| its eigenvalues made positive.
  const int d[3] = { 20, 18, 16 };
  const art::VoxelVolume v = Volume(d, [](double x, double y, double z) { return x * x + 3 * y * y - 2 * z * z + x * y; });
  art::MetricOptions o;
  o.Sigma = 0.7;
  o.TensorSigma = 0;
  const art::HessianMetric metric(v, o);
  const double p[3] = { 9.3, 8.6, 7.2 }; // inside, away from the faces
  double h[6];
  metric.HessianAt(p, h);
  const double hessian[6] = { 2, 1, 0, 6, 0, -4 };
  const art::SymmetricEigen3 eig(hessian);
  double l[3];
  for (int k = 0; k < 3; ++k)
  {
    l[k] = std::fabs(eig.Values[k]);
  }
  double abs[6];
  eig.Compose(l, abs);
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(h[i], abs[i], 1e-3) << i;
  }
}

TEST(Anisotropic, SymmetricEigenDecompositionRebuildsTheMatrix)
{
  const double m[6] = { 4, 1, -2, 3, 0.5, -1 };
  const art::SymmetricEigen3 eig(m);
  double back[6];
  eig.Compose(eig.Values, back);
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_NEAR(back[i], m[i], 1e-12) << i;
  }
  for (int a = 0; a < 3; ++a)
  {
    for (int b = 0; b < 3; ++b)
    {
      const double dot = eig.Vectors[a][0] * eig.Vectors[b][0] + eig.Vectors[a][1] * eig.Vectors[b][1] +
        eig.Vectors[a][2] * eig.Vectors[b][2];
      EXPECT_NEAR(dot, a == b ? 1.0 : 0.0, 1e-12);
    }
  }
}

TEST(Anisotropic, PlaneStepGivesTetsLongAlongItAndAFarLowerError)
{
  const int d[3] = { 40, 40, 40 };
  const art::VoxelVolume v = Volume(d, Step);
  const long long budget = 3000;
  const art::ReducedMesh aniso = art::TetReducer(Anisotropic(budget)).Run(v).back();
  art::ReducerOptions bis;
  bis.TargetTets = aniso.NumberOfTets();
  const art::ReducedMesh iso = art::TetReducer(bis).Run(v).back();
  ExpectValid(aniso);
  ExpectWithinFivePercent(aniso, budget);
  const double ratio = AlongOverAcross(aniso, 1.5), isoRatio = AlongOverAcross(iso, 1.5);
  std::printf("along / across: anisotropic %.2f, bisection %.2f; RMS %.2f vs %.2f at %lld / %lld tets\n", ratio,
    isoRatio, aniso.Rms, iso.Rms, aniso.NumberOfTets(), iso.NumberOfTets());
  EXPECT_GT(ratio, 3.0);
  EXPECT_LT(isoRatio, 2.0);
  EXPECT_LT(aniso.Rms, 0.7 * iso.Rms);
  EXPECT_EQ(aniso.Refinement, "anisotropic");
  EXPECT_FALSE(aniso.Nested);
}

TEST(Anisotropic, LinearRampIsReproducedToRoundOff)
{
  const int d[3] = { 24, 20, 18 };
  const double s[3] = { 0.5, 1.0, 2.0 }, o[3] = { -3, 2, 1 };
  auto ramp = [](double x, double y, double z) { return 2 * x - 3 * y + 0.5 * z + 7; };
  const art::VoxelVolume v = art::VolumeFromImage(fixtures::Field(d, s, o, ramp));
  art::ReducerOptions opt = Anisotropic(600);
  opt.SolverTolerance = 1e-14;
  const art::ReducedMesh m = art::TetReducer(opt).Run(v).back();
  ExpectValid(m);
  const double range = v.Range[1] - v.Range[0];
  EXPECT_LT(m.Rms, 1e-11 * range);
  EXPECT_LT(m.Max, 1e-10 * range);
  for (long long i = 0; i < m.NumberOfVertices(); ++i)
  {
    const double* p = &m.Points[3 * i];
    EXPECT_NEAR(m.Values[i], ramp(p[0], p[1], p[2]), 1e-9 * range);
  }
}

TEST(Anisotropic, FacesHugASphere)
{
  // A ball of 1000 in 0: the faces of the adapted mesh lie along its surface.
  const int d[3] = { 36, 36, 36 };
  const double c[3] = { 17.6, 17.3, 18.1 }, r = 11.2;
  const art::VoxelVolume v = Volume(d, [&](double x, double y, double z) {
    return (x - c[0]) * (x - c[0]) + (y - c[1]) * (y - c[1]) + (z - c[2]) * (z - c[2]) < r * r ? 1000.0 : 0.0;
  });
  auto hugging = [&](const art::ReducedMesh& m) {
    // Area of the faces whose three corners are within half a voxel of the sphere, against its area.
    std::map<std::array<int, 3>, int> faces;
    for (long long t = 0; t < m.NumberOfTets(); ++t)
    {
      static const int f[4][3] = { { 1, 2, 3 }, { 0, 2, 3 }, { 0, 1, 3 }, { 0, 1, 2 } };
      for (const auto& q : f)
      {
        std::array<int, 3> k = { m.Tets[4 * t + q[0]], m.Tets[4 * t + q[1]], m.Tets[4 * t + q[2]] };
        std::sort(k.begin(), k.end());
        ++faces[k];
      }
    }
    auto near = [&](int i) {
      const double* p = &m.Points[3 * static_cast<size_t>(i)];
      const double dist = std::sqrt((p[0] - c[0]) * (p[0] - c[0]) + (p[1] - c[1]) * (p[1] - c[1]) + (p[2] - c[2]) * (p[2] - c[2]));
      return std::fabs(dist - r) < 0.5;
    };
    double area = 0;
    for (const auto& f : faces)
    {
      if (near(f.first[0]) && near(f.first[1]) && near(f.first[2]))
      {
        const double* a = &m.Points[3 * static_cast<size_t>(f.first[0])];
        const double* b = &m.Points[3 * static_cast<size_t>(f.first[1])];
        const double* e = &m.Points[3 * static_cast<size_t>(f.first[2])];
        const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] }, w[3] = { e[0] - a[0], e[1] - a[1], e[2] - a[2] };
        const double x[3] = { u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0] };
        area += 0.5 * std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      }
    }
    return area / (4 * M_PI * r * r);
  };
  const art::ReducedMesh aniso = art::TetReducer(Anisotropic(6000)).Run(v).back();
  art::ReducerOptions bis;
  bis.TargetTets = aniso.NumberOfTets();
  const art::ReducedMesh iso = art::TetReducer(bis).Run(v).back();
  ExpectValid(aniso);
  const double a = hugging(aniso), b = hugging(iso);
  std::printf("sphere area covered by faces within half a voxel: anisotropic %.2f, bisection %.2f\n", a, b);
  EXPECT_GT(a, 0.5);
  EXPECT_GT(a, 3 * b);
}

TEST(Anisotropic, LevelsMeetTheirBudgetsAndAreValid)
{
  const int d[3] = { 40, 40, 40 };
  const art::VoxelVolume v = Volume(d, Step);
  art::ReducerOptions opt = Anisotropic(4000);
  opt.Levels = { 1000, 2000 };
  const auto meshes = art::TetReducer(opt).Run(v);
  ASSERT_EQ(meshes.size(), 3u);
  const long long budgets[3] = { 1000, 2000, 4000 };
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_EQ(meshes[i].TargetTets, budgets[i]);
    ExpectWithinFivePercent(meshes[i], budgets[i]);
    ExpectValid(meshes[i]);
  }
  EXPECT_GT(meshes[0].Rms, meshes[2].Rms);
}

TEST(Anisotropic, SameMeshForOneThreadAndTwo)
{
  const int d[3] = { 24, 22, 20 };
  const art::VoxelVolume v = Volume(d, [](double x, double y, double z) {
    return std::sin(0.3 * x) * 400 + (y + 0.4 * z > 16 ? 600.0 : 0.0);
  });
  fixtures::ExpectSameForOneAndTwoThreads(Anisotropic(1500), v);
}

TEST(Anisotropic, ErrorBoundIsMet)
{
  const int d[3] = { 32, 32, 32 };
  const art::VoxelVolume v = Volume(d, [](double x, double y, double z) {
    return 100 * std::sin(0.25 * x) * std::cos(0.2 * y) + 3 * z;
  });
  art::ReducerOptions opt;
  opt.Refine = art::ReducerOptions::Refinement::Anisotropic;
  opt.TargetError = 2.0;
  const auto meshes = art::TetReducer(opt).Run(v);
  ASSERT_FALSE(meshes.empty());
  EXPECT_LE(meshes.back().Rms, 2.0);
  EXPECT_TRUE(meshes.back().TargetReached);
  ExpectValid(meshes.back());
}
