// The tet caster against closed forms and references: a linear field with a constant-opacity
// transfer function, two tetrahedralisations, thread counts, a sphere's distance field
// iso-surface, maximum intensity, clipping planes, opaque geometry and a camera inside the mesh.
#include "Error.h"
#include "MeshFixtures.h"
#include "ParallelTiles.h"
#include "TetRayCaster.h"
#include "VoxelReferenceCaster.h"

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkNew.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace art;
using fixtures::Linear;
using fixtures::LinearTF;
using fixtures::ViewOf;

namespace
{
// Every pixel against the closed-form integral of the linear field through the box (from the
// ray's origin when that lies inside); returns the number of pixels whose ray meets the box.
int ExpectClosedForm(const TetMesh& m, const Image& img, const Camera& cam, double lo, double hi,
  const std::vector<double>* ends = nullptr, const std::vector<std::array<double, 4>>& planes = {})
{
  const double tau = -std::log(0.7) / 0.5;
  int inside = 0;
  for (int y = 0; y < img.Height(); ++y)
    for (int x = 0; x < img.Width(); ++x)
    {
      Ray r = cam.Generate(x, y);
      r.tmax = ends ? (*ends)[y * img.Width() + x] : r.tmax;
      double t0, t1, C[3] = { 0, 0, 0 }, a = 0;
      bool in = m.Bounds().Clip(r, t0, t1);
      for (const auto& q : planes) // the half-space a x + b y + c z + d >= 0 on the ray
      {
        const double at0 = q[0] * r.At(t0).x + q[1] * r.At(t0).y + q[2] * r.At(t0).z + q[3];
        const double at1 = q[0] * r.At(t1).x + q[1] * r.At(t1).y + q[2] * r.At(t1).z + q[3];
        if (at0 < 0 && at1 < 0)
          in = false;
        else if (at0 < 0)
          t0 += (t1 - t0) * at0 / (at0 - at1);
        else if (at1 < 0)
          t1 -= (t1 - t0) * at1 / (at1 - at0);
      }
      if (in && t1 > t0)
      {
        ++inside;
        const double L = (t1 - t0) * Length(r.dir), s0 = Linear(r.At(t0)), s1 = Linear(r.At(t1));
        const double T = std::exp(-tau * L), J = -std::expm1(-tau * L) / (tau * L);
        const double c0[3] = { (s0 - lo) / (hi - lo), (hi - s0) / (hi - lo), 0.5 };
        const double c1[3] = { (s1 - lo) / (hi - lo), (hi - s1) / (hi - lo), 0.5 };
        for (int k = 0; k < 3; ++k)
          C[k] = c0[k] - c1[k] * T + (c1[k] - c0[k]) * J;
        a = 1 - T;
      }
      const float* p = img.Pixel(x, y);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(p[k], C[k], 1e-5) << x << "," << y;
      EXPECT_NEAR(p[3], a, 1e-5) << x << "," << y;
      if (::testing::Test::HasFailure())
        return inside;
    }
  return inside;
}
} // namespace

namespace
{
// The linear field on a 1 x 1 x 1 box of 4 x 3 x 5 cubes, its transfer function's range, and
// settings without early termination: what the closed-form tests render.
constexpr double LinearLo = -0.2, LinearHi = 0.9;
TetMesh LinearBox()
{
  return fixtures::GridMesh(4, 3, 5, { 0, 0, 0 }, { 0.25, 1.0 / 3, 0.2 }, Linear, 6);
}
RenderSettings LinearSettings()
{
  RenderSettings s;
  s.tf = LinearTF(LinearLo, LinearHi);
  s.earlyTermination = 2.0;
  return s;
}
} // namespace

TEST(TetRayCast, LinearFieldMatchesClosedForm)
{
  const TetMesh m = LinearBox();
  ASSERT_TRUE(m.IsConvex());
  const double lo = LinearLo, hi = LinearHi;
  RenderSettings s = LinearSettings();
  const TetRayCaster rc(m, s);
  const Camera cam = ViewOf(m.Bounds(), 48, 40, 30, 20);
  Image img;
  const RenderStats st = rc.Render(cam, img);
  EXPECT_GT(ExpectClosedForm(m, img, cam, lo, hi), 500);
  EXPECT_GT(st.counters.tetsCrossed, st.counters.hits);
  EXPECT_LT(st.counters.entrySearches, st.counters.hits / 4) << "coherent entrance walk";
}

TEST(TetRayCast, RaysEndAtOpaqueGeometry)
{
  // Each ray ends on a sphere through the box (as opaque geometry drawn before the volume would
  // end it): the closed form up to there. Rays that miss the sphere run to the far side.
  const TetMesh m = LinearBox();
  const double lo = LinearLo, hi = LinearHi;
  RenderSettings s = LinearSettings();
  const Camera cam = ViewOf(m.Bounds(), 48, 40, 30, 20);
  std::vector<double> ends(48 * 40, std::numeric_limits<double>::infinity());
  const Vec3 c(0.5, 0.4, 0.6);
  int cut = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 48; ++x)
    {
      const Ray r = cam.Generate(x, y);
      const Vec3 oc = r.org - c;
      const double a = Dot(r.dir, r.dir), b = Dot(oc, r.dir), disc = b * b - a * (Dot(oc, oc) - 0.35 * 0.35);
      if (disc > 0)
      {
        ends[y * 48 + x] = (-b - std::sqrt(disc)) / a;
        ++cut;
      }
    }
  ASSERT_GT(cut, 100);
  Image img;
  TetRayCaster(m, s).Render(cam, img, nullptr, &ends);
  EXPECT_GT(ExpectClosedForm(m, img, cam, lo, hi, &ends), 500);
  // Maximum intensity only sees the field up to the end.
  s.mode = RenderSettings::Mode::MaxIntensity;
  Ray r;
  r.org = { -1, 0.5, 0.5 };
  r.dir = { 1, 0, 0 }; // the field rises along x
  r.tmax = 1.6;
  EXPECT_NEAR(TetRayCaster(m, s).Cast(r).maxScalar, Linear({ 0.6, 0.5, 0.5 }), 1e-12);
  std::vector<double> wrong(10, 1.0);
  EXPECT_THROW(TetRayCaster(m, s).Render(cam, img, nullptr, &wrong), Error);
}

TEST(TetRayCast, CameraInsideTheMesh)
{
  // Rays that start inside are integrated from their origin: perspective (every ray from the
  // eye's tet) and parallel (origins on a plane through the mesh), each against the closed form.
  const TetMesh m = LinearBox();
  const double lo = LinearLo, hi = LinearHi;
  RenderSettings s = LinearSettings();
  const TetRayCaster rc(m, s);
  for (bool parallel : { false, true })
  {
    vtkNew<vtkCamera> vc;
    vc->SetPosition(0.37, 0.41, 0.53); // inside the 1 x 1 x 1 box, off every vertex and face
    vc->SetFocalPoint(0.9, 0.8, 0.7);
    vc->SetViewUp(0, 0, 1);
    vc->SetViewAngle(70);
    vc->SetParallelProjection(parallel);
    vc->SetParallelScale(0.2);
    const Camera cam = Camera::FromVTK(vc, 40, 32);
    Image img;
    rc.Render(cam, img);
    EXPECT_EQ(ExpectClosedForm(m, img, cam, lo, hi), 40 * 32) << "parallel " << parallel;
  }
}

TEST(TetRayCast, ClippingPlanesCutEachRay)
{
  // Two oblique planes leave a wedge of the box: each pixel against the closed form over the
  // wedge, from outside (perspective) and from inside (parallel, origins in the clipped part).
  const TetMesh m = LinearBox();
  RenderSettings s = LinearSettings();
  s.clipPlanes = { { 1, 0.5, -0.3, -0.41 }, { -0.2, 1, 0.6, -0.35 } };
  const TetRayCaster rc(m, s);
  Image img;
  const Camera outside = ViewOf(m.Bounds(), 48, 40, 30, 20);
  rc.Render(outside, img);
  const int kept = ExpectClosedForm(m, img, outside, LinearLo, LinearHi, nullptr, s.clipPlanes);
  EXPECT_GT(kept, 200);
  int box = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 48; ++x)
    {
      double t0, t1;
      box += m.Bounds().Clip(outside.Generate(x, y), t0, t1) ? 1 : 0;
    }
  EXPECT_LT(kept, box - 200) << "the planes cut rays off";
  // The voxel reference (the same linear field sampled on the box's 5 x 4 x 6 grid) clips alike.
  std::vector<double> values;
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 5; ++i)
        values.push_back(Linear({ 0.25 * i, j / 3.0, 0.2 * k }));
  const int dims[3] = { 5, 4, 6 };
  VoxelReferenceCaster ref(values, dims, { 0, 0, 0 }, { 0.25, 1.0 / 3, 0.2 }, s.tf);
  ref.SetClipPlanes(s.clipPlanes);
  ref.Render(outside, img);
  EXPECT_EQ(ExpectClosedForm(m, img, outside, LinearLo, LinearHi, nullptr, s.clipPlanes), kept);
  // The tets wholly clipped away leave the walk (cullClipped, the default): the same image, from
  // fewer tets than walking them without integrating, seen from the clipped side.
  {
    const TetMesh fine = fixtures::GridMesh(12, 12, 12, { 0, 0, 0 }, { 1.0 / 12, 1.0 / 12, 1.0 / 12 }, Linear, 6);
    RenderSettings cut = s, walkAll = s;
    cut.clipPlanes = walkAll.clipPlanes = { { 1, 0.1, 0.2, -0.53 } };
    walkAll.cullClipped = false;
    const Camera side = ViewOf(fine.Bounds(), 48, 40, 270, 10);
    Image culled, walked;
    const RenderStats a = TetRayCaster(fine, cut).Render(side, culled);
    const RenderStats b = TetRayCaster(fine, walkAll).Render(side, walked);
    EXPECT_LT(a.counters.tetsCrossed, b.counters.tetsCrossed * 3 / 4);
    double worst = 0;
    for (std::size_t i = 0; i < culled.Pixels().size(); ++i)
      worst = std::max(worst, double(std::fabs(culled.Pixels()[i] - walked.Pixels()[i])));
    EXPECT_LT(worst, 1e-6);
    EXPECT_GT(ExpectClosedForm(fine, culled, side, LinearLo, LinearHi, nullptr, cut.clipPlanes), 200);
  }
  vtkNew<vtkCamera> vc;
  vc->SetPosition(0.37, 0.41, 0.53);
  vc->SetFocalPoint(0.9, 0.8, 0.7);
  vc->SetViewUp(0, 0, 1);
  vc->SetParallelProjection(true);
  vc->SetParallelScale(0.3);
  const Camera inside = Camera::FromVTK(vc, 40, 32);
  rc.Render(inside, img);
  EXPECT_GT(ExpectClosedForm(m, img, inside, LinearLo, LinearHi, nullptr, s.clipPlanes), 200);
  // One ray by Cast, and everything clipped away.
  Ray r;
  r.org = { -1, 0.5, 0.5 };
  r.dir = { 1, 0, 0 };
  s.clipPlanes = { { 1, 0, 0, -0.6 } };
  EXPECT_NEAR(TetRayCaster(m, s).Cast(r).rgba[3], 1 - std::pow(0.7, 0.4 / 0.5), 1e-12);
  s.clipPlanes = { { 1, 0, 0, -2 } };
  TetRayCaster(m, s).Render(outside, img);
  for (float v : img.Pixels())
    ASSERT_EQ(v, 0.0f);
}

TEST(TetRayCast, TwoTetrahedralisationsGiveTheSameImage)
{
  const TetMesh a = fixtures::GridMesh(5, 5, 5, { -1, -1, -1 }, { 0.4, 0.4, 0.4 }, Linear, 6);
  const TetMesh b = fixtures::GridMesh(5, 5, 5, { -1, -1, -1 }, { 0.4, 0.4, 0.4 }, Linear, 5);
  EXPECT_EQ(a.NumberOfTets(), 750u);
  EXPECT_EQ(b.NumberOfTets(), 625u);
  RenderSettings s;
  s.tf = TransferFunction({ { -0.2, { 0, 0, 1 }, 0.0, 0 }, { 0.2, { 0, 1, 0 }, 0.6, 0 }, { 0.6, { 1, 0, 0 }, 0.1, 0 },
                            { 1.0, { 1, 1, 1 }, 0.9, 0 } },
    0.3);
  s.earlyTermination = 2.0;
  const Camera cam = ViewOf(a.Bounds(), 40, 40, -35, 25);
  Image ia, ib;
  TetRayCaster(a, s).Render(cam, ia);
  TetRayCaster(b, s).Render(cam, ib);
  double worst = 0;
  for (std::size_t i = 0; i < ia.Pixels().size(); ++i)
    worst = std::max(worst, double(std::fabs(ia.Pixels()[i] - ib.Pixels()[i])));
  EXPECT_LT(worst, 1e-6);
}

TEST(TetRayCast, ThreadCountDoesNotChangeTheImage)
{
  auto f = [](const Vec3& p) { return std::sin(3 * p.x) * std::cos(2 * p.y) + p.z; };
  const TetMesh m = fixtures::GridMesh(8, 8, 8, { 0, 0, 0 }, { 0.125, 0.125, 0.125 }, f, 5);
  RenderSettings s;
  s.tf = TransferFunction::Preset("grey-ramp", m.ScalarRange(0), m.ScalarRange(1));
  s.isos = { { 0.5, { { 1, 0.8, 0.6 } }, 0.4 } };
  const Camera cam = ViewOf(m.Bounds(), 64, 48, 10, 10);
  Image one, two;
  const int before = GetThreadCount();
  SetThreadCount(1);
  TetRayCaster(m, s).Render(cam, one);
  SetThreadCount(2);
  TetRayCaster(m, s).Render(cam, two);
  SetThreadCount(before);
  EXPECT_EQ(one.Pixels(), two.Pixels());
}

TEST(TetRayCast, SphereIsoSurfaceLiesAtTheRadius)
{
  const Vec3 c(0.1, -0.05, 0.02);
  const double R = 0.6, h = 0.1;
  const TetMesh m = fixtures::GridMesh(20, 20, 20, { -1, -1, -1 }, { h, h, h },
    [&](const Vec3& p) { return Length(p - c); }, 6);
  RenderSettings s;
  s.tf = TransferFunction({ { 0, { 0, 0, 0 }, 0.0, 0 }, { 2, { 0, 0, 0 }, 0.0, 0 } });
  s.isos = { { R, { { 1, 1, 1 } }, 1.0 } };
  const TetRayCaster rc(m, s);
  int hits = 0;
  for (int i = 0; i < 40; ++i)
  {
    // Rays from all around, aimed at points near the centre.
    const double th = 0.7 + i * 2.399, z = -0.9 + 1.8 * i / 39.0;
    const Vec3 dir = Normalize(Vec3(std::sqrt(1 - z * z) * std::cos(th), std::sqrt(1 - z * z) * std::sin(th), z));
    const Vec3 aim = c + Vec3(0.05 * std::sin(i), 0.03 * std::cos(i), 0.02);
    Ray r;
    r.org = aim - dir * 3.0;
    r.dir = dir;
    const RayResult res = rc.Cast(r);
    ASSERT_GT(res.firstIso, 0) << i;
    const double err = std::fabs(Length(r.At(res.firstIso) - c) - R);
    EXPECT_LT(err, 0.5 * h * h / R + 1e-9) << "ray " << i; // linear interpolation of |x|
    EXPECT_NEAR(res.rgba[3], 1.0, 1e-12);
    ++hits;
  }
  EXPECT_EQ(hits, 40);
}

TEST(TetRayCast, MaximumIntensity)
{
  const TetMesh m = fixtures::GridMesh(3, 3, 3, { 0, 0, 0 }, { 1, 1, 1 }, Linear, 6);
  RenderSettings s;
  s.tf = LinearTF(-0.2, 0.9);
  s.mode = RenderSettings::Mode::MaxIntensity;
  Ray r;
  r.org = { -1, 1.5, 1.2 };
  r.dir = { 1, 0, 0 };
  const RayResult res = TetRayCaster(m, s).Cast(r);
  EXPECT_NEAR(res.maxScalar, Linear({ 3, 1.5, 1.2 }), 1e-12);
}

// A parallel camera's rays from the notch of an L-shape (inside the mesh's box, outside the mesh),
// looking out of it: their lines meet the mesh only behind their origins, so every pixel keeps
// the background, in maximum intensity as in composite (MIP drew the transfer function's lowest
// colour there: its ray counted a piece with nothing after the origin).
TEST(TetRayCast, RaysWithTheMeshOnlyBehindThemMissIt)
{
  const TetMesh L = fixtures::GridMesh(4, 4, 2, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Linear, 6,
    [](int i, int j, int) { return !(i >= 2 && j >= 2); });
  vtkNew<vtkCamera> vc;
  vc->SetPosition(1.5, 1.5, 0.5);
  vc->SetFocalPoint(2.5, 2.5, 0.5);
  vc->SetViewUp(0, 0, 1);
  vc->SetParallelProjection(true);
  vc->SetParallelScale(0.2);
  const Camera cam = Camera::FromVTK(vc, 16, 16);
  for (auto mode : { RenderSettings::Mode::MaxIntensity, RenderSettings::Mode::Composite })
  {
    RenderSettings s;
    s.tf = LinearTF(-0.2, 0.9);
    s.mode = mode;
    Image img;
    TetRayCaster(L, s).Render(cam, img);
    for (float v : img.Pixels())
      ASSERT_EQ(v, 0.0f) << "mode " << int(mode);
    vc->SetFocalPoint(0.5, 0.5, 0.5); // turned round, the same rays meet the mesh in front
    TetRayCaster(L, s).Render(Camera::FromVTK(vc, 16, 16), img);
    vc->SetFocalPoint(2.5, 2.5, 0.5);
    double alpha = 0;
    for (int i = 3; i < static_cast<int>(img.Pixels().size()); i += 4)
      alpha += img.Pixels()[i];
    EXPECT_GT(alpha, 16 * 16 * 0.1) << "mode " << int(mode);
  }
}

// Volume shading through a linear field: one gradient everywhere, and a parallel camera sees it
// at one angle, so every pixel's lit colour is (ka + kd |n.v|) times the unlit colour plus
// ks |n.v|^p times its opacity, for either rule, with and without early termination.
TEST(TetRayCast, ShadingOfALinearFieldIsOneFactorAndOneSpecularWeight)
{
  const TetMesh m = fixtures::GridMesh(4, 3, 3, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Linear, 6);
  vtkNew<vtkCamera> vc;
  vc->SetPosition(4, -3, 2.5);
  vc->SetFocalPoint(1, 0.75, 0.75);
  vc->SetViewUp(0, 0, 1);
  vc->SetParallelProjection(1);
  vc->SetParallelScale(1.6);
  const Camera cam = Camera::FromVTK(vc, 40, 32);
  const Vec3 view = Normalize(Vec3(1, 0.75, 0.75) - Vec3(4, -3, 2.5));
  const Vec3 g(0.2, -0.1, 0.15); // Linear's gradient
  const double nv = std::fabs(Dot(g, view)) / Length(g);
  const TransferFunction tf({ { 0.0, { 0.1, 0.9, 0.3 }, 0.2, 0 }, { 0.5, { 0.8, 0.2, 0.6 }, 0.6, 0 },
                              { 1.0, { 0.9, 0.9, 0.1 }, 0.4, 0 } },
    0.5);
  for (const auto rule : { RenderSettings::Rule::Exact, RenderSettings::Rule::Trapezoid })
    for (const double ert : { 2.0, 0.9 })
    {
      RenderSettings s;
      s.tf = tf, s.rule = rule, s.earlyTermination = ert;
      Image plain, lit;
      TetRayCaster(m, s).Render(cam, plain);
      s.shading.on = true;
      s.shading.ambient = 0.2, s.shading.diffuse = 0.6, s.shading.specular = 0.4, s.shading.power = 8;
      TetRayCaster(m, s).Render(cam, lit);
      const double a = 0.2 + 0.6 * nv, spec = 0.4 * std::pow(nv, 8.0);
      double worst = 0, changed = 0;
      for (int y = 0; y < cam.Height(); ++y)
        for (int x = 0; x < cam.Width(); ++x)
        {
          const float *p = plain.Pixel(x, y), *l = lit.Pixel(x, y);
          EXPECT_EQ(p[3], l[3]); // shading changes colour, not opacity
          for (int k = 0; k < 3; ++k)
          {
            worst = std::max(worst, std::fabs(l[k] - (a * p[k] + spec * p[3])));
            changed = std::max(changed, double(std::fabs(l[k] - p[k])));
          }
        }
      EXPECT_LE(worst, 2e-6);
      EXPECT_GT(changed, 0.05) << "the light changes the image";
    }
}
