// The tet caster against closed forms: a linear field with a constant-opacity transfer function,
// two tetrahedralisations, thread counts, a sphere's distance field iso-surface, and bad meshes.
#include "Error.h"
#include "MeanSpacing.h"
#include "MeshFixtures.h"
#include "ParallelTiles.h"
#include "TetRayCaster.h"
#include "VoxelReferenceCaster.h"

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkCellType.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace art;

namespace
{
double Linear(const Vec3& p) { return 0.3 + 0.2 * p.x - 0.1 * p.y + 0.15 * p.z; }

// Red rises, green falls, blue constant; constant opacity 0.3 per 0.5 units.
TransferFunction LinearTF(double lo, double hi)
{
  return TransferFunction({ { lo, { 0, 1, 0.5 }, 0.3, 0 }, { hi, { 1, 0, 0.5 }, 0.3, 0 } }, 0.5);
}

Camera ViewOf(const Box3& b, int w, int h, double az, double el)
{
  vtkNew<vtkCamera> cam;
  cam->SetPosition(0, -1, 0);
  cam->SetFocalPoint(0, 0, 0);
  cam->SetViewUp(0, 0, 1);
  Camera::Frame(cam, b, az, el, 1.3);
  return Camera::FromVTK(cam, w, h);
}
} // namespace

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

TEST(VoxelReferenceCaster, IsoSurfaceOfASphere)
{
  // The reference composites iso-surfaces too (so --iso renders get error figures): a sphere's
  // distance field seen by a parallel camera is an opaque disc of the sphere's radius, lit
  // head-on at its centre (ambient + diffuse = 1) and darker towards the rim.
  const Vec3 c(0.1, -0.05, 0.02);
  const double R = 0.6, h = 0.1;
  const int n = 21;
  std::vector<double> v;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        v.push_back(Length(Vec3(-1 + i * h, -1 + j * h, -1 + k * h) - c));
  const int dims[3] = { n, n, n };
  VoxelReferenceCaster rc(v, dims, { -1, -1, -1 }, { h, h, h },
    TransferFunction({ { 0, { 0, 0, 0 }, 0.0, 0 }, { 2, { 0, 0, 0 }, 0.0, 0 } }));
  rc.SetIsoSurfaces({ { R, { { 1, 1, 1 } }, 1.0 } }, 0.3, 0.7);
  vtkNew<vtkCamera> vc;
  vc->SetPosition(c.x, c.y, 5);
  vc->SetFocalPoint(c.x, c.y, c.z);
  vc->SetViewUp(0, 1, 0);
  vc->SetParallelProjection(1);
  vc->SetParallelScale(1.0);
  const Camera cam = Camera::FromVTK(vc, 41, 41);
  Image img;
  rc.Render(cam, img);
  int disc = 0;
  for (int y = 0; y < 41; ++y)
    for (int x = 0; x < 41; ++x)
    {
      const Ray r = cam.Generate(x, y);
      const double d = std::hypot(r.org.x - c.x, r.org.y - c.y);
      const float* p = img.Pixel(x, y);
      if (d < R - 0.05)
      {
        ++disc;
        EXPECT_NEAR(p[3], 1.0, 1e-9) << x << "," << y;
      }
      else if (d > R + 0.05)
        EXPECT_EQ(p[3], 0.0f) << x << "," << y;
    }
  EXPECT_GT(disc, 400);
  EXPECT_NEAR(img.Pixel(20, 20)[0], 1.0, 0.02); // facing the viewer
  // 0.537 from the axis, n . view = 0.446: shade 0.61.
  EXPECT_NEAR(img.Pixel(20, 9)[3], 1.0, 1e-9);
  EXPECT_NEAR(img.Pixel(20, 9)[0], 0.3 + 0.7 * 0.446, 0.05);
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

TEST(TetMesh, FromImageSaysWhatIsMissing)
{
  // A 10 x 10 x 1 image has scalars but no cells: the message says that, not "needs scalars".
  vtkNew<vtkImageData> flat;
  flat->SetDimensions(10, 10, 1);
  flat->AllocateScalars(VTK_FLOAT, 1);
  try
  {
    TetMesh::FromImage(flat, "flat.vti");
    FAIL() << "a one-voxel-thick image was accepted";
  }
  catch (const Error& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find("10 x 10 x 1 voxels has no cells"), std::string::npos) << what;
    EXPECT_EQ(what.find("scalars"), std::string::npos) << what;
  }
  vtkNew<vtkImageData> bare;
  bare->SetDimensions(4, 4, 4);
  EXPECT_THROW(TetMesh::FromImage(bare), Error);
  // Scalars of another image's size (set by hand) were read past their end.
  vtkNew<vtkFloatArray> few;
  few->SetNumberOfTuples(27);
  few->Fill(1.0);
  bare->GetPointData()->SetScalars(few);
  try
  {
    TetMesh::FromImage(bare, "few.vti");
    FAIL() << "27 values for 64 voxels accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("few.vti: the volume's scalars hold 27 values for 4 x 4 x 4 voxels"),
      std::string::npos) << e.what();
  }
  // NaN voxels (a masked MRI map) are named as voxels, by their index in the extent; the message
  // was the mesh's "point 21 has a non-finite coordinate or scalar".
  vtkNew<vtkImageData> masked;
  masked->SetExtent(10, 13, 0, 3, 5, 8);
  masked->AllocateScalars(VTK_FLOAT, 1);
  masked->GetPointData()->GetScalars()->Fill(1.0);
  masked->GetPointData()->GetScalars()->SetComponent(1 + 4 * (1 + 4 * 1), 0, std::nan(""));
  masked->GetPointData()->GetScalars()->SetComponent(63, 0, std::numeric_limits<double>::infinity());
  try
  {
    TetMesh::FromImage(masked, "masked.vti");
    FAIL() << "NaN voxels were accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("2 voxels hold NaN or infinite values (the first at i, j, k = 11, 1, 6)"),
      std::string::npos)
      << e.what();
  }
}

TEST(TetMesh, FromVTKAndBadMeshes)
{
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(0, 0, 0);
  pts->InsertNextPoint(1, 0, 0);
  pts->InsertNextPoint(0, 1, 0);
  pts->InsertNextPoint(0, 0, 1);
  pts->InsertNextPoint(1, 1, 1);
  pts->InsertNextPoint(-1, -1, 0.5);
  ug->SetPoints(pts);
  vtkIdType t0[4] = { 0, 1, 2, 3 }, t1[4] = { 1, 2, 3, 4 };
  ug->InsertNextCell(VTK_TETRA, 4, t0);
  ug->InsertNextCell(VTK_TETRA, 4, t1);
  EXPECT_THROW(TetMesh::FromVTK(ug), Error); // no scalars at all
  // Cell scalars only: averaged to the points (as vtkCellDataToPointData does), with a note.
  vtkNew<vtkDoubleArray> cs;
  cs->SetName("pressure");
  cs->InsertNextValue(2.0);
  cs->InsertNextValue(6.0);
  ug->GetCellData()->SetScalars(cs);
  std::string cellNote;
  const TetMesh cm = TetMesh::FromVTK(ug, {}, &cellNote);
  EXPECT_NE(cellNote.find("cell scalars 'pressure' were averaged to the points"), std::string::npos) << cellNote;
  EXPECT_DOUBLE_EQ(cm.Scalars()[0], 2.0); // only in tet 0
  EXPECT_DOUBLE_EQ(cm.Scalars()[4], 6.0); // only in tet 1
  EXPECT_DOUBLE_EQ(cm.Scalars()[1], 4.0); // shared
  EXPECT_THROW(TetMesh::FromVTK(ug, "temperature"), Error);
  // An array shorter than its cells or points (made by hand) was read past its end ('point 31 has a
  // non-finite coordinate or scalar', or a crash): it is named with both counts.
  cs->SetNumberOfTuples(1);
  try
  {
    TetMesh::FromVTK(ug, {}, nullptr, "short.vtu");
    FAIL() << "a short cell array accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("short.vtu: cell array 'pressure' holds 1 values for 2 cells"),
      std::string::npos) << e.what();
  }
  ug->GetCellData()->Initialize();
  vtkNew<vtkDoubleArray> s;
  s->SetName("f");
  for (int i = 0; i < 3; ++i)
    s->InsertNextValue(i);
  ug->GetPointData()->SetScalars(s);
  try
  {
    TetMesh::FromVTK(ug, {}, nullptr, "short.vtu");
    FAIL() << "a short point array accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("short.vtu: point array 'f' holds 3 values for 6 points"),
      std::string::npos) << e.what();
  }
  for (int i = 3; i < 6; ++i)
    s->InsertNextValue(i);
  const TetMesh m = TetMesh::FromVTK(ug);
  EXPECT_EQ(m.NumberOfTets(), 2u);
  EXPECT_EQ(m.Neighbours(0)[0], 1); // face (1,2,3) is shared
  EXPECT_EQ(m.BoundaryFaces().size(), 6u);
  // A third tet on the same face is inconsistent.
  vtkIdType t2[4] = { 1, 2, 3, 5 };
  ug->InsertNextCell(VTK_TETRA, 4, t2);
  try
  {
    TetMesh::FromVTK(ug, {}, nullptr, "three.vtu");
    FAIL();
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("three.vtu: inconsistent neighbours: a face of tet"), std::string::npos)
      << e.what();
    EXPECT_NE(std::string(e.what()).find("is shared by 3 tets"), std::string::npos) << e.what();
  }
  // Two tets on the same side of their shared face overlap.
  vtkNew<vtkUnstructuredGrid> over;
  vtkNew<vtkPoints> op;
  for (int i = 0; i < 4; ++i)
    op->InsertNextPoint(pts->GetPoint(i));
  op->InsertNextPoint(0.1, 0.1, 0.1); // inside tet (0, 1, 2, 3)
  over->SetPoints(op);
  vtkIdType inner[4] = { 1, 2, 3, 4 };
  over->InsertNextCell(VTK_TETRA, 4, t0);
  over->InsertNextCell(VTK_TETRA, 4, inner);
  vtkNew<vtkDoubleArray> os;
  for (int i = 0; i < 5; ++i)
    os->InsertNextValue(i);
  over->GetPointData()->SetScalars(os);
  try
  {
    TetMesh::FromVTK(over, {}, nullptr, "over.vtu");
    FAIL() << "overlapping tets accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("over.vtu: inconsistent neighbours: tets 0 and 1 lie on the same side"),
      std::string::npos) << e.what();
  }
  // A hexahedron is tetrahedralised with a note.
  vtkNew<vtkUnstructuredGrid> hex;
  vtkNew<vtkPoints> hp;
  vtkNew<vtkDoubleArray> hs;
  for (int i = 0; i < 8; ++i)
  {
    hp->InsertNextPoint(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    hs->InsertNextValue(i);
  }
  hex->SetPoints(hp);
  hex->GetPointData()->SetScalars(hs);
  vtkIdType h[8] = { 0, 1, 3, 2, 4, 5, 7, 6 };
  hex->InsertNextCell(VTK_HEXAHEDRON, 8, h);
  std::string note;
  const TetMesh hm = TetMesh::FromVTK(hex, {}, &note);
  EXPECT_GE(hm.NumberOfTets(), 5u);
  EXPECT_NE(note.find("tetrahedralised"), std::string::npos);
}

// A mesh whose tets each keep their own points (as exported meshes often do) is merged back into
// one with shared faces, with a note: the same tets and boundary, and the same image as the shared
// mesh. Points equal in position but not in scalar (a discontinuous field) are kept apart.
TEST(TetMesh, DuplicatePointsAreMerged)
{
  const TetMesh shared = fixtures::GridMesh(3, 2, 2, { 0, 0, 0 }, { 1, 1, 1 }, Linear, 5);
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  for (std::size_t t = 0; t < shared.NumberOfTets(); ++t)
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
    {
      const Vec3& p = shared.PointsArray()[shared.Tet(t)[k]];
      ids[k] = pts->InsertNextPoint(p.x, p.y, p.z);
      f->InsertNextValue(shared.Scalars()[shared.Tet(t)[k]]);
    }
    ug->InsertNextCell(VTK_TETRA, 4, ids);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(f);
  std::string note;
  const TetMesh m = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_NE(note.find(std::to_string(4 * shared.NumberOfTets() - shared.PointsArray().size()) + " duplicate points"),
    std::string::npos) << note;
  EXPECT_EQ(m.PointsArray().size(), shared.PointsArray().size());
  EXPECT_EQ(m.BoundaryFaces().size(), shared.BoundaryFaces().size());
  // A preset's unit distance counts the merged points, as for the mesh with shared points.
  const double spacing = std::cbrt(3.0 * 2.0 * 2.0 / double(shared.PointsArray().size()));
  EXPECT_NEAR(TransferFunction::SampleSpacing(ug, &m), spacing, 1e-12);
  EXPECT_NEAR(TransferFunction::SampleSpacing(ug), std::cbrt(12.0 / double(4 * shared.NumberOfTets())), 1e-12)
    << "without the mesh, every cell's own points";
  // Points no cell uses (far away) change neither the mesh's bounds nor its count.
  for (int k = 0; k < 5; ++k)
  {
    pts->InsertNextPoint(100.0 + k, 0, 0);
    f->InsertNextValue(0.0);
  }
  const TetMesh withUnused = TetMesh::FromVTK(ug, {}, nullptr);
  EXPECT_NEAR(TransferFunction::SampleSpacing(ug, &withUnused), spacing, 1e-12);
  EXPECT_TRUE(m.IsConvex());
  RenderSettings s;
  s.tf = LinearTF(shared.ScalarRange(0), shared.ScalarRange(1));
  const Camera cam = ViewOf(shared.Bounds(), 24, 20, 35, 25);
  Image a, b;
  TetRayCaster(shared, s).Render(cam, a);
  TetRayCaster(m, s).Render(cam, b);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 24; ++x)
      ASSERT_NEAR(a.Pixel(x, y)[3], b.Pixel(x, y)[3], 1e-12) << x << "," << y;
  // A jump in the field across every face: nothing merges.
  for (vtkIdType i = 0; i < f->GetNumberOfTuples(); ++i)
  {
    f->SetValue(i, f->GetValue(i) + 0.01 * (i / 4)); // a different offset in every tet
  }
  f->Modified();
  note.clear();
  const TetMesh apart = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_EQ(note.find("duplicate"), std::string::npos) << note;
  EXPECT_EQ(apart.BoundaryFaces().size(), 4 * apart.NumberOfTets());
}

// A surface saved as a grid is named as such; surface cells beside tets are left out with a note.
TEST(TetMesh, SurfaceCellsAreNamed)
{
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> f;
  for (int i = 0; i < 5; ++i)
  {
    pts->InsertNextPoint(i == 1, i == 2, i == 3 ? 1 : (i == 4 ? -1 : 0));
    f->InsertNextValue(i);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(f);
  vtkIdType tri[3] = { 0, 1, 2 }, tet[4] = { 0, 1, 2, 3 };
  ug->InsertNextCell(VTK_TRIANGLE, 3, tri);
  try
  {
    TetMesh::FromVTK(ug, {}, nullptr, "surface.vtu");
    ADD_FAILURE() << "a triangle-only grid was accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("holds no 3-D cells (its 1 cells are surface"), std::string::npos) << e.what();
  }
  ug->InsertNextCell(VTK_TETRA, 4, tet);
  std::string note;
  const TetMesh m = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_EQ(m.NumberOfTets(), 1u);
  EXPECT_NE(note.find("1 cells that are not 3-D were left out"), std::string::npos) << note;
}

// Surface cells beside tets (as ParaView's output often has) are left out without tetrahedralising
// the tets again: the note does not claim a tetrahedralisation (it did, for every cell, and ran the
// triangle filter over the whole mesh: 2.4 s instead of 0.12 s for a 150k-tet mesh with one triangle).
// A hexahedron beside them is tetrahedralised and counted alone.
TEST(TetMesh, SurfaceCellsBesideTetsAreOnlyLeftOut)
{
  const TetMesh tets = fixtures::GridMesh(2, 2, 2, { 0, 0, 0 }, { 1, 1, 1 }, Linear, 5);
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> f;
  for (std::size_t i = 0; i < tets.NumberOfPoints(); ++i)
  {
    const Vec3& p = tets.PointsArray()[i];
    pts->InsertNextPoint(p.x, p.y, p.z);
    f->InsertNextValue(tets.Scalars()[i]);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(f);
  vtkIdType tri[3] = { 0, 1, 2 }, quad[4] = { 0, 1, 4, 3 };
  ug->InsertNextCell(VTK_TRIANGLE, 3, tri);
  for (std::size_t t = 0; t < tets.NumberOfTets(); ++t)
  {
    const vtkIdType ids[4] = { tets.Tet(t)[0], tets.Tet(t)[1], tets.Tet(t)[2], tets.Tet(t)[3] };
    ug->InsertNextCell(VTK_TETRA, 4, ids);
  }
  ug->InsertNextCell(VTK_QUAD, 4, quad);
  std::string note;
  const TetMesh m = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_EQ(note, "2 cells that are not 3-D were left out");
  ASSERT_EQ(m.NumberOfTets(), tets.NumberOfTets());
  for (std::size_t t = 0; t < m.NumberOfTets(); ++t)
  {
    auto a = m.Tet(t), b = tets.Tet(t);
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b) << t;
  }

  // A unit hexahedron apart from the grid (x 3 .. 4): 3-D, so tetrahedralised.
  const vtkIdType base = pts->GetNumberOfPoints();
  vtkIdType hex[8];
  for (int k = 0; k < 8; ++k)
  {
    const double x = 3 + ((k == 1 || k == 2 || k == 5 || k == 6) ? 1 : 0), y = (k % 4 >= 2) ? 1 : 0, z = k >= 4;
    pts->InsertNextPoint(x, y, z);
    f->InsertNextValue(Linear(Vec3(x, y, z)));
    hex[k] = base + k;
  }
  ug->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
  note.clear();
  const TetMesh withHex = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_NE(note.find("non-tetrahedral cells were tetrahedralised (" + std::to_string(tets.NumberOfTets() + 1) +
              " 3-D cells -> "),
    std::string::npos)
    << note;
  EXPECT_NE(note.find("2 cells that are not 3-D were left out"), std::string::npos) << note;
  EXPECT_GT(withHex.NumberOfTets(), tets.NumberOfTets() + 4);
}

// A reducer's output (field data scalar_range_min/max, as ReducerVTK writes) maps presets onto its
// volume's range, as `render VOLUME --tets N` does: the fit's overshoot widened the mesh's own range,
// and a uint16 volume's mesh (0 .. 61481 reduced to -2132 .. 65580) took the CT preset in HU, 8.8 dB
// from the same tets rendered from the volume. Scalars a filter changed since keep their own range.
TEST(TetMesh, ReducedMeshKeepsItsVolumesRange)
{
  const TetMesh tets = fixtures::GridMesh(2, 2, 2, { 0, 0, 0 }, { 1, 1, 1 }, Linear, 5);
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> f, twice;
  f->SetName("f");
  twice->SetName("twice");
  for (std::size_t i = 0; i < tets.NumberOfPoints(); ++i)
  {
    const Vec3& p = tets.PointsArray()[i];
    pts->InsertNextPoint(p.x, p.y, p.z);
    f->InsertNextValue(1000 * tets.Scalars()[i]);
    twice->InsertNextValue(2000 * tets.Scalars()[i]);
  }
  for (std::size_t t = 0; t < tets.NumberOfTets(); ++t)
  {
    const vtkIdType ids[4] = { tets.Tet(t)[0], tets.Tet(t)[1], tets.Tet(t)[2], tets.Tet(t)[3] };
    ug->InsertNextCell(VTK_TETRA, 4, ids);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(f);
  ug->GetPointData()->AddArray(twice);
  double own[2];
  f->GetRange(own);
  const double lo = own[0] + 0.05 * (own[1] - own[0]), hi = own[1] - 0.05 * (own[1] - own[0]);
  auto field = [&](const char* name, double v) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(v);
    ug->GetFieldData()->AddArray(a);
  };
  EXPECT_EQ(TetMesh::FromVTK(ug).ScalarRange(0), own[0]); // no field: its own
  field("scalar_range_min", lo);
  field("scalar_range_max", hi);
  const TetMesh reduced = TetMesh::FromVTK(ug);
  EXPECT_EQ(reduced.ScalarRange(0), lo);
  EXPECT_EQ(reduced.ScalarRange(1), hi);
  EXPECT_EQ(TetMesh::FromVTK(ug, "f").ScalarRange(1), hi); // the same array by name
  const TetMesh other = TetMesh::FromVTK(ug, "twice"); // another array: its own
  EXPECT_EQ(other.ScalarRange(1), 2 * own[1]);
  ug->GetPointData()->SetScalars(twice); // rescaled since (a calculator): its own range
  EXPECT_EQ(TetMesh::FromVTK(ug).ScalarRange(1), 2 * own[1]);
}

// Without active scalars (as ParaView saves a filter's output), the field is the first array that
// is not VTK's bookkeeping: ParaView's Extract Selection puts vtkOriginalPointIds first, and the
// point ids were rendered as the field without a word.
TEST(TetMesh, BookkeepingArraysAreNotTheField)
{
  const TetMesh tets = fixtures::GridMesh(2, 2, 2, { 0, 0, 0 }, { 1, 1, 1 }, Linear, 5);
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> ids, f;
  ids->SetName("vtkOriginalPointIds");
  f->SetName("density");
  for (std::size_t i = 0; i < tets.NumberOfPoints(); ++i)
  {
    const Vec3& p = tets.PointsArray()[i];
    pts->InsertNextPoint(p.x, p.y, p.z);
    ids->InsertNextValue(static_cast<double>(i));
    f->InsertNextValue(tets.Scalars()[i]);
  }
  for (std::size_t t = 0; t < tets.NumberOfTets(); ++t)
  {
    const vtkIdType c[4] = { tets.Tet(t)[0], tets.Tet(t)[1], tets.Tet(t)[2], tets.Tet(t)[3] };
    ug->InsertNextCell(VTK_TETRA, 4, c);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->AddArray(ids);
  ug->GetPointData()->AddArray(f);
  ASSERT_EQ(ug->GetPointData()->GetScalars(), nullptr);
  const TetMesh m = TetMesh::FromVTK(ug);
  for (std::size_t i = 0; i < m.NumberOfPoints(); ++i)
  {
    EXPECT_EQ(m.Scalars()[i], tets.Scalars()[i]) << i;
  }
  ug->GetPointData()->RemoveArray("density"); // only bookkeeping left: taken as before
  EXPECT_EQ(TetMesh::FromVTK(ug).ScalarRange(1), double(tets.NumberOfPoints() - 1));
}

// Points no tet uses (a clip's leftovers, stray points far away, a NaN among them) are dropped:
// the bounds, and so the framing, are the tets', and the mesh is not refused.
TEST(TetMesh, UnusedPointsAreDropped)
{
  const TetMesh tets = fixtures::GridMesh(2, 2, 2, { 0, 0, 0 }, { 1, 1, 1 }, Linear, 5);
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  auto stray = [&](double x, double v) {
    pts->InsertNextPoint(x, x, x);
    f->InsertNextValue(v);
  };
  stray(1000, 1);
  for (std::size_t i = 0; i < tets.NumberOfPoints(); ++i)
  {
    const Vec3& p = tets.PointsArray()[i];
    pts->InsertNextPoint(p.x, p.y, p.z);
    f->InsertNextValue(tets.Scalars()[i]);
    if (i == 5)
    {
      stray(std::nan(""), std::nan(""));
    }
  }
  stray(-1e9, 0);
  auto id = [](std::size_t i) { return static_cast<vtkIdType>(1 + i + (i > 5 ? 1 : 0)); };
  for (std::size_t t = 0; t < tets.NumberOfTets(); ++t)
  {
    vtkIdType ids[4];
    for (int k = 0; k < 4; ++k)
      ids[k] = id(tets.Tet(t)[k]);
    ug->InsertNextCell(VTK_TETRA, 4, ids);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(f);
  std::string note;
  const TetMesh m = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_NE(note.find("3 points no tet uses were dropped"), std::string::npos) << note;
  EXPECT_EQ(m.NumberOfPoints(), tets.NumberOfPoints());
  EXPECT_EQ(m.Bounds().lo.x, 0.0);
  EXPECT_EQ(m.Bounds().hi.x, 2.0);
  for (std::size_t i = 0; i < m.NumberOfPoints(); ++i)
    EXPECT_EQ(m.Scalars()[i], tets.Scalars()[i]) << i; // in order
}

// A volume whose direction matrix turns it 90 degrees about z renders exactly like the same voxels
// stored already turned (axes swapped, one reversed) with the identity direction: through the
// full-resolution tets and through the voxel reference alike.
TEST(VoxelReference, DirectionMatrixMatchesTheTurnedVolume)
{
  const int nx = 9, ny = 6, nz = 5;
  const double h = 0.5;
  // Linear in the index, so every tetrahedralisation interpolates it exactly.
  auto value = [](int i, int j, int k) { return 1.0 + 2.0 * i + 0.5 * j + k; };
  vtkNew<vtkImageData> a, b;
  a->SetDimensions(nx, ny, nz);
  a->SetSpacing(h, h, h);
  a->SetOrigin(1, 2, 3);
  const double turn[9] = { 0, -1, 0, 1, 0, 0, 0, 0, 1 }; // world = origin + R (index * h)
  a->SetDirectionMatrix(turn);
  b->SetDimensions(ny, nx, nz);
  b->SetSpacing(h, h, h);
  b->SetOrigin(1 - (ny - 1) * h, 2, 3);
  vtkNew<vtkDoubleArray> sa, sb;
  sa->SetNumberOfTuples(nx * ny * nz);
  sb->SetNumberOfTuples(nx * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
      {
        // A's voxel (i, j, k) sits at x = 1 - j h, y = 2 + i h: B's voxel (ny - 1 - j, i, k).
        sa->SetValue(i + nx * (j + ny * k), value(i, j, k));
        sb->SetValue((ny - 1 - j) + ny * (i + nx * k), value(i, j, k));
      }
  a->GetPointData()->SetScalars(sa);
  b->GetPointData()->SetScalars(sb);
  const TransferFunction tf({ { 0, { 1, 0.5, 0 }, 0.0, 0 }, { 25, { 0, 0.5, 1 }, 0.9, 0 } }, 1.0);
  const TetMesh ma = TetMesh::FromImage(a), mb = TetMesh::FromImage(b);
  const Camera cam = ViewOf(mb.Bounds(), 48, 40, 30, 20);
  RenderSettings s;
  s.tf = tf;
  s.earlyTermination = 2;
  Image ia, ib, ra, rb;
  TetRayCaster(ma, s).Render(cam, ia);
  TetRayCaster(mb, s).Render(cam, ib);
  VoxelReferenceCaster::FromVTK(a, tf).Render(cam, ra);
  VoxelReferenceCaster::FromVTK(b, tf).Render(cam, rb);
  double tetDiff = 0, refDiff = 0, alpha = 0;
  for (int y = 0; y < cam.Height(); ++y)
    for (int x = 0; x < cam.Width(); ++x)
      for (int c = 0; c < 4; ++c)
      {
        tetDiff = std::max(tetDiff, double(std::fabs(ia.Pixel(x, y)[c] - ib.Pixel(x, y)[c])));
        refDiff = std::max(refDiff, double(std::fabs(ra.Pixel(x, y)[c] - rb.Pixel(x, y)[c])));
        alpha += ib.Pixel(x, y)[3];
      }
  EXPECT_GT(alpha, 0.2 * cam.Width() * cam.Height()); // the volume fills the view
  EXPECT_LT(refDiff, 1e-6);
  EXPECT_LT(tetDiff, 1e-5);
}

// A sheared direction matrix (a gantry-tilted CT): the voxel reference of a field linear in the
// index matches the full-resolution tets (both exact for it), iso-surface shading included, which
// needs the world gradient (the frame's taken through the inverse transpose).
TEST(VoxelReference, ShearedDirectionMatchesTheTets)
{
  const int nx = 9, ny = 6, nz = 5;
  vtkNew<vtkImageData> a;
  a->SetDimensions(nx, ny, nz);
  a->SetSpacing(0.5, 0.4, 0.6);
  a->SetOrigin(1, 2, 3);
  const double shear[9] = { 1, 0.5, 0, 0, 1, 0, 0, 0.3, 1.2 }; // world = origin + M (index * h)
  a->SetDirectionMatrix(shear);
  vtkNew<vtkDoubleArray> sa;
  sa->SetNumberOfTuples(nx * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        sa->SetValue(i + nx * (j + ny * k), 1.0 + 2.0 * i + 0.5 * j + k);
  a->GetPointData()->SetScalars(sa);
  const TransferFunction tf({ { 0, { 1, 0.5, 0 }, 0.0, 0 }, { 25, { 0, 0.5, 1 }, 0.9, 0 } }, 1.0);
  const TetMesh m = TetMesh::FromImage(a);
  const Camera cam = ViewOf(m.Bounds(), 48, 40, 30, 20);
  RenderSettings s;
  s.tf = tf;
  s.earlyTermination = 2;
  auto rc = VoxelReferenceCaster::FromVTK(a, tf);
  for (bool iso : { false, true })
  {
    s.isos = iso ? std::vector<IsoSurface>{ { 9.5, { { 1, 1, 1 } }, 0.5 } } : std::vector<IsoSurface>{};
    rc.SetIsoSurfaces(s.isos, s.ambient, s.diffuse);
    Image tets, ref;
    TetRayCaster(m, s).Render(cam, tets);
    rc.Render(cam, ref);
    double diff = 0, alpha = 0;
    for (int y = 0; y < cam.Height(); ++y)
      for (int x = 0; x < cam.Width(); ++x)
        for (int c = 0; c < 4; ++c)
        {
          diff = std::max(diff, double(std::fabs(tets.Pixel(x, y)[c] - ref.Pixel(x, y)[c])));
          alpha += tets.Pixel(x, y)[3];
        }
    EXPECT_GT(alpha, 0.2 * cam.Width() * cam.Height()) << "iso " << iso;
    EXPECT_LT(diff, 1e-4) << "iso " << iso;
  }
  const double singular[9] = { 1, 2, 0, 2, 4, 0, 0, 0, 1 };
  EXPECT_THROW(rc.SetDirection(singular), Error);
}

// An image whose extent starts at (20, -3, 5) sits where its first voxel is: it renders exactly like
// the same voxels with extent 0 and the origin moved there (tets and reference alike).
TEST(VoxelReference, ExtentStartMatchesAMovedOrigin)
{
  const int n[3] = { 7, 6, 5 }, e0[3] = { 20, -3, 5 };
  const double h = 0.5;
  vtkNew<vtkImageData> a, b;
  a->SetExtent(e0[0], e0[0] + n[0] - 1, e0[1], e0[1] + n[1] - 1, e0[2], e0[2] + n[2] - 1);
  b->SetDimensions(n[0], n[1], n[2]);
  for (vtkImageData* img : { a.GetPointer(), b.GetPointer() })
  {
    img->SetSpacing(h, h, h);
  }
  a->SetOrigin(1, 2, 3);
  b->SetOrigin(1 + e0[0] * h, 2 + e0[1] * h, 3 + e0[2] * h);
  vtkNew<vtkDoubleArray> s;
  s->SetNumberOfTuples(n[0] * n[1] * n[2]);
  for (vtkIdType i = 0; i < s->GetNumberOfTuples(); ++i)
  {
    s->SetValue(i, double((i * 7) % 13));
  }
  a->GetPointData()->SetScalars(s);
  b->GetPointData()->SetScalars(s);
  const TransferFunction tf({ { 0, { 1, 0.5, 0 }, 0.0, 0 }, { 13, { 0, 0.5, 1 }, 0.9, 0 } }, 1.0);
  const TetMesh ma = TetMesh::FromImage(a), mb = TetMesh::FromImage(b);
  double ba[6];
  a->GetBounds(ba);
  const Camera cam = ViewOf(Box3::FromBounds(ba), 40, 32, 25, 15);
  RenderSettings rs;
  rs.tf = tf;
  Image ia, ib, ra, rb;
  TetRayCaster(ma, rs).Render(cam, ia);
  TetRayCaster(mb, rs).Render(cam, ib);
  VoxelReferenceCaster::FromVTK(a, tf).Render(cam, ra);
  VoxelReferenceCaster::FromVTK(b, tf).Render(cam, rb);
  double alpha = 0;
  for (int y = 0; y < cam.Height(); ++y)
    for (int x = 0; x < cam.Width(); ++x)
    {
      for (int c = 0; c < 4; ++c)
      {
        ASSERT_NEAR(ia.Pixel(x, y)[c], ib.Pixel(x, y)[c], 1e-7) << x << "," << y;
        ASSERT_NEAR(ra.Pixel(x, y)[c], rb.Pixel(x, y)[c], 1e-7) << x << "," << y;
      }
      alpha += ib.Pixel(x, y)[3];
    }
  EXPECT_GT(alpha, 0.2 * cam.Width() * cam.Height()); // the volume fills the view
}

// Cell scalars of hexahedra are averaged to the points on the hexahedra, as vtkCellDataToPointData
// gives them, not on the tets they are split into (which would weigh a cell by its tet count).
TEST(TetMesh, CellScalarsAveragedBeforeTetrahedralising)
{
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i)
        pts->InsertNextPoint(i, j, k);
  ug->SetPoints(pts);
  auto id = [](int i, int j, int k) { return vtkIdType(i + 3 * (j + 2 * k)); };
  for (int c = 0; c < 2; ++c)
  {
    const vtkIdType h[8] = { id(c, 0, 0), id(c + 1, 0, 0), id(c + 1, 1, 0), id(c, 1, 0), id(c, 0, 1), id(c + 1, 0, 1),
      id(c + 1, 1, 1), id(c, 1, 1) };
    ug->InsertNextCell(VTK_HEXAHEDRON, 8, h);
  }
  vtkNew<vtkDoubleArray> v;
  v->SetName("phase");
  v->InsertNextValue(0.0);
  v->InsertNextValue(1.0);
  ug->GetCellData()->SetScalars(v);
  std::string note;
  const TetMesh m = TetMesh::FromVTK(ug, {}, &note);
  EXPECT_NE(note.find("tetrahedralised"), std::string::npos) << note;
  EXPECT_NE(note.find("cell scalars 'phase' were averaged"), std::string::npos) << note;
  int middle = 0;
  for (std::size_t p = 0; p < m.PointsArray().size(); ++p)
  {
    const double x = m.PointsArray()[p].x;
    EXPECT_DOUBLE_EQ(m.Scalars()[p], x == 0 ? 0.0 : (x == 1 ? 0.5 : 1.0)) << "point at x = " << x;
    middle += x == 1 ? 1 : 0;
  }
  EXPECT_EQ(middle, 4);
}

// A preset's unit distance follows the data's sample spacing (1 mm on CT in HU): the same voxels
// stored in metres, millimetres or kilometres render the same image, as they would in ParaView.
// With the unit distance fixed at 1 world unit the metre volume comes out nearly clear and the
// kilometre one opaque.
TEST(TransferFunction, PresetScalesWithTheSampleSpacing)
{
  const int n = 12;
  auto volumeAt = [&](double h) {
    vtkNew<vtkImageData> v;
    v->SetDimensions(n, n, n);
    v->SetSpacing(h, h, h);
    v->SetOrigin(-0.5 * h * (n - 1), 3 * h, 0);
    vtkNew<vtkDoubleArray> s;
    s->SetNumberOfTuples(n * n * n);
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          s->SetValue(i + n * (j + n * k), std::sin(0.5 * i) + 0.2 * j + 0.1 * k * k);
    v->GetPointData()->SetScalars(s);
    return vtkSmartPointer<vtkImageData>(v.Get());
  };
  auto render = [&](vtkImageData* v, bool scaled) {
    double r[2];
    v->GetPointData()->GetScalars()->GetRange(r);
    const double u = scaled ? TransferFunction::PresetUnitDistance(r[0], r[1], TransferFunction::SampleSpacing(v)) : 1.0;
    const TetMesh m = TetMesh::FromImage(v);
    RenderSettings s;
    s.tf = TransferFunction::Preset("grey-ramp", r[0], r[1], u);
    Image img;
    TetRayCaster(m, s).Render(ViewOf(m.Bounds(), 40, 32, 30, 20), img);
    return img;
  };
  auto meanAlpha = [](const Image& img) {
    double a = 0;
    for (int y = 0; y < img.Height(); ++y)
      for (int x = 0; x < img.Width(); ++x)
        a += img.Pixel(x, y)[3];
    return a / (img.Width() * img.Height());
  };
  auto maxDiff = [](const Image& a, const Image& b) {
    double d = 0;
    for (int y = 0; y < a.Height(); ++y)
      for (int x = 0; x < a.Width(); ++x)
        for (int c = 0; c < 4; ++c)
          d = std::max(d, double(std::fabs(a.Pixel(x, y)[c] - b.Pixel(x, y)[c])));
    return d;
  };
  const auto mm = volumeAt(1.0), m = volumeAt(1e-3), km = volumeAt(1e3);
  EXPECT_DOUBLE_EQ(TransferFunction::SampleSpacing(m), 1e-3);
  const Image ref = render(mm, true);
  EXPECT_GT(meanAlpha(ref), 0.2);
  EXPECT_LT(maxDiff(ref, render(m, true)), 1e-4);
  EXPECT_LT(maxDiff(ref, render(km, true)), 1e-4);
  EXPECT_LT(meanAlpha(render(m, false)), 0.01);
  EXPECT_GT(meanAlpha(render(km, false)), 0.5);
  // CT in Hounsfield units with voxels of 0.1 to 10 mm keeps the presets' millimetres.
  EXPECT_EQ(TransferFunction::PresetUnitDistance(-1024, 3071, 0.5), 1.0);
  EXPECT_EQ(TransferFunction::PresetUnitDistance(0, 255, 0.5), 0.5);
  // CT whose voxels are no millimetres (metres, a micro-CT's microns): scaled as other data.
  EXPECT_EQ(TransferFunction::PresetUnitDistance(-1024, 3071, 0.001), 0.001);
  EXPECT_EQ(TransferFunction::PresetUnitDistance(-1024, 3071, 0.02), 0.02);
  EXPECT_EQ(TransferFunction::PresetUnitDistance(-1024, 3071, 50.0), 50.0);
  EXPECT_EQ(TransferFunction::PresetUnitDistance(-1024, 3071, 5.0), 1.0);
}

// "auto" on a range that looks like Hounsfield units: a float simulation field of -997 .. 997 (no
// whole values, 0.8% near -1000) gets the grey ramp, not CT colours; the same values rounded to
// whole numbers (as a scanner stores them), or with a tenth of the samples at air, count as CT.
TEST(TransferFunction, AutoTellsCTFromASignedField)
{
  auto field = [](bool whole, bool air) {
    vtkNew<vtkImageData> v;
    const int n = 24;
    v->SetDimensions(n, n, n);
    vtkNew<vtkFloatArray> a;
    a->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
    for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    {
      const double x = 0.05 * double(i % n), y = 0.05 * double((i / n) % n), z = 0.05 * double(i / (n * n));
      double f = 997.5 * std::sin(6.0 * x + 0.3) * std::cos(4.0 * y) * std::cos(z + 0.2);
      f = air && i % 10 == 0 ? -1000.25 : f;
      a->SetValue(i, static_cast<float>(whole ? std::round(f) : f));
    }
    v->GetPointData()->SetScalars(a);
    return v;
  };
  for (int k = 0; k < 3; ++k)
  {
    const auto v = field(k == 1, k == 2);
    const double* r = v->GetPointData()->GetScalars()->GetRange();
    ASSERT_TRUE(TransferFunction::LooksLikeHU(r[0], r[1]));
    const auto tf = TransferFunction::PresetFor("auto", v, r[0], r[1]);
    EXPECT_EQ(tf.Nodes().size(), k == 0 ? 2u : 8u) << "case " << k; // grey-ramp has 2 nodes, ct-skin-bone 8
  }
}

// Spacing of data other than images: the reducer's source_spacing field, else the mean point spacing
// over the non-flat axes of the bounds.
TEST(TransferFunction, SampleSpacingOfMeshes)
{
  vtkNew<vtkUnstructuredGrid> g;
  vtkNew<vtkPoints> p;
  for (int i = 0; i < 1000; ++i)
    p->InsertNextPoint((i % 10) * 0.2, (i / 10 % 10) * 0.2, (i / 100) * 0.2); // 10^3 points 0.2 apart
  g->SetPoints(p);
  EXPECT_NEAR(TransferFunction::SampleSpacing(g), 1.8 / 10, 1e-7); // (1.8^3 / 1000)^(1/3), float points
  vtkNew<vtkDoubleArray> h;
  h->SetName("source_spacing");
  h->InsertNextValue(0.25);
  g->GetFieldData()->AddArray(h);
  EXPECT_EQ(TransferFunction::SampleSpacing(g), 0.25);
  const double flat[3] = { 4.0, 0.0, 9.0 }; // a slab: spacing over its two axes
  EXPECT_NEAR(MeanSpacing(flat, 36), 1.0, 1e-12);
  const double none[3] = { 0, 0, 0 };
  EXPECT_EQ(MeanSpacing(none, 1), 1.0);
}

// Full-resolution tets that would not fit are refused before anything is built, naming the file
// and the memory (the CT head's 4.3 M tets need about 0.7 GB).
TEST(TetMesh, FullResolutionMemoryGuard)
{
  const long long ctHead = 5LL * 127 * 127 * 53;
  EXPECT_NO_THROW(TetMesh::CheckFullResolutionFits(ctHead, 24e9, "head.mha"));
  EXPECT_NO_THROW(TetMesh::CheckFullResolutionFits(ctHead, 0.0, "head.mha")); // memory unknown
  try
  {
    TetMesh::CheckFullResolutionFits(ctHead, 0.5e9, "head.mha");
    FAIL() << "0.7 GB of tets accepted with 0.5 GB available";
  }
  catch (const Error& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find("head.mha"), std::string::npos) << what;
    EXPECT_NE(what.find("need about 0.684 GB, more than the 0.5 GB of memory available"), std::string::npos) << what;
    EXPECT_NE(what.find("--tets"), std::string::npos) << what;
  }
  EXPECT_THROW(TetMesh::CheckFullResolutionFits(1LL << 29, 0.0, "big.mha"), Error);
}

// A flat tet (four coplanar points, as Delaunay meshes of lattice points have) has no side of its
// faces: it is linked to its neighbour, not reported as an overlap.
TEST(TetMesh, FlatTetBesideANormalOneIsLinked)
{
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  const double p[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 0 } };
  vtkNew<vtkDoubleArray> s;
  for (int i = 0; i < 5; ++i)
  {
    pts->InsertNextPoint(p[i]);
    s->InsertNextValue(i);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(s);
  vtkIdType normal[4] = { 0, 1, 2, 3 }, flat[4] = { 0, 1, 2, 4 };
  ug->InsertNextCell(VTK_TETRA, 4, normal);
  ug->InsertNextCell(VTK_TETRA, 4, flat);
  const TetMesh m = TetMesh::FromVTK(ug, {}, nullptr, "flat.vtu");
  EXPECT_EQ(m.BoundaryFaces().size(), 6u); // 8 faces, one pair shared
}

// Non-finite voxels are a clear error naming the file, not a crash in the reference.
TEST(VoxelReference, NonFiniteVoxelsAreAnError)
{
  vtkNew<vtkImageData> v;
  v->SetExtent(2, 4, 0, 2, 0, 2);
  vtkNew<vtkDoubleArray> s;
  s->SetNumberOfTuples(27);
  s->Fill(1.0);
  s->SetValue(13, std::nan(""));
  s->SetValue(26, -std::numeric_limits<double>::infinity());
  v->GetPointData()->SetScalars(s);
  const TransferFunction tf = TransferFunction::Preset("grey-ramp", 0, 1);
  try
  {
    VoxelReferenceCaster::FromVTK(v, tf, "nan.mha");
    FAIL() << "a NaN voxel accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("nan.mha: 2 voxels hold NaN or infinite values (the first at i, j, k = 3, 1, 1); "
                                         "rendering needs finite voxels"),
      std::string::npos) << e.what();
  }
}

// Full-resolution tets of denormal voxels (1e-310) are refused with the way out: the transfer
// function built over their range crashed (its table's scale, the range's inverse, was inf).
TEST(TetMesh, DenormalVoxelsAreRefused)
{
  vtkNew<vtkImageData> img;
  img->SetDimensions(3, 3, 3);
  vtkNew<vtkDoubleArray> s;
  s->SetNumberOfTuples(27);
  for (int i = 0; i < 27; ++i)
  {
    s->SetValue(i, 1e-310 * (1 + i));
  }
  img->GetPointData()->SetScalars(s);
  try
  {
    TetMesh::FromImage(img, "tiny.vti");
    FAIL() << "denormal voxels accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("tiny.vti: the scalars' range 1e-310 .. 2.7e-309 lies below 1e-150"),
      std::string::npos)
      << e.what();
  }
}

// A mesh's NaN point scalars (a masked simulation field) are counted and the first placed in the
// world, with what to do; it said 'point 2 has a non-finite coordinate or scalar', an index into
// the mesh as cleaned (unused points dropped, duplicates merged), not the file's.
TEST(TetMesh, NaNPointScalarsAreCountedAndPlaced)
{
  vtkNew<vtkUnstructuredGrid> ug;
  vtkNew<vtkPoints> pts;
  const double p[6][3] = { { 9, 9, 9 }, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 1 } };
  vtkNew<vtkDoubleArray> s;
  s->SetName("pressure");
  for (int i = 0; i < 6; ++i)
  {
    pts->InsertNextPoint(p[i]);
    s->InsertNextValue(i == 3 || i == 5 ? std::nan("") : i);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(s);
  const vtkIdType a[4] = { 1, 2, 3, 4 }, b[4] = { 2, 3, 4, 5 };
  ug->InsertNextCell(VTK_TETRA, 4, a);
  ug->InsertNextCell(VTK_TETRA, 4, b);
  try
  {
    TetMesh::FromVTK(ug, {}, nullptr, "flow.vtu");
    FAIL() << "NaN scalars accepted";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("flow.vtu: 2 points have a NaN or infinite scalar (the first at x, y, z = 0, "
                                         "1, 0); rendering needs finite values"),
      std::string::npos)
      << e.what();
  }
}

// A mesh whose tets would not fit in the memory available is refused before the triangle filter
// and the engine's arrays, naming the file, the tets and the way out.
TEST(TetMesh, MeshMemoryGuard)
{
  EXPECT_NO_THROW(TetMesh::CheckMeshFits(6000000, 24e9, "flow.vtu")); // 1.2 GB
  EXPECT_NO_THROW(TetMesh::CheckMeshFits(600000000, 0.0, "flow.vtu")); // memory unknown
  try
  {
    TetMesh::CheckMeshFits(150000000, 24e9, "flow.vtu"); // 25 million hexahedra: 30 GB
    FAIL() << "30 GB of tets accepted with 24 GB available";
  }
  catch (const Error& e)
  {
    EXPECT_EQ(std::string(e.what()), "flow.vtu: its cells make about 150000000 tets, which need about 30 GB, more than "
                                     "the 24 GB of memory available; render a part of it first (e.g. ParaView's "
                                     "Extract Cells By Region, Clip or Threshold)");
  }
}
