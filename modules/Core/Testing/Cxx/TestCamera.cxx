#include "Camera.h"
#include "Error.h"

#include <vtkCamera.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <array>

#include <cmath>

using art::Vec3;

TEST(Camera, CentreRayFollowsTheViewDirection)
{
  vtkNew<vtkCamera> vc;
  vc->SetPosition(1, 2, 10);
  vc->SetFocalPoint(1, 2, 0);
  vc->SetViewUp(0, 1, 0);
  vc->SetViewAngle(60);
  // Odd size: the centre pixel's ray is exactly the view direction.
  const auto cam = art::Camera::FromVTK(vc, 101, 51);
  const art::Ray r = cam.Generate(50, 25);
  EXPECT_NEAR(r.dir.x, 0, 1e-15);
  EXPECT_NEAR(r.dir.y, 0, 1e-15);
  EXPECT_NEAR(r.dir.z, -1, 1e-15);
  EXPECT_EQ(r.org, Vec3(1, 2, 10));
}

TEST(Camera, EdgeRaysSpanTheVerticalViewAngle)
{
  vtkNew<vtkCamera> vc;
  vc->SetViewAngle(60);
  const auto cam = art::Camera::FromVTK(vc, 200, 100);
  // The top edge of the image (py = -0.5 is the top boundary) is 30 degrees above the axis.
  const art::Ray top = cam.Generate(99.5, -0.5);
  EXPECT_NEAR(std::atan2(top.dir.y, -top.dir.z) * 180 / M_PI, 30.0, 1e-9);
  // Row 0 is the top: its rays point up.
  EXPECT_GT(cam.Generate(100, 0).dir.y, 0);
  // Aspect 2: the right edge is at atan(2 tan 30).
  const art::Ray right = cam.Generate(199.5, 49.5);
  EXPECT_NEAR(std::atan2(right.dir.x, -right.dir.z), std::atan(2 * std::tan(M_PI / 6)), 1e-9);
}

TEST(Camera, ParallelProjectionRaysShareDirection)
{
  vtkNew<vtkCamera> vc;
  vc->ParallelProjectionOn();
  vc->SetParallelScale(3);
  const auto cam = art::Camera::FromVTK(vc, 10, 10);
  const art::Ray a = cam.Generate(-0.5, -0.5), b = cam.Generate(9.5, 9.5);
  EXPECT_EQ(a.dir, b.dir);
  EXPECT_NEAR(a.org.x, -3, 1e-12);
  EXPECT_NEAR(a.org.y, 3, 1e-12);
  EXPECT_NEAR(b.org.x, 3, 1e-12);
}

TEST(Camera, FrameShowsTheWholeBox)
{
  vtkNew<vtkCamera> vc;
  const art::Box3 box({ -1, -2, -3 }, { 5, 4, 3 });
  art::Camera::Frame(vc, box, 30, 20, 1.0);
  const Vec3 f(vc->GetFocalPoint());
  EXPECT_NEAR(Length(f - box.Center()), 0, 1e-12);
  // Every box corner projects inside the view cone.
  const auto cam = art::Camera::FromVTK(vc, 100, 100);
  const double half = 30 * M_PI / 180;
  for (int i = 0; i < 8; ++i)
  {
    const Vec3 c((i & 1) ? 5 : -1, (i & 2) ? 4 : -2, (i & 4) ? 3 : -3);
    const Vec3 d = Normalize(c - cam.Position());
    EXPECT_LT(std::acos(Dot(d, cam.Forward())), half + 1e-9);
  }
}

// A portrait image fits the narrower horizontal angle: framed by the vertical one alone, the box's
// sides fell outside a 40 x 100 image (the CT head cut off in a tall viewer window).
// Landscape and square images are framed as before. Checked by projecting every box corner.
TEST(Camera, FrameFitsPortraitImages)
{
  const art::Box3 box({ -1, -2, -3 }, { 5, 4, 3 });
  for (bool parallel : { false, true })
  {
    for (const auto& size : { std::array<int, 2>{ 40, 100 }, std::array<int, 2>{ 100, 100 }, std::array<int, 2>{ 250, 100 } })
    {
      vtkNew<vtkCamera> vc;
      vc->SetParallelProjection(parallel);
      art::Camera::Frame(vc, box, 30, 20, 1.0, double(size[0]) / size[1]);
      const auto cam = art::Camera::FromVTK(vc, size[0], size[1]);
      // The pixel a corner falls on, from the rays through the image's corners and centre.
      const art::Ray c0 = cam.Generate(0.5 * size[0] - 0.5, 0.5 * size[1] - 0.5);
      const art::Ray cx = cam.Generate(size[0] - 0.5, 0.5 * size[1] - 0.5);
      const art::Ray cy = cam.Generate(0.5 * size[0] - 0.5, -0.5);
      auto plane = [&](const art::Ray& r) { return parallel ? r.org : r.org + r.dir / Dot(r.dir, cam.Forward()); };
      const Vec3 o = plane(c0), ex = plane(cx) - o, ey = plane(cy) - o;
      for (int i = 0; i < 8; ++i)
      {
        const Vec3 p((i & 1) ? 5 : -1, (i & 2) ? 4 : -2, (i & 4) ? 3 : -3);
        const Vec3 q = parallel ? p : cam.Position() + (p - cam.Position()) / Dot(p - cam.Position(), cam.Forward());
        const double u = Dot(q - o, ex) / Dot(ex, ex), v = Dot(q - o, ey) / Dot(ey, ey);
        EXPECT_LE(std::fabs(u), 1.0) << size[0] << "x" << size[1] << " parallel " << parallel << " corner " << i;
        EXPECT_LE(std::fabs(v), 1.0) << size[0] << "x" << size[1] << " parallel " << parallel << " corner " << i;
      }
    }
  }
}

// A NaN or infinite angle (from a script or a mistyped option) made every ray NaN: the voxel
// reference crashed and the surface tracer wrote a blank image. Framing refuses them.
TEST(Camera, FrameRefusesNonFiniteAnglesAndZoom)
{
  const art::Box3 box(Vec3(0, 0, 0), Vec3(1, 2, 3));
  const double bad[] = { std::nan(""), INFINITY, -INFINITY };
  for (double v : bad)
  {
    vtkNew<vtkCamera> vc;
    EXPECT_THROW(art::Camera::Frame(vc, box, v, 0, 1), art::Error);
    EXPECT_THROW(art::Camera::Frame(vc, box, 0, v, 1), art::Error);
    EXPECT_THROW(art::Camera::Frame(vc, box, 0, 0, v), art::Error);
  }
  vtkNew<vtkCamera> vc;
  EXPECT_THROW(art::Camera::Frame(vc, box, 0, 0, 0), art::Error);
  EXPECT_NO_THROW(art::Camera::Frame(vc, box, 720, -45, 3));
}

TEST(Camera, DefaultViewSeesFlatDataFaceOn)
{
  // From the front, z up; a slab thin in z from above (y up), one thin in x from the side.
  auto view = [](art::Vec3 hi, double* pos, double* up) {
    vtkNew<vtkCamera> c;
    art::Camera::DefaultView(c, art::Box3{ art::Vec3(0, 0, 0), hi });
    c->GetPosition(pos);
    c->GetViewUp(up);
  };
  double p[3], u[3];
  view(art::Vec3(10, 12, 8), p, u);
  EXPECT_EQ(p[1], -1);
  EXPECT_EQ(u[2], 1);
  view(art::Vec3(31, 31, 1), p, u);
  EXPECT_EQ(p[2], 1);
  EXPECT_EQ(u[1], 1);
  view(art::Vec3(0.5, 20, 30), p, u);
  EXPECT_EQ(p[0], -1);
  EXPECT_EQ(u[2], 1);
}
