// Degenerate rays and meshes, each checked against a brute-force reference that clips the ray
// with every tet: rays exactly through vertices, along edges, inside faces, parallel to the axes;
// sliver tets; non-convex meshes (an L-shape, a block with a tunnel) that rays enter twice.
#include "MeshFixtures.h"
#include "TetRayCaster.h"

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkNew.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace art;

namespace
{
using fixtures::Wavy;

RenderSettings Settings()
{
  RenderSettings s;
  s.tf = TransferFunction({ { 0, { 0, 0, 1 }, 0.05, 0 }, { 0.4, { 0, 1, 0 }, 0.3, 0 }, { 0.5, { 1, 1, 0 }, 0.02, 0 },
                            { 1, { 1, 0, 0 }, 0.5, 0 } },
    0.7);
  s.earlyTermination = 2.0;
  return s;
}

void Check(const TetMesh& m, const TetRayCaster& rc, const Ray& r, const char* what, int expectPieces = -1)
{
  const RayResult got = rc.Cast(r);
  const RayAccum ref = fixtures::BruteForce(m, rc.Settings().tf, r);
  for (int k = 0; k < 3; ++k)
    ASSERT_NEAR(got.rgba[k], ref.rgb[k], 1e-9) << what << " ch " << k << " org " << r.org.x << "," << r.org.y
                                               << "," << r.org.z << " dir " << r.dir.x << "," << r.dir.y << ","
                                               << r.dir.z;
  ASSERT_NEAR(got.rgba[3], ref.Alpha(), 1e-9) << what;
  if (expectPieces >= 0)
    EXPECT_EQ(got.pieces, expectPieces) << what;
}

Ray MakeRay(const Vec3& o, const Vec3& d)
{
  Ray r;
  r.org = o;
  r.dir = d;
  return r;
}
} // namespace

TEST(TetStability, RaysThroughVerticesEdgesAndFaces)
{
  for (int scheme : { 5, 6 })
  {
    const TetMesh m = fixtures::GridMesh(4, 4, 4, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, scheme);
    const TetRayCaster rc(m, Settings());
    int n = 0;
    // Parallel to each axis along grid lines (the ray lies in edges), through face centres
    // (in faces), and through cell interiors.
    for (int axis = 0; axis < 3; ++axis)
      for (double u : { 0.0, 0.25, 0.5, 0.75, 1.0, 2.0 })
        for (double v : { 0.0, 0.5, 0.6, 1.5, 2.0 })
        {
          Vec3 o, d;
          o[axis] = -1;
          o[(axis + 1) % 3] = u;
          o[(axis + 2) % 3] = v;
          d[axis] = 1;
          Check(m, rc, MakeRay(o, d), "axis", 1);
          d[axis] = -1;
          o[axis] = 3;
          Check(m, rc, MakeRay(o, d), "axis reversed", 1);
          n += 2;
        }
    // Through pairs of vertices: along face and cube diagonals, through many vertices at once.
    for (const auto& pq : std::vector<std::pair<Vec3, Vec3>>{ { { 0, 0, 0 }, { 2, 2, 2 } }, { { 2, 0, 0 }, { 0, 2, 2 } },
           { { 0, 0.5, 0 }, { 2, 0.5, 2 } }, { { 0.5, 0, 1 }, { 0.5, 2, 1 } }, { { 0, 0, 0.5 }, { 1, 2, 0.5 } },
           { { 1, 1, 0 }, { 1.5, 0.5, 2 } }, { { 0, 2, 0 }, { 2, 0, 0 } }, { { 0, 0, 0 }, { 1, 0.5, 2 } } })
    {
      const Vec3 d = pq.second - pq.first;
      Check(m, rc, MakeRay(pq.first - d * 0.7, d), "vertex to vertex", 1);
      Check(m, rc, MakeRay(pq.second + d * 0.7, -d), "vertex to vertex reversed", 1);
      n += 2;
    }
    // Rays that only touch the mesh: along an outer edge and in an outer face.
    Check(m, rc, MakeRay({ -1, 0, 0 }, { 1, 0, 0 }), "outer edge");
    Check(m, rc, MakeRay({ -1, 0.7, 0 }, { 1, 0.1, 0 }), "outer face");
    EXPECT_EQ(n, 2 * 3 * 6 * 5 + 16);
  }
}

TEST(TetStability, SliverTets)
{
  const TetMesh m = fixtures::SliverMesh(); // needles and slivers everywhere
  const TetRayCaster rc(m, Settings());
  for (int i = 0; i < 200; ++i)
  {
    const Vec3 a(0.1 + 2.3 * std::fmod(i * 0.618, 1.0), 0.1 + 2.3 * std::fmod(i * 0.414, 1.0), -1);
    const Vec3 b(0.2 + 2.1 * std::fmod(i * 0.732, 1.0), 0.2 + 2.1 * std::fmod(i * 0.236, 1.0), 3);
    Check(m, rc, MakeRay(a, b - a), "sliver", 1);
  }
  // Rays grazing the squashed layer.
  Check(m, rc, MakeRay({ -1, 1.1, 1.0 + 5e-8 }, { 1, 0.01, 0 }), "inside the sliver layer");
  Check(m, rc, MakeRay({ -1, 1.0, 1.0 }, { 1, 0, 0 }), "on the sliver layer's base");
}

class NonConvex : public ::testing::TestWithParam<bool>
{
};

// Entry faces from the TriangleGrid all-hits query (true) and from the screen buckets (false).
TEST_P(NonConvex, RaysEnterTwice)
{
  RenderSettings settings = Settings();
  settings.boundaryGrid = GetParam();
  // L-shape: a quarter of the block removed.
  const TetMesh L = fixtures::GridMesh(4, 4, 2, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 6,
    [](int i, int j, int) { return !(i >= 2 && j >= 2); });
  EXPECT_FALSE(L.IsConvex());
  const TetRayCaster rc(L, settings);
  // Across both arms: leaves at x = 1, re-enters... along y at x in (0,1) it stays inside once.
  Check(L, rc, MakeRay({ 3.4, -1, 0.3 }, { -1, 1, 0.05 }), "L twice", 2);
  Check(L, rc, MakeRay({ 1.6, 2.5, 0.4 }, { -1, -1.2, 0 }), "L corner");
  for (int i = 0; i < 100; ++i)
  {
    const double a = 0.3 + i * 0.05;
    const Vec3 dir(std::cos(a), std::sin(a), 0.1 * std::sin(3 * a));
    const Vec3 c(1.0 + 0.2 * std::sin(i), 1.0 + 0.2 * std::cos(i * 1.3), 0.5);
    Check(L, rc, MakeRay(c - dir * 4, dir), "L random");
  }
  // Along grid lines and face diagonals: through the notch's concave edges and corner vertices.
  for (double u : { 0.0, 0.5, 1.0, 1.5, 2.0 })
    for (double z : { 0.0, 0.5, 1.0 })
    {
      Check(L, rc, MakeRay({ -1, u, z }, { 1, 0, 0 }), "L along x");
      Check(L, rc, MakeRay({ u, 3, z }, { 0, -1, 0 }), "L along -y");
      Check(L, rc, MakeRay({ u - 1.5, -1.5 + 0.0, z }, { 1, 1, 0 }), "L diagonal");
      Check(L, rc, MakeRay({ u + 2, -1, z + 0.25 }, { -1, 1, 0 }), "L anti-diagonal");
    }
  // A block with a tunnel through it (a hole): rays along x cross the tunnel.
  const TetMesh T = fixtures::GridMesh(5, 3, 3, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 5,
    [](int i, int j, int k) { return !(j == 1 && k == 1 && i > 0 && i < 4); });
  EXPECT_FALSE(T.IsConvex());
  const TetRayCaster rt(T, settings);
  Check(T, rt, MakeRay({ -1, 0.7, 0.7 }, { 1, 0.01, 0.02 }), "tunnel axis", 2);
  Check(T, rt, MakeRay({ 1.2, 0.75, -1 }, { 0.05, 0, 1 }), "across tunnel", 2);
  // The image path (screen buckets) agrees with single rays.
  vtkNew<vtkCamera> cam;
  cam->SetPosition(-1, -3, 2);
  cam->SetFocalPoint(1, 1, 0.5);
  const Camera c = Camera::FromVTK(cam, 40, 30);
  Image img;
  rc.Render(c, img);
  for (int y = 0; y < 30; y += 3)
    for (int x = 0; x < 40; x += 3)
    {
      const RayAccum ref = fixtures::BruteForce(L, rc.Settings().tf, c.Generate(x, y));
      EXPECT_NEAR(img.Pixel(x, y)[3], ref.Alpha(), 1e-6) << x << "," << y;
      EXPECT_NEAR(img.Pixel(x, y)[0], ref.rgb[0], 1e-6) << x << "," << y;
    }
}

// A ray ends where opaque geometry stands (Ray::tmax, the mapper's depth buffer): in the first
// piece, in the gap between pieces, inside the second, before the mesh; single rays and images.
TEST_P(NonConvex, RaysEndAtOpaqueGeometry)
{
  RenderSettings settings = Settings();
  settings.boundaryGrid = GetParam();
  const TetMesh L = fixtures::GridMesh(4, 4, 2, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 6,
    [](int i, int j, int) { return !(i >= 2 && j >= 2); });
  const TetRayCaster rc(L, settings);
  // Enters the x arm at t ~ 2.4, leaves it, crosses the notch, re-enters the y arm.
  Ray r = MakeRay({ 3.4, -1, 0.3 }, { -1, 1, 0.05 });
  const RayResult whole = rc.Cast(r);
  ASSERT_EQ(whole.pieces, 2);
  int shorter = 0;
  for (double end : { 0.5, 1.0, 1.6, 1.9, 2.2, 2.5, 2.9, 3.3, 10.0 })
  {
    r.tmax = end;
    Check(L, rc, r, "L ends");
    shorter += rc.Cast(r).rgba[3] < whole.rgba[3] - 1e-6 ? 1 : 0;
  }
  EXPECT_GE(shorter, 6) << "most of these ends cut the ray short";
  r.tmax = 0.2; // before the mesh
  EXPECT_EQ(rc.Cast(r).rgba[3], 0.0);
  // Whole images with a slanted opaque plane x + y + 2z = 2.2 through the mesh.
  vtkNew<vtkCamera> cam;
  cam->SetPosition(-1, -3, 2);
  cam->SetFocalPoint(1, 1, 0.5);
  const Camera c = Camera::FromVTK(cam, 40, 30);
  std::vector<double> ends(40 * 30, std::numeric_limits<double>::infinity());
  const Vec3 n(1, 1, 2);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x)
    {
      const Ray q = c.Generate(x, y);
      const double t = (2.2 - Dot(n, q.org)) / Dot(n, q.dir);
      ends[y * 40 + x] = t > 0 ? t : ends[y * 40 + x];
    }
  Image img, open;
  rc.Render(c, img, nullptr, &ends);
  rc.Render(c, open);
  double changed = 0;
  for (int y = 0; y < 30; y += 2)
    for (int x = 0; x < 40; x += 2)
    {
      Ray q = c.Generate(x, y);
      q.tmax = ends[y * 40 + x];
      const RayAccum ref = fixtures::BruteForce(L, rc.Settings().tf, q);
      EXPECT_NEAR(img.Pixel(x, y)[3], ref.Alpha(), 1e-6) << x << "," << y;
      EXPECT_NEAR(img.Pixel(x, y)[0], ref.rgb[0], 1e-6) << x << "," << y;
      changed = std::max(changed, double(open.Pixel(x, y)[3] - img.Pixel(x, y)[3]));
    }
  EXPECT_GT(changed, 0.1) << "the plane must hide part of the mesh";
}

// Every tet with its own four points and a field that jumps between tets: no face is shared, so
// each tet is a piece of its own that the ray enters through a face coincident with the previous
// piece's exit. The grid's all-hits query merges such coincident hits into one surface; entries
// must still find every piece.
TEST_P(NonConvex, TetsWithTheirOwnPoints)
{
  RenderSettings settings = Settings();
  settings.boundaryGrid = GetParam();
  const TetMesh g = fixtures::GridMesh(3, 3, 2, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 5);
  std::vector<Vec3> pts;
  std::vector<double> val;
  std::vector<std::array<int, 4>> tets;
  for (std::size_t t = 0; t < g.NumberOfTets(); ++t)
  {
    std::array<int, 4> ids;
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = static_cast<int>(pts.size());
      pts.push_back(g.PointsArray()[g.Tet(t)[k]]);
      val.push_back(g.Scalars()[g.Tet(t)[k]] + 0.15 * (t % 3));
    }
    tets.push_back(ids);
  }
  const TetMesh m(std::move(pts), std::move(val), std::move(tets));
  EXPECT_EQ(m.BoundaryFaces().size(), 4 * m.NumberOfTets());
  const TetRayCaster rc(m, settings);
  vtkNew<vtkCamera> cam;
  cam->SetPosition(-1.1, -2.7, 2.3);
  cam->SetFocalPoint(0.8, 0.7, 0.4);
  const Camera c = Camera::FromVTK(cam, 32, 24);
  Image img;
  rc.Render(c, img);
  int crossed = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 32; ++x)
    {
      const RayAccum ref = fixtures::BruteForce(m, rc.Settings().tf, c.Generate(x, y));
      crossed += ref.Alpha() > 0.05 ? 1 : 0;
      ASSERT_NEAR(img.Pixel(x, y)[3], ref.Alpha(), 1e-6) << x << "," << y;
      ASSERT_NEAR(img.Pixel(x, y)[1], ref.rgb[1], 1e-6) << x << "," << y;
    }
  EXPECT_GT(crossed, 200);
}

// The L-shape 2.5e7 units from the origin (survey coordinates): the boundary grid stores floats,
// so it is built about the mesh's centre; rays still enter both arms.
TEST_P(NonConvex, FarFromTheOrigin)
{
  RenderSettings settings = Settings();
  settings.boundaryGrid = GetParam();
  const Vec3 o(2.5e7, -1e7, 4e6);
  auto wavy = [&](const Vec3& p) { return Wavy(p - o); };
  const TetMesh L = fixtures::GridMesh(4, 4, 2, o, { 0.5, 0.5, 0.5 }, wavy, 6,
    [](int i, int j, int) { return !(i >= 2 && j >= 2); });
  const TetRayCaster rc(L, settings);
  int twice = 0;
  for (int i = 0; i < 60; ++i)
  {
    const double a = 0.3 + i * 0.08;
    const Vec3 dir(std::cos(a), std::sin(a), 0.1 * std::sin(3 * a));
    const Ray r = MakeRay(o + Vec3(1.0 + 0.2 * std::sin(i), 1.0 + 0.2 * std::cos(i * 1.3), 0.5) - dir * 4, dir);
    const RayResult got = rc.Cast(r);
    const RayAccum ref = fixtures::BruteForce(L, rc.Settings().tf, r);
    ASSERT_NEAR(got.rgba[3], ref.Alpha(), 1e-6) << i;
    ASSERT_NEAR(got.rgba[0], ref.rgb[0], 1e-6) << i;
    twice += got.pieces == 2 ? 1 : 0;
  }
  EXPECT_GT(twice, 5);
}

INSTANTIATE_TEST_SUITE_P(TetStability, NonConvex, ::testing::Values(true, false));

// Empty-space skipping walks only the tets the transfer function (or an iso-surface) can show,
// entering that region through its faces: every image must equal the full walk's, also for rays
// exactly along grid lines (through the region's edges and vertices), from inside the mesh, and
// on non-convex meshes, while crossing fewer tets.
TEST(TetStability, EmptySpaceSkippingKeepsEveryImage)
{
  // Wavy spans about 0.2 .. 1.4 here: two visible bands with transparent ranges around them.
  RenderSettings shown;
  shown.tf = TransferFunction({ { 0.2, { 0, 0, 1 }, 0, 0 }, { 0.7, { 0, 0, 1 }, 0, 0 }, { 0.8, { 0, 1, 0 }, 0.8, 0 },
                                { 0.9, { 1, 1, 0 }, 0, 0 }, { 1.1, { 1, 1, 0 }, 0, 0 }, { 1.3, { 1, 0, 0 }, 0.9, 0 } },
    0.5);
  shown.earlyTermination = 2.0;
  RenderSettings iso = shown;
  iso.isos.push_back({ 1.0, { { 0.9, 0.8, 0.7 } }, 0.4 }); // inside a transparent range
  auto views = [](const Box3& b, double offset) {
    std::vector<Camera> cams;
    // Parallel along each axis, 9 x 9 rays 0.5 apart: along the grid lines through the centre
    // (offset 0), or between them.
    const Vec3 c(1.5 + offset, 1.5 + offset, 1.5 + offset), axes[3] = { { 1, 0, 0 }, { 0, -1, 0 }, { 0, 0, 1 } };
    for (const Vec3& a : axes)
    {
      vtkNew<vtkCamera> vc;
      vc->SetFocalPoint(c.x, c.y, c.z);
      vc->SetPosition(c.x - 5 * a.x, c.y - 5 * a.y, c.z - 5 * a.z);
      vc->SetViewUp(0, a.z != 0 ? 1 : 0, a.z != 0 ? 0 : 1);
      vc->ParallelProjectionOn();
      vc->SetParallelScale(2.25);
      cams.push_back(Camera::FromVTK(vc, 9, 9));
    }
    // Oblique perspective views, one from inside the mesh, and parallel rays starting inside.
    for (const Vec3& eye : { Vec3(-2.0, -3.1, 4.2), Vec3(4.4, 3.7, -1.3), Vec3(0.9, 1.1, 1.3) })
    {
      vtkNew<vtkCamera> vc;
      vc->SetFocalPoint(b.Center().x + 0.1, b.Center().y, b.Center().z - 0.2);
      vc->SetPosition(eye.x, eye.y, eye.z);
      vc->SetViewUp(0, 0, 1);
      vc->SetViewAngle(60);
      cams.push_back(Camera::FromVTK(vc, 40, 30));
      vc->ParallelProjectionOn();
      vc->SetParallelScale(1.2);
      cams.push_back(Camera::FromVTK(vc, 24, 20));
    }
    return cams;
  };
  // Every pixel of both against each other; every third one of the full walk against the
  // brute-force reference too.
  auto compare = [&](const TetMesh& m, RenderSettings s, const char* what, double offset = 0.0) {
    std::uint64_t crossedOn = 0, crossedOff = 0;
    int shownPixels = 0;
    for (const Camera& cam : views(m.Bounds(), offset))
    {
      Image on, off;
      s.skipEmpty = true;
      crossedOn += TetRayCaster(m, s).Render(cam, on).counters.tetsCrossed;
      s.skipEmpty = false;
      crossedOff += TetRayCaster(m, s).Render(cam, off).counters.tetsCrossed;
      for (int y = 0; y < cam.Height(); ++y)
        for (int x = 0; x < cam.Width(); ++x)
        {
          shownPixels += off.Pixel(x, y)[3] > 0.01;
          if ((x + y) % 3 == 0)
          {
            const RayAccum ref = fixtures::BruteForce(m, s.tf, cam.Generate(x, y));
            if (s.isos.empty())
              ASSERT_NEAR(off.Pixel(x, y)[3], ref.Alpha(), 1e-6) << what << " pixel " << x << "," << y << " of " << cam.Width() << (cam.IsParallel() ? " parallel" : "");
          }
          for (int k = 0; k < 4; ++k)
            ASSERT_NEAR(on.Pixel(x, y)[k], off.Pixel(x, y)[k], 1e-6) << what << " pixel " << x << "," << y;
        }
    }
    EXPECT_GT(shownPixels, 500) << what;
    EXPECT_LT(crossedOn, crossedOff) << what;
  };
  for (int scheme : { 5, 6 })
  {
    const TetMesh m = fixtures::GridMesh(6, 6, 6, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, scheme);
    compare(m, shown, "grid");
    compare(m, iso, "grid with an iso-surface in a transparent range");
  }
  // Non-convex: the L-shape and the tunnel block, with either entry path for the mesh itself.
  // The tunnel is seen between grid lines: a ray exactly along its concave corner edges (solid in
  // three quadrants about it) leaves at the tunnel in the full walk and is integrated on in the
  // skipping one, as by the brute force (a known tie in the full walk, not a leak elsewhere).
  const TetMesh L = fixtures::GridMesh(6, 6, 6, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 6,
    [](int i, int j, int) { return !(i >= 3 && j >= 3); });
  const TetMesh T = fixtures::GridMesh(6, 5, 5, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 5,
    [](int i, int j, int k) { return !(j == 2 && k == 2 && i > 0 && i < 5); });
  for (bool grid : { true, false })
  {
    shown.boundaryGrid = grid;
    compare(L, shown, "L-shape");
    compare(T, shown, "tunnel", 0.125);
  }
}
