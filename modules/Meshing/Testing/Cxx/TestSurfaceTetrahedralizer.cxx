// Closed surfaces to tets (TetGen): a torus's mesh holds the torus's volume and nothing outside
// it; open and self-intersecting surfaces are refused with the count of what is wrong, before
// TetGen sees them; the VTK filter; the torus rendered through the non-convex (multi-entry) path
// against a brute-force reference.
#include "Error.h"
#include "MeshFixtures.h"
#include "SurfaceCheck.h"
#include "SurfaceTetrahedralizer.h"
#include "TetRayCaster.h"
#include "TorusFixture.h"
#include "vtkSurfaceTetrahedralizer.h"

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace
{
using fixtures::Torus;

std::string Refusal(art::TriangleSurface s, long long tets = 2000)
{
  art::SurfaceMeshOptions o;
  o.TargetTets = tets;
  try
  {
    art::TetrahedralizeSurface(std::move(s), o, "part.ply");
  }
  catch (const art::Error& e)
  {
    return e.what();
  }
  return "";
}

art::TriangleSurface Shifted(art::TriangleSurface s, double dx, double dy, double dz)
{
  for (size_t i = 0; i < s.Points.size(); i += 3)
  {
    s.Points[i] += dx, s.Points[i + 1] += dy, s.Points[i + 2] += dz;
  }
  return s;
}

art::TriangleSurface Union(const art::TriangleSurface& a, const art::TriangleSurface& b)
{
  art::TriangleSurface u = a;
  const int off = static_cast<int>(a.Points.size() / 3);
  u.Points.insert(u.Points.end(), b.Points.begin(), b.Points.end());
  for (auto t : b.Triangles)
  {
    u.Triangles.push_back({ t[0] + off, t[1] + off, t[2] + off });
  }
  return u;
}

vtkSmartPointer<vtkPolyData> PolyOf(const art::TriangleSurface& s)
{
  vtkNew<vtkPoints> pts;
  for (size_t i = 0; i < s.Points.size(); i += 3)
  {
    pts->InsertNextPoint(s.Points[i], s.Points[i + 1], s.Points[i + 2]);
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& t : s.Triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  auto p = vtkSmartPointer<vtkPolyData>::New();
  p->SetPoints(pts);
  p->SetPolys(polys);
  return p;
}

struct ErrorText : vtkCommand
{
  static ErrorText* New() { return new ErrorText; }
  void Execute(vtkObject*, unsigned long, void* data) override { Text += static_cast<const char*>(data); }
  std::string Text;
};

// Separate stretches of the ray inside the mesh (every tet clipped, the pieces merged).
int Pieces(const art::TetMesh& m, const art::Ray& r)
{
  std::vector<std::pair<double, double>> in;
  for (std::size_t t = 0; t < m.NumberOfTets(); ++t)
  {
    double t0 = r.tmin, t1 = std::min(r.tmax, 1e300);
    bool ok = true;
    for (int f = 0; f < 4 && ok; ++f)
    {
      const auto pl = m.FacePlane(t, f);
      const double dn = Dot(pl.n, r.dir), dist = pl.d - Dot(pl.n, r.org);
      if (dn == 0)
        ok = dist >= 0;
      else if (dn > 0)
        t1 = std::min(t1, dist / dn);
      else
        t0 = std::max(t0, dist / dn);
    }
    if (ok && t1 > t0 + 1e-12)
      in.emplace_back(t0, t1);
  }
  std::sort(in.begin(), in.end());
  int pieces = 0;
  double end = -1e300;
  for (const auto& [a, b] : in)
  {
    pieces += a > end + 1e-9 ? 1 : 0;
    end = std::max(end, b);
  }
  return pieces;
}
} // namespace

TEST(SurfaceTetrahedralizer, TorusVolumeWithinOnePercentAndEveryTetInside)
{
  const Torus torus{ 1.0, 0.4, 96, 40 }; // its flat facets hold 99.5% of the torus's volume
  art::SurfaceMeshOptions o;
  o.TargetTets = 40000;
  const art::SurfaceMeshResult r = art::TetrahedralizeSurface(torus.Surface(), o, "torus");
  const art::ReducedMesh& m = r.Mesh;
  ASSERT_GT(m.NumberOfTets(), 0);
  EXPECT_NEAR(r.MeshVolume, torus.Volume(), 0.01 * torus.Volume());
  // The tets fill the polygonal solid exactly (TetGen -p keeps the surface as the boundary).
  EXPECT_NEAR(r.MeshVolume, r.Surface.Volume, 1e-9 * r.Surface.Volume);
  EXPECT_GT(m.NumberOfTets(), 0.7 * o.TargetTets);
  EXPECT_LT(m.NumberOfTets(), 1.3 * o.TargetTets);
  long long outside = 0, inverted = 0;
  const double bound = torus.r + torus.Sag() + 1e-9;
  for (long long t = 0; t < m.NumberOfTets(); ++t)
  {
    const double* p[4];
    double c[3] = { 0, 0, 0 };
    for (int k = 0; k < 4; ++k)
    {
      p[k] = &m.Points[3 * static_cast<size_t>(m.Tets[4 * t + k])];
      outside += torus.TubeDistance(p[k]) > bound ? 1 : 0;
      for (int a = 0; a < 3; ++a)
      {
        c[a] += 0.25 * p[k][a];
      }
    }
    outside += torus.TubeDistance(c) > torus.r ? 1 : 0;
    double e[3][3];
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a)
        e[k][a] = p[k + 1][a] - p[0][a];
    const double six = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
      e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) + e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    inverted += six <= 0 ? 1 : 0;
  }
  EXPECT_EQ(outside, 0);
  EXPECT_EQ(inverted, 0);
}

TEST(SurfaceTetrahedralizer, OpenSurfacesAreRefusedWithTheirOpenEdges)
{
  const Torus torus{ 1.0, 0.4, 24, 12 };
  art::TriangleSurface one = torus.Surface();
  one.Triangles.erase(one.Triangles.begin() + 7);
  art::TriangleSurface check = one;
  EXPECT_EQ(art::CheckSurface(check).OpenEdges, 3);
  EXPECT_EQ(Refusal(one), "part.ply: is not a closed surface: 3 open edges (edges of only one triangle: it has "
                          "holes); tetrahedralize needs a closed, manifold surface (close it first, e.g. with "
                          "PyMeshFix or MeshLab)");
  // A quad (two triangles sharing an edge) removed: its four sides are open.
  art::TriangleSurface quad = torus.Surface();
  quad.Triangles.erase(quad.Triangles.begin() + 10, quad.Triangles.begin() + 12);
  EXPECT_NE(Refusal(quad).find("4 open edges"), std::string::npos) << Refusal(quad);
  // A fin: a third triangle on an edge is not manifold.
  art::TriangleSurface fin = torus.Surface();
  fin.Points.insert(fin.Points.end(), { 0.0, 0.0, 3.0 });
  fin.Triangles.push_back({ fin.Triangles[0][0], fin.Triangles[0][1], static_cast<int>(fin.Points.size() / 3 - 1) });
  EXPECT_NE(Refusal(fin).find("1 edge shared by three or more triangles"), std::string::npos) << Refusal(fin);
  EXPECT_NE(Refusal({}).find("part.ply: holds 0 triangles"), std::string::npos);
}

TEST(SurfaceTetrahedralizer, SelfIntersectingSurfacesAreRefused)
{
  const Torus torus{ 1.0, 0.4, 24, 12 };
  const art::TriangleSurface a = torus.Surface();
  // Two tori through each other: closed and manifold, but crossing.
  art::TriangleSurface crossing = Union(a, Shifted(a, 1.0, 0.0, 0.1));
  art::TriangleSurface check = crossing;
  const art::SurfaceReport rep = art::CheckSurface(check);
  EXPECT_TRUE(rep.Closed());
  EXPECT_GT(rep.Intersections, 0);
  EXPECT_NE(Refusal(crossing).find("part.ply: intersects itself: "), std::string::npos) << Refusal(crossing);
  // Apart, the same two are a valid surface (two solids), and mesh.
  art::TriangleSurface apart = Union(a, Shifted(a, 3.0, 0.0, 0.0));
  check = apart;
  EXPECT_TRUE(art::CheckSurface(check).Valid());
  EXPECT_EQ(Refusal(apart), "");
  // One vertex pushed through the tube's far side.
  art::TriangleSurface poked = a;
  poked.Points[2] = 0.9; // vertex 0 sits at (1.4, 0, 0): lift it through the top of the tube
  poked.Points[0] = 1.0;
  check = poked;
  EXPECT_GT(art::CheckSurface(check).Intersections, 0);
}

TEST(SurfaceTetrahedralizer, VTKFilterMeshesAndCarriesAVolumesValues)
{
  const Torus torus{ 1.0, 0.4, 64, 24 };
  const auto poly = PolyOf(torus.Surface());
  vtkNew<vtkSurfaceTetrahedralizer> f;
  f->SetInputData(poly);
  f->SetMaxVolume(0.002);
  f->Update();
  vtkUnstructuredGrid* g = f->GetOutput();
  ASSERT_GT(g->GetNumberOfCells(), 1000);
  EXPECT_EQ(g->GetCellType(0), VTK_TETRA);
  EXPECT_NEAR(f->GetMeshVolume(), f->GetSurfaceVolume(), 1e-6 * f->GetSurfaceVolume()); // float points
  EXPECT_NEAR(g->GetFieldData()->GetArray("mesh_volume")->GetTuple1(0), f->GetMeshVolume(), 1e-12);

  // A linear field in a volume around the torus: the least-squares fit reproduces it.
  vtkNew<vtkImageData> image;
  image->SetDimensions(60, 60, 20);
  image->SetOrigin(-1.5, -1.5, -0.5);
  image->SetSpacing(3.0 / 59, 3.0 / 59, 1.0 / 19);
  vtkNew<vtkDoubleArray> v;
  v->SetName("linear");
  v->SetNumberOfTuples(image->GetNumberOfPoints());
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    const double* p = image->GetPoint(i);
    v->SetValue(i, 10 + p[0] - 2 * p[1] + 3 * p[2]);
  }
  image->GetPointData()->SetScalars(v);
  vtkNew<vtkSurfaceTetrahedralizer> fv;
  fv->SetInputData(poly);
  fv->SetVolumeData(image);
  fv->SetTargetTets(6000);
  fv->Update();
  vtkUnstructuredGrid* gv = fv->GetOutput();
  vtkDataArray* s = gv->GetPointData()->GetScalars();
  ASSERT_NE(s, nullptr);
  EXPECT_STREQ(s->GetName(), "linear");
  double worst = 0;
  for (vtkIdType i = 0; i < gv->GetNumberOfPoints(); ++i)
  {
    const double* p = gv->GetPoint(i);
    worst = std::max(worst, std::fabs(s->GetTuple1(i) - (10 + p[0] - 2 * p[1] + 3 * p[2])));
  }
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(fv->GetRMSError(), 1e-5);
  EXPECT_GT(gv->GetFieldData()->GetArray("covered_voxels")->GetTuple1(0), 1000);

  // An open surface: the filter reports the error with the count, and makes nothing.
  art::TriangleSurface open = torus.Surface();
  open.Triangles.pop_back();
  vtkNew<vtkSurfaceTetrahedralizer> fo;
  vtkNew<ErrorText> err;
  fo->AddObserver(vtkCommand::ErrorEvent, err);
  fo->SetInputData(PolyOf(open));
  fo->SetTargetTets(100);
  fo->Update();
  EXPECT_NE(err->Text.find("3 open edges"), std::string::npos) << err->Text;
  EXPECT_EQ(fo->GetOutput()->GetNumberOfCells(), 0);
}

TEST(SurfaceTetrahedralizer, TorusRendersThroughTheMultiEntryPathWithoutCracks)
{
  const Torus torus{ 1.0, 0.4, 48, 16 };
  art::SurfaceMeshOptions o;
  o.MaxVolume = 0.01;
  const art::ReducedMesh m = art::TetrahedralizeSurface(torus.Surface(), o, "torus").Mesh;
  std::vector<art::Vec3> pts;
  std::vector<double> val;
  for (long long v = 0; v < m.NumberOfVertices(); ++v)
  {
    const art::Vec3 p(m.Points[3 * v], m.Points[3 * v + 1], m.Points[3 * v + 2]);
    pts.push_back(p);
    val.push_back(fixtures::Linear(p));
  }
  std::vector<std::array<int, 4>> tets;
  for (long long t = 0; t < m.NumberOfTets(); ++t)
  {
    tets.push_back({ m.Tets[4 * t], m.Tets[4 * t + 1], m.Tets[4 * t + 2], m.Tets[4 * t + 3] });
  }
  const art::TetMesh mesh(std::move(pts), std::move(val), std::move(tets));
  ASSERT_FALSE(mesh.IsConvex());
  for (bool grid : { true, false })
  {
    art::RenderSettings s;
    s.tf = fixtures::LinearTF(-0.2, 0.8);
    s.earlyTermination = 2.0;
    s.boundaryGrid = grid;
    const art::TetRayCaster rc(mesh, s);
    vtkNew<vtkCamera> view; // from the front and above: rays cross the near tube, the hole, the far tube
    view->SetPosition(0.3, -4.0, 1.0);
    view->SetFocalPoint(0, 0, 0);
    view->SetViewUp(0, 0, 1);
    view->SetViewAngle(40);
    const art::Camera cam = art::Camera::FromVTK(view, 48, 36);
    art::Image img;
    rc.Render(cam, img);
    int cracked = 0, covered = 0, twice = 0;
    for (int y = 0; y < 36; ++y)
      for (int x = 0; x < 48; ++x)
      {
        const art::Ray ray = cam.Generate(x, y);
        const art::RayAccum ref = fixtures::BruteForce(mesh, s.tf, ray);
        const float* px = img.Pixel(x, y);
        bool same = std::fabs(px[3] - ref.Alpha()) < 1e-5;
        for (int k = 0; k < 3; ++k)
          same = same && std::fabs(px[k] - ref.rgb[k]) < 1e-5;
        cracked += same ? 0 : 1;
        covered += ref.Alpha() > 0 ? 1 : 0;
        twice += Pieces(mesh, ray) >= 2 ? 1 : 0;
      }
    EXPECT_EQ(cracked, 0) << (grid ? "boundary grid" : "screen buckets");
    EXPECT_GT(covered, 48 * 36 / 5);
    EXPECT_GT(twice, 40) << "rays that enter the torus twice";
  }
}
