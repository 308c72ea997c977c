// The projected walker against the 3-D TetWalker on a camera's own rays: the same crossings (exit
// t, scalar integral and maximum to 1e-9) on rays exactly through vertices, along edges and in
// faces, on slivers and on non-convex meshes, for perspective and parallel cameras; the fallback
// to the 3-D walker when vertices lie behind the eye; and images rendered both ways.
#include "EntryFinder.h"
#include "MeshFixtures.h"
#include "ProjectedWalker.h"
#include "TetRayCaster.h"

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkNew.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace art;

namespace
{
using fixtures::Wavy;

struct Path
{
  std::vector<int> tets;
  double tEnd = 0, integral = 0, maxS = -1e300;
};

template <class W>
Path Follow(const TetMesh& m, const W& w, const Entry& e)
{
  Path p;
  FaceCrossing out;
  std::uint64_t steps = 0, nudges = 0;
  const auto& bf = m.BoundaryFaces()[e.face];
  w.Walk(bf[0], bf[1], e.x,
    [&](int t, const FaceCrossing& a, const FaceCrossing& b) {
      p.tets.push_back(t);
      p.integral += 0.5 * (b.t - a.t) * (a.s + b.s);
      p.maxS = std::max(p.maxS, std::max(a.s, b.s));
      return true;
    },
    out, steps, nudges);
  p.tEnd = out.t;
  return p;
}

// Every crossing of one piece, walked by WalkFacesWith<Speculate> (the walk's two loop forms).
template <bool Speculate, class W>
std::vector<double> Crossings(const TetMesh& m, const W& w, const Entry& e)
{
  std::vector<double> x;
  FaceCrossing out;
  std::uint64_t steps = 0, nudges = 0;
  const auto& bf = m.BoundaryFaces()[e.face];
  WalkFacesWith<Speculate>(m, w, bf[0], bf[1], e.x,
    [&](int t, const FaceCrossing& a, const FaceCrossing& b) {
      x.insert(x.end(), { double(t), a.t, a.s, b.t, b.s });
      return true;
    },
    out, steps, nudges, m.Records());
  x.insert(x.end(), { out.t, out.s, double(nudges) });
  return x;
}

struct Tally
{
  int rays = 0, pieces = 0, sameTets = 0;
};

// Every pixel of cam: both walkers from every entry; returns how many paths visit the same tets.
Tally Compare(const TetMesh& m, const Camera& cam, const char* what)
{
  const ProjectedView view(m, cam);
  EXPECT_TRUE(view.Valid()) << what;
  const EntryFinder finder(m, cam);
  Tally n;
  std::vector<Entry> entries;
  int hint = -1;
  Counters c;
  for (int y = 0; y < cam.Height(); ++y)
    for (int x = 0; x < cam.Width(); ++x)
    {
      const Ray r = cam.Generate(x, y);
      EXPECT_TRUE(view.Fits(r));
      const TetWalker w(m, r);
      const ProjectedWalker pw(view, r);
      finder.Find(w, r, x, y, !m.IsConvex(), entries, hint, c);
      ++n.rays;
      for (const Entry& e : entries)
      {
        const Path a = Follow(m, w, e), b = Follow(m, pw, e);
        ++n.pieces;
        // The jump and lookup forms of the loop give the same bits, for both walkers.
        EXPECT_EQ(Crossings<true>(m, w, e), Crossings<false>(m, w, e)) << what << " pixel " << x << "," << y;
        EXPECT_EQ(Crossings<true>(m, pw, e), Crossings<false>(m, pw, e)) << what << " pixel " << x << "," << y;
        n.sameTets += a.tets == b.tets ? 1 : 0;
        const bool same = std::fabs(a.tEnd - b.tEnd) <= 1e-9 * (1 + std::fabs(a.tEnd)) &&
          std::fabs(a.integral - b.integral) <= 1e-9 && std::fabs(a.maxS - b.maxS) <= 1e-9;
        if (!same)
        {
          ADD_FAILURE() << what << " pixel " << x << "," << y << ": t " << a.tEnd << " vs " << b.tEnd
                        << ", integral " << a.integral << " vs " << b.integral << ", max " << a.maxS
                        << " vs " << b.maxS;
          return n; // one report per view
        }
      }
    }
  if (getenv("ART_VERBOSE"))
    std::printf("%-30s rays %d pieces %d same tets %d\n", what, n.rays, n.pieces, n.sameTets);
  return n;
}

// A camera at eye looking at focal; parallel ones with the given parallel scale.
Camera Look(const Vec3& eye, const Vec3& focal, const Vec3& up, int w, int h, bool parallel, double scale = 1)
{
  vtkNew<vtkCamera> cam;
  cam->SetPosition(eye.x, eye.y, eye.z);
  cam->SetFocalPoint(focal.x, focal.y, focal.z);
  cam->SetViewUp(up.x, up.y, up.z);
  cam->SetParallelProjection(parallel);
  cam->SetParallelScale(scale);
  return Camera::FromVTK(cam, w, h);
}

RenderSettings Settings(bool projected)
{
  RenderSettings s;
  s.tf = TransferFunction({ { 0, { 0, 0, 1 }, 0.05, 0 }, { 0.4, { 0, 1, 0 }, 0.3, 0 }, { 0.5, { 1, 1, 0 }, 0.02, 0 },
                            { 1, { 1, 0, 0 }, 0.5, 0 } },
    0.7);
  s.earlyTermination = 2.0;
  s.projectedWalk = projected;
  return s;
}

// Renders with both walkers: the images agree to float precision.
void ExpectSameImage(const TetMesh& m, const Camera& cam, const char* what)
{
  Image a, b;
  const RenderStats sa = TetRayCaster(m, Settings(false)).Render(cam, a);
  const RenderStats sb = TetRayCaster(m, Settings(true)).Render(cam, b);
  EXPECT_GT(sa.counters.tetsCrossed, 0u) << what;
  double worst = 0;
  for (int y = 0; y < cam.Height(); ++y)
    for (int x = 0; x < cam.Width(); ++x)
      for (int k = 0; k < 4; ++k)
        worst = std::max(worst, double(std::fabs(a.Pixel(x, y)[k] - b.Pixel(x, y)[k])));
  EXPECT_LE(worst, 1e-6) << what;
}
} // namespace

TEST(ProjectedWalker, SameCrossingsThroughVerticesEdgesAndFaces)
{
  for (int scheme : { 5, 6 })
  {
    const TetMesh m = fixtures::GridMesh(4, 4, 4, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, scheme);
    // Perspective from a point on the grid line x = y = 1: the centre pixel's ray runs along the
    // line's edges through its vertices; the odd image keeps the rays symmetric about it, so
    // others run in the grid's diagonal planes.
    const Camera line = Look({ 1, 1, -3 }, { 1, 1, 0 }, { 0, 1, 0 }, 21, 21, false);
    Tally t = Compare(m, line, "perspective on a grid line");
    EXPECT_EQ(t.rays, 21 * 21);
    EXPECT_EQ(t.pieces, 21 * 21);
    EXPECT_EQ(t.sameTets, t.pieces);
    // Along the face diagonal from a corner of the grid, and obliquely from above.
    t = Compare(m, Look({ -2, -2, 1 }, { 1, 1, 1 }, { 0, 0, 1 }, 25, 19, false), "perspective along a diagonal");
    EXPECT_GT(t.pieces, 400);
    EXPECT_EQ(t.sameTets, t.pieces);
    t = Compare(m, Look({ 3.1, -1.7, 4.2 }, { 1, 1, 1 }, { 0, 0, 1 }, 30, 24, false), "perspective oblique");
    EXPECT_EQ(t.sameTets, t.pieces);
    // Parallel along z with pixel centres on the grid lines (9 pixels over 2.25 units): rays in
    // edges and faces everywhere; along the cube diagonal, where the centre column of rays lies
    // in the faces of Kuhn's tets (their 2-D products are rounding noise: the 3-D ones decide).
    t = Compare(m, Look({ 1, 1, -3 }, { 1, 1, 0 }, { 0, 1, 0 }, 9, 9, true, 1.125), "parallel on grid lines");
    EXPECT_EQ(t.pieces, 9 * 9);
    EXPECT_EQ(t.sameTets, t.pieces);
    const Camera diag = Look({ -2, -2, -2 }, { 1, 1, 1 }, { 0, 0, 1 }, 23, 17, true, 1.6);
    t = Compare(m, diag, "parallel diagonal");
    EXPECT_GT(t.pieces, 150);
    EXPECT_EQ(t.sameTets, t.pieces);
    // The projected images against the brute-force reference, every pixel.
    for (const Camera* c : { &line, &diag })
    {
      const TetRayCaster rc(m, Settings(true));
      Image img;
      rc.Render(*c, img);
      int bad = 0;
      for (int y = 0; y < c->Height(); ++y)
        for (int x = 0; x < c->Width(); ++x)
        {
          const RayAccum ref = fixtures::BruteForce(m, rc.Settings().tf, c->Generate(x, y));
          double e = std::fabs(img.Pixel(x, y)[3] - ref.Alpha());
          for (int k = 0; k < 3; ++k)
            e = std::max(e, std::fabs(img.Pixel(x, y)[k] - ref.rgb[k]));
          bad += e > 1e-6 ? 1 : 0;
        }
      EXPECT_EQ(bad, 0) << "scheme " << scheme;
    }
  }
}

TEST(ProjectedWalker, SameCrossingsOnSliversAndNonConvexMeshes)
{
  const TetMesh s = fixtures::SliverMesh(); // needles and slivers everywhere
  Tally t = Compare(s, Look({ 1.2, 1.1, -4 }, { 1.2, 1.2, 1 }, { 0, 1, 0 }, 31, 29, false), "slivers perspective");
  EXPECT_EQ(t.sameTets, t.pieces);
  // Grazing the squashed layer.
  t = Compare(s, Look({ -3, 1.1, 1.0 + 5e-8 }, { 1, 1.2, 1.0 + 5e-8 }, { 0, 0, 1 }, 21, 21, false), "slivers grazing");
  EXPECT_EQ(t.sameTets, t.pieces);
  t = Compare(s, Look({ -3, 1.1, 1.0 }, { 1, 1.1, 1.0 }, { 0, 0, 1 }, 21, 21, true, 1.5), "slivers parallel");
  EXPECT_GT(t.pieces, 150);
  EXPECT_EQ(t.sameTets, t.pieces);
  ExpectSameImage(s, Look({ 3, -2, 4 }, { 1.2, 1.2, 0.7 }, { 0, 0, 1 }, 40, 30, false), "slivers image");

  const TetMesh L = fixtures::GridMesh(4, 4, 2, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 6,
    [](int i, int j, int) { return !(i >= 2 && j >= 2); });
  ASSERT_FALSE(L.IsConvex());
  t = Compare(L, Look({ 3.5, -2, 0.5 }, { 0, 1.5, 0.5 }, { 0, 0, 1 }, 31, 21, false), "L-shape perspective");
  EXPECT_GT(t.pieces, t.rays / 2);
  EXPECT_EQ(t.sameTets, t.pieces);
  t = Compare(L, Look({ 3, 3, 0.5 }, { 0, 0, 0.5 }, { 0, 0, 1 }, 25, 15, true, 1.5), "L-shape parallel");
  EXPECT_EQ(t.sameTets, t.pieces);
  ExpectSameImage(L, Look({ -1, -3, 2 }, { 1, 1, 0.5 }, { 0, 0, 1 }, 40, 30, false), "L-shape image");
}

TEST(ProjectedWalker, FallsBackWhenVerticesAreBehindTheEye)
{
  const TetMesh m = fixtures::GridMesh(4, 4, 4, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 5);
  // Eye inside the mesh, eye on the mesh's bounding plane, eye just outside with the nearest
  // vertices a hair in front: no projected view; the image still matches the 3-D walker's and
  // the brute-force reference.
  const Camera inside = Look({ 0.9, 1.1, 0.8 }, { 1.5, 1.6, 1.9 }, { 0, 0, 1 }, 32, 24, false);
  const Camera onPlane = Look({ 1, 1, 0 }, { 1, 1, 1 }, { 0, 1, 0 }, 32, 24, false);
  const Camera close = Look({ 1, 1, -1e-9 }, { 1, 1, 1 }, { 0, 1, 0 }, 32, 24, false);
  for (const Camera* c : { &inside, &onPlane, &close })
  {
    EXPECT_FALSE(ProjectedView(m, *c).Valid());
    ExpectSameImage(m, *c, "fallback");
  }
  Image img;
  const TetRayCaster rc(m, Settings(true));
  rc.Render(inside, img);
  for (int y = 0; y < 24; y += 3)
    for (int x = 0; x < 32; x += 3)
    {
      Ray r = inside.Generate(x, y);
      const RayAccum ref = fixtures::BruteForce(m, rc.Settings().tf, r);
      EXPECT_NEAR(img.Pixel(x, y)[3], ref.Alpha(), 1e-6) << x << "," << y;
      EXPECT_NEAR(img.Pixel(x, y)[0], ref.rgb[0], 1e-6) << x << "," << y;
    }
  // A view that is valid still refuses rays that are not the camera's own.
  const Camera out = Look({ 1, 1, -3 }, { 1, 1, 0 }, { 0, 1, 0 }, 8, 8, false);
  const ProjectedView v(m, out);
  ASSERT_TRUE(v.Valid());
  Ray r = out.Generate(3, 4);
  EXPECT_TRUE(v.Fits(r));
  r.org.x += 1e-12;
  EXPECT_FALSE(v.Fits(r));
  const Camera par = Look({ 1, 1, -3 }, { 1, 1, 0 }, { 0, 1, 0 }, 8, 8, true);
  const ProjectedView vp(m, par);
  Ray rp = par.Generate(3, 4);
  EXPECT_TRUE(vp.Fits(rp));
  rp.dir.y += 1e-12;
  EXPECT_FALSE(vp.Fits(rp));
}

TEST(ProjectedWalker, ParallelRaysStartingInsideTheMesh)
{
  // The image plane cuts the mesh: rays start in a tet (3-D start test), then walk projected.
  const TetMesh m = fixtures::GridMesh(4, 4, 4, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 6);
  const Camera cam = Look({ 1.1, 0.9, 0.7 }, { 1.6, 1.4, 2.0 }, { 0, 0, 1 }, 36, 28, true, 1.2);
  EXPECT_TRUE(ProjectedView(m, cam).Valid());
  ExpectSameImage(m, cam, "parallel inside");
}

// The SIMD form of the projected walk against the portable one: the same image bit for bit and
// the same tets crossed and fallback exits, on random rays (random cameras, perspective and
// parallel, some along the grid's lines) through random meshes (jittered grids, slivers, an L).
TEST(ProjectedWalker, SimdWalkGivesThePortableWalksBits)
{
  if (!SimdWalkAvailable())
  {
    GTEST_SKIP() << "this CPU has no AVX2";
  }
  std::uint64_t seed = 12345;
  auto uniform = [&](double lo, double hi) {
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * double(seed >> 11) / double(1ULL << 53);
  };
  std::vector<TetMesh> meshes;
  for (int k = 0; k < 3; ++k)
  {
    const double a = uniform(0.0, 0.2), b = uniform(0.0, 0.2);
    meshes.push_back(fixtures::GridMesh(5, 4, 4, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, k == 1 ? 6 : 5, {},
      [a, b](const Vec3& p) { return Vec3(p.x + a * std::sin(5 * p.y), p.y + b * std::cos(4 * p.z), p.z); }));
  }
  meshes.push_back(fixtures::GridMesh(4, 4, 4, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 6));
  meshes.push_back(fixtures::SliverMesh());
  meshes.push_back(fixtures::GridMesh(4, 4, 2, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 6,
    [](int i, int j, int) { return !(i >= 2 && j >= 2); }));
  int views = 0, differing = 0;
  std::uint64_t crossed = 0, nudged = 0;
  for (const TetMesh& m : meshes)
  {
    const Vec3 c = m.Bounds().Center();
    for (int v = 0; v < 6; ++v)
    {
      const bool parallel = v % 2 == 1 || v == 2;
      // Views 0 and 1 look along a grid line from a lattice point; the others from anywhere.
      // View 2 along the cube diagonal, where rays lie in the faces of Kuhn's tets.
      const Vec3 eye = v < 2 ? Vec3(1, 1, -3)
                             : (v == 2 ? Vec3(-2, -2, -2) : c + Vec3(uniform(-4, 4), uniform(-4, 4), uniform(-4, 4)));
      const Vec3 focal = v < 2 ? Vec3(1, 1, 0)
                               : (v == 2 ? Vec3(1, 1, 1) : c + Vec3(uniform(-0.3, 0.3), uniform(-0.3, 0.3), uniform(-0.3, 0.3)));
      const Vec3 up = std::fabs(Normalize(focal - eye).z) > 0.9 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
      const Camera cam = Look(eye, focal, up, 31, 23, parallel, 1.6);
      if (!ProjectedView(m, cam).Valid())
      {
        continue;
      }
      RenderSettings s = Settings(true);
      Image a, b;
      s.simdWalk = true;
      const RenderStats sa = TetRayCaster(m, s).Render(cam, a);
      s.simdWalk = false;
      const RenderStats sb = TetRayCaster(m, s).Render(cam, b);
      ++views;
      crossed += sa.counters.tetsCrossed;
      nudged += sa.nudges;
      EXPECT_EQ(sa.counters.tetsCrossed, sb.counters.tetsCrossed);
      EXPECT_EQ(sa.nudges, sb.nudges);
      for (int y = 0; y < cam.Height(); ++y)
        for (int x = 0; x < cam.Width(); ++x)
          for (int k = 0; k < 4; ++k)
            differing += a.Pixel(x, y)[k] != b.Pixel(x, y)[k] ? 1 : 0;
    }
  }
  EXPECT_GE(views, 25);
  EXPECT_GT(crossed, 100000u);
  EXPECT_GT(nudged, 0u) << "rays in the faces of Kuhn's tets take the fallback exit";
  EXPECT_EQ(differing, 0);
}
