// Watertightness in the manner of Embree's verify: a closed, finely triangulated sphere far from the
// origin; rays from inside in random directions, and rays aimed exactly at its vertices and edge
// midpoints, must all leave through exactly one surface crossing. No leak, no double count.
#include "Accelerator.h"
#include "TriangleTestUtil.h"

#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>

#include <gtest/gtest.h>

TEST(TriangleGridWatertight, ClosedSphereFarFromOriginNoLeak)
{
  const art::Vec3 centre(1000.0, -2000.0, 500.0);
  const double radius = 1.0;
  vtkNew<vtkSphereSource> src;
  src->SetCenter(centre.x, centre.y, centre.z);
  src->SetRadius(radius);
  src->SetThetaResolution(160);
  src->SetPhiResolution(160);
  src->Update();
  auto store = std::make_shared<art::TriangleStore>(art::TriangleStore::FromPolyData(src->GetOutput()));
  ASSERT_GT(store->Size(), 50000u);
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  // Targets: random directions, and exactly the mesh's vertices and edge midpoints.
  std::vector<art::Ray> rays;
  for (int i = 0; i < 20000; ++i)
  {
    art::Ray r;
    r.org = centre + art::Vec3(u(g), u(g), u(g));
    r.dir = arttest::RandomUnit(g);
    rays.push_back(r);
  }
  for (size_t t = 0; t < store->Size(); t += 7)
  {
    for (int k = 0; k < 3; ++k)
    {
      art::Ray r;
      r.org = centre + art::Vec3(u(g), u(g), u(g)) * 0.1;
      const art::Vec3 a = store->Vertex(t, k), b = store->Vertex(t, (k + 1) % 3);
      r.dir = (k == 0 ? a : (a + b) * 0.5) - r.org;
      rays.push_back(r);
    }
  }
  for (const auto& o : arttest::AllKinds())
  {
    if (o.kind == art::AcceleratorKind::BruteForce)
    {
      continue; // 60k rays x 51k triangles: the grids are checked against it elsewhere
    }
    auto acc = art::MakeAccelerator(store, o);
    size_t leaks = 0, multiple = 0;
    std::vector<art::Hit> all;
    for (const art::Ray& r : rays)
    {
      art::Counters c;
      art::Hit h;
      if (!acc->Closest(r, h, c) || !acc->Any(r, c))
      {
        ++leaks;
        continue;
      }
      acc->All(r, all, c);
      multiple += all.size() != 1;
    }
    EXPECT_EQ(leaks, 0u) << acc->Name() << " of " << rays.size() << " rays";
    EXPECT_EQ(multiple, 0u) << acc->Name() << " of " << rays.size() << " rays";
  }
}
