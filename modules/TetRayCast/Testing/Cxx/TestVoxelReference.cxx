// The voxel reference caster: iso-surfaces, turned, sheared and moved volumes seen as their tets
// are, and non-finite voxels refused.
#include "Error.h"
#include "MeshFixtures.h"
#include "TetRayCaster.h"
#include "VoxelReferenceCaster.h"

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace art;
using fixtures::ViewOf;

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
