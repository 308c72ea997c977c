// SurfaceTracer against hand-computed shading: Lambert from a point light, a hard shadow, and light
// attenuated through a transparent occluder with the all-hits query.
#include "SurfaceTracer.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
// A floor square z = 0 over [-10, 10]^2 and an occluder square z = 1 over [-1, 1]^2.
std::shared_ptr<art::TriangleStore> Scene()
{
  std::vector<art::Vec3> p = { { -10, -10, 0 }, { 10, -10, 0 }, { 10, 10, 0 }, { -10, 10, 0 }, { -1, -1, 1 },
    { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } };
  return std::make_shared<art::TriangleStore>(
    p, std::vector<std::array<long long, 3>>{ { 0, 1, 2 }, { 0, 2, 3 }, { 4, 5, 6 }, { 4, 6, 7 } });
}

art::Ray Towards(const art::Vec3& from, const art::Vec3& to)
{
  art::Ray r;
  r.org = from;
  r.dir = to - from;
  return r;
}
} // namespace

TEST(SurfaceTracer, LambertShadowAndTransparency)
{
  auto store = Scene();
  auto acc = art::MakeAccelerator(store, {});
  art::SurfaceTracerSettings s;
  s.lights = { { { 0, 0, 5 }, 0.8 } }; // shading stays below 1 (it is clamped there)
  s.ambient = 0.1;
  s.smooth = false;
  s.color = { { 1.f, 1.f, 1.f } };
  art::Counters c;
  const art::Vec3 eye(15, 0.3, 3);
  {
    // Lit floor point (5, 5, 0): ambient + 0.8 cos, cos = 5 / |(-5, -5, 5)|.
    art::SurfaceTracer t(*acc, s);
    const auto px = t.Trace(Towards(eye, { 5, 5, 0 }), c);
    EXPECT_NEAR(px[0], 0.1 + 0.8 * 5 / std::sqrt(75.0), 1e-5);
    EXPECT_FLOAT_EQ(px[3], 1.f);
    // Floor point (0.2, 0.3, 0) lies in the occluder's shadow: ambient only.
    const auto sh = t.Trace(Towards(eye, { 0.2, 0.3, 0 }), c);
    EXPECT_NEAR(sh[0], 0.1, 1e-6);
    s.shadows = false;
    const auto ns = art::SurfaceTracer(*acc, s).Trace(Towards(eye, { 0.2, 0.3, 0 }), c);
    EXPECT_NEAR(ns[0], 0.1 + 0.8 * 5 / std::sqrt(0.04 + 0.09 + 25), 1e-5);
    s.shadows = true;
  }
  {
    // Opacity 0.5: the view ray meets the floor only (alpha 0.5); light through the occluder is halved.
    s.opacity = 0.5;
    art::SurfaceTracer t(*acc, s);
    const auto px = t.Trace(Towards(eye, { 0.2, 0.3, 0 }), c);
    const double shade = 0.1 + 0.5 * 0.8 * 5 / std::sqrt(0.04 + 0.09 + 25);
    EXPECT_NEAR(px[0], 0.5 * shade, 1e-5);
    EXPECT_NEAR(px[3], 0.5, 1e-6);
    // Looking straight down through the occluder onto the floor: two layers composited.
    const auto two = t.Trace(Towards({ 0.5, 0.5, 10 }, { 0.5, 0.5, 0 }), c);
    EXPECT_NEAR(two[3], 0.75, 1e-6);
  }
}
