// The caster's new paths against their plain forms: the SIMD projected walk against the portable
// one from a camera inside the mesh (perspective: the projected view refuses it and both walk in
// 3-D; parallel: rays start in a tet, then walk projected), and the entry finder's 4 x 4 pixel
// buckets on rays that diverge (some miss, some enter once, some leave and re-enter a non-convex
// mesh, the eye inside) against the finder without buckets, which tests every boundary face.
#include "EntryFinder.h"
#include "MeshFixtures.h"
#include "ProjectedWalker.h"
#include "TetRayCaster.h"
#include "TetWalker.h"

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkNew.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

using namespace art;

namespace
{
using fixtures::Wavy;

Camera Look(const Vec3& eye, const Vec3& focal, int w, int h, bool parallel, double scale = 1.2)
{
  vtkNew<vtkCamera> cam;
  cam->SetPosition(eye.x, eye.y, eye.z);
  cam->SetFocalPoint(focal.x, focal.y, focal.z);
  cam->SetViewUp(0, 0, 1);
  cam->SetParallelProjection(parallel);
  cam->SetParallelScale(scale);
  return Camera::FromVTK(cam, w, h);
}

RenderSettings Settings(bool projected, bool simd)
{
  RenderSettings s;
  s.tf = TransferFunction({ { 0, { 0, 0, 1 }, 0.05, 0 }, { 0.4, { 0, 1, 0 }, 0.3, 0 }, { 0.5, { 1, 1, 0 }, 0.02, 0 },
                            { 1, { 1, 0, 0 }, 0.5, 0 } },
    0.7);
  s.earlyTermination = 2.0;
  s.projectedWalk = projected;
  s.simdWalk = simd;
  return s;
}

double WorstDifference(const Image& a, const Image& b)
{
  double worst = 0;
  for (int y = 0; y < a.Height(); ++y)
    for (int x = 0; x < a.Width(); ++x)
      for (int k = 0; k < 4; ++k)
        worst = std::max(worst, double(std::fabs(a.Pixel(x, y)[k] - b.Pixel(x, y)[k])));
  return worst;
}

struct View
{
  Vec3 eye, focal;
  bool parallel;
};
} // namespace

TEST(SimdWalk, SameBitsFromACameraInsideTheMesh)
{
  if (!SimdWalkAvailable())
  {
    GTEST_SKIP() << "this CPU has no AVX2";
  }
  const TetMesh m = fixtures::GridMesh(5, 5, 5, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 6, {},
    [](const Vec3& p) { return Vec3(p.x + 0.1 * std::sin(5 * p.y), p.y + 0.1 * std::cos(4 * p.z), p.z); });
  int projected = 0;
  for (const View& v : { View{ { 1.1, 0.9, 0.7 }, { 1.6, 1.4, 2.0 }, false }, View{ { 1.3, 1.2, 1.4 }, { 0, 2.3, 2 }, false },
         View{ { 1.1, 0.9, 0.7 }, { 1.6, 1.4, 2.0 }, true }, View{ { 0.9, 1.3, 1.1 }, { 2.2, 0.1, 1.4 }, true } })
  {
    const Camera cam = Look(v.eye, v.focal, 33, 27, v.parallel);
    const bool valid = ProjectedView(m, cam).Valid();
    EXPECT_EQ(valid, v.parallel) << "a perspective eye inside has vertices behind it";
    projected += valid ? 1 : 0;
    Image simd, portable, walk3d;
    const RenderStats a = TetRayCaster(m, Settings(true, true)).Render(cam, simd);
    const RenderStats b = TetRayCaster(m, Settings(true, false)).Render(cam, portable);
    TetRayCaster(m, Settings(false, false)).Render(cam, walk3d);
    EXPECT_GT(a.counters.tetsCrossed, 1000u);
    EXPECT_EQ(a.counters.tetsCrossed, b.counters.tetsCrossed);
    EXPECT_EQ(WorstDifference(simd, portable), 0.0) << "SIMD and portable walks give the same bits";
    EXPECT_LE(WorstDifference(simd, walk3d), 1e-6) << "the projected walk agrees with the 3-D walker";
  }
  EXPECT_EQ(projected, 2);
}

TEST(EntryBuckets, DivergingRaysOfABucketFindEveryEntry)
{
  // An L (non-convex: rays leave through the notch and re-enter) and a warped box; views from
  // outside, across the notch, and from inside (faces behind the eye are tested by every ray).
  const TetMesh ell = fixtures::GridMesh(4, 4, 2, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 6,
    [](int i, int j, int) { return !(i >= 2 && j >= 2); });
  const TetMesh box = fixtures::GridMesh(4, 4, 4, { 0, 0, 0 }, { 0.5, 0.5, 0.5 }, Wavy, 5, {},
    [](const Vec3& p) { return Vec3(p.x + 0.15 * std::sin(4 * p.z), p.y, p.z + 0.1 * std::cos(5 * p.x)); });
  int diverging = 0, reentering = 0, rays = 0;
  for (const TetMesh* m : { &ell, &box })
  {
    const Vec3 c = m->Bounds().Center();
    for (const View& v : { View{ c + Vec3(3.1, 2.7, 1.3), c, false }, View{ c + Vec3(2.9, 3.2, 0.4), c, true },
           View{ { 1.9, 1.8, 0.5 }, { 0.2, 0.3, 0.5 }, false }, View{ c + Vec3(0.1, 0.05, 0.02), c + Vec3(1, 0.4, 0.3), false } })
    {
      const Camera cam = Look(v.eye, v.focal, 37, 29, v.parallel, 1.6); // partial buckets at the edges
      const EntryFinder bucketed(*m, cam), flat(*m);
      std::map<std::pair<int, int>, std::pair<int, int>> perBucket; // fewest, most entries
      for (int y = 0; y < cam.Height(); ++y)
        for (int x = 0; x < cam.Width(); ++x)
        {
          const Ray r = cam.Generate(x, y);
          const TetWalker w(*m, r);
          std::vector<Entry> a, b;
          int ha = -1, hb = -1;
          Counters ca, cb;
          bucketed.Find(w, r, x, y, true, a, ha, ca);
          flat.Find(w, r, x, y, true, b, hb, cb);
          EntryCursor cur;
          bucketed.Start(cur, w, r, x, y, ca);
          std::vector<Entry> pulled;
          for (const Entry* e = cur.Front(); e; e = cur.Front())
          {
            pulled.push_back(*e);
            cur.Pop();
          }
          ++rays;
          // A ray along an edge of two boundary faces enters both at one t, in either order.
          for (std::vector<Entry>* l : { &a, &b, &pulled })
          {
            std::stable_sort(l->begin(), l->end(), [](const Entry& p, const Entry& q) {
              return p.x.t < q.x.t || (p.x.t == q.x.t && p.face < q.face);
            });
          }
          ASSERT_EQ(a.size(), b.size()) << "pixel " << x << "," << y;
          ASSERT_EQ(pulled.size(), b.size()) << "pixel " << x << "," << y;
          for (std::size_t i = 0; i < b.size(); ++i)
          {
            EXPECT_EQ(a[i].face, b[i].face);
            EXPECT_EQ(pulled[i].face, b[i].face);
            EXPECT_LE(std::fabs(a[i].x.t - b[i].x.t), 1e-12 * (1 + std::fabs(b[i].x.t)));
            EXPECT_LE(std::fabs(pulled[i].x.t - b[i].x.t), 1e-12 * (1 + std::fabs(b[i].x.t)));
          }
          reentering += b.size() > 1 ? 1 : 0;
          auto& mm = perBucket.try_emplace({ x / 4, y / 4 }, int(b.size()), int(b.size())).first->second;
          mm.first = std::min(mm.first, int(b.size())), mm.second = std::max(mm.second, int(b.size()));
        }
      for (const auto& kv : perBucket)
      {
        diverging += kv.second.first != kv.second.second ? 1 : 0;
      }
    }
  }
  EXPECT_GT(rays, 8000);
  EXPECT_GT(diverging, 50) << "buckets whose rays find different numbers of entries";
  EXPECT_GT(reentering, 40) << "rays that leave the L and re-enter";
}
