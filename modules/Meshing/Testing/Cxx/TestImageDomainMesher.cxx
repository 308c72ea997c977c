// Regions and label maps meshed by CGAL's Mesh_3 through vtkAdaptiveTetReducer: a sphere of 1 in
// a box of 0 cut at 0.5 gives the sphere's volume and boundary points on it; two touching
// labelled cubes give one conforming mesh whose interface faces both labels share exactly.
#include "vtkAdaptiveTetReducer.h"
#include "vtkImageDomainMesher.h"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <set>

namespace
{
using Face = std::array<vtkIdType, 3>;

vtkSmartPointer<vtkImageData> Image(int n, const std::function<int(int, int, int)>& value)
{
  auto im = vtkSmartPointer<vtkImageData>::New();
  im->SetDimensions(n, n, n);
  vtkNew<vtkUnsignedCharArray> a;
  a->SetName("v");
  a->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        a->SetValue(i + n * (j + n * k), static_cast<unsigned char>(value(i, j, k)));
  im->GetPointData()->SetScalars(a);
  return im;
}

double TetVolume(vtkUnstructuredGrid* g, vtkIdType c)
{
  double p[4][3];
  for (int k = 0; k < 4; ++k)
    g->GetPoint(g->GetCell(c)->GetPointId(k), p[k]);
  double e[3][3];
  for (int k = 0; k < 3; ++k)
    for (int a = 0; a < 3; ++a)
      e[k][a] = p[k + 1][a] - p[0][a];
  return (e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) /
    6.0;
}

// Each face of the grid's tets and the cells that hold it.
std::map<Face, std::vector<vtkIdType>> Faces(vtkUnstructuredGrid* g)
{
  std::map<Face, std::vector<vtkIdType>> faces;
  static const int F[4][3] = { { 1, 2, 3 }, { 0, 3, 2 }, { 0, 1, 3 }, { 0, 2, 1 } };
  for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c)
  {
    vtkIdList* ids = g->GetCell(c)->GetPointIds();
    for (const auto& f : F)
    {
      Face key = { ids->GetId(f[0]), ids->GetId(f[1]), ids->GetId(f[2]) };
      std::sort(key.begin(), key.end());
      faces[key].push_back(c);
    }
  }
  return faces;
}
} // namespace

TEST(ImageDomainMesher, FactoryGivesCGAL)
{
  vtkNew<vtkImageDomainMesher> m;
  EXPECT_TRUE(m->IsAvailable());
  EXPECT_STREQ(m->GetClassName(), "vtkCGALImageDomainMesher");
}

TEST(ImageDomainMesher, SphereRegionHasTheSpheresVolumeAndBoundary)
{
  const int n = 40;
  const double c = (n - 1) / 2.0, R = 12.0;
  const auto image = Image(n, [&](int i, int j, int k) {
    return (i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c) <= R * R ? 1 : 0;
  });
  vtkNew<vtkAdaptiveTetReducer> red;
  red->SetInputData(image);
  red->SetRegion(0.5, 1.0);
  red->SetTargetTets(4000);
  red->Update();
  vtkUnstructuredGrid* g = red->GetOutput();
  ASSERT_GT(g->GetNumberOfCells(), 1000);
  double volume = 0;
  for (vtkIdType t = 0; t < g->GetNumberOfCells(); ++t)
  {
    const double v = TetVolume(g, t);
    ASSERT_GT(v, 0) << "tet " << t;
    volume += v;
  }
  const double sphere = 4.0 / 3.0 * M_PI * R * R * R;
  EXPECT_NEAR(volume, sphere, 0.02 * sphere);
  // The boundary's points lie on the sphere, within the half voxel a 0/1 image leaves it.
  int boundary = 0;
  double worst = 0;
  std::set<vtkIdType> seen;
  for (const auto& [f, cells] : Faces(g))
  {
    ASSERT_LE(cells.size(), 2u) << "a face of three tets";
    if (cells.size() != 1)
      continue;
    for (vtkIdType p : f)
    {
      if (!seen.insert(p).second)
        continue;
      const double* x = g->GetPoint(p);
      worst = std::max(worst, std::fabs(std::sqrt((x[0] - c) * (x[0] - c) + (x[1] - c) * (x[1] - c) +
                                          (x[2] - c) * (x[2] - c)) - R));
      ++boundary;
    }
  }
  EXPECT_GT(boundary, 200);
  EXPECT_LT(worst, 0.75);
  EXPECT_EQ(red->GetRegionVoxels(), static_cast<vtkIdType>(g->GetFieldData()->GetArray("region_voxels")->GetTuple1(0)));
  EXPECT_LT(red->GetRMSError(), 1e-9); // the field is 1 everywhere inside
}

TEST(ImageDomainMesher, TouchingLabelledCubesShareTheirInterfaceFaces)
{
  // Label 1 in z voxels 4..11, label 2 in 12..19: the interface is the plane z = 11.5.
  const auto image = Image(24, [](int i, int j, int k) {
    if (i < 4 || i > 19 || j < 4 || j > 19 || k < 4 || k > 19)
      return 0;
    return k < 12 ? 1 : 2;
  });
  vtkNew<vtkAdaptiveTetReducer> red;
  red->SetInputData(image);
  red->SetLabels(true);
  red->SetTargetTets(3000);
  red->Update();
  vtkUnstructuredGrid* g = red->GetOutput();
  ASSERT_GT(g->GetNumberOfCells(), 500);
  vtkDataArray* label = g->GetCellData()->GetArray("label");
  ASSERT_NE(label, nullptr);
  std::map<int, int> perLabel;
  for (vtkIdType t = 0; t < g->GetNumberOfCells(); ++t)
    ++perLabel[static_cast<int>(label->GetTuple1(t))];
  ASSERT_EQ(perLabel.size(), 2u);
  EXPECT_GT(perLabel[1], 100);
  EXPECT_GT(perLabel[2], 100);
  // The boundary of each label's tets, less the mesh's outer boundary: the same faces for both.
  std::set<Face> of[3];
  double area = 0, offPlane = 0;
  for (const auto& [f, cells] : Faces(g))
  {
    ASSERT_LE(cells.size(), 2u);
    if (cells.size() != 2)
      continue;
    const int a = static_cast<int>(label->GetTuple1(cells[0])), b = static_cast<int>(label->GetTuple1(cells[1]));
    if (a == b)
      continue;
    of[a].insert(f);
    of[b].insert(f);
    double p[3][3];
    for (int k = 0; k < 3; ++k)
      g->GetPoint(f[k], p[k]);
    // Away from the rim, where the smoothed outer surface rounds the interface's edge.
    for (int k = 0; k < 3; ++k)
      if (p[k][0] > 6 && p[k][0] < 17 && p[k][1] > 6 && p[k][1] < 17)
        offPlane = std::max(offPlane, std::fabs(p[k][2] - 11.5));
    const double u[3] = { p[1][0] - p[0][0], p[1][1] - p[0][1], 0 }, v[3] = { p[2][0] - p[0][0], p[2][1] - p[0][1], 0 };
    area += 0.5 * std::fabs(u[0] * v[1] - u[1] * v[0]);
  }
  // A face of one tet is on the outer boundary: none lies inside the shared square (where a mesh
  // of each label on its own would leave two unmatched faces).
  int hanging = 0;
  for (const auto& [f, cells] : Faces(g))
  {
    if (cells.size() != 1)
      continue;
    double m[3] = { 0, 0, 0 };
    for (vtkIdType p : f)
      for (int a = 0; a < 3; ++a)
        m[a] += g->GetPoint(p)[a] / 3;
    hanging += std::fabs(m[2] - 11.5) < 0.5 && m[0] > 5 && m[0] < 18 && m[1] > 5 && m[1] < 18 ? 1 : 0;
  }
  EXPECT_EQ(hanging, 0);
  EXPECT_EQ(of[1], of[2]);
  EXPECT_GT(of[1].size(), 50u);
  EXPECT_LT(offPlane, 0.05) << "interface points lie on z = 11.5";
  EXPECT_GT(area, 0.8 * 16 * 16) << "the interface covers the cubes' shared square";
  EXPECT_LT(area, 16.0 * 16.0 + 1e-9);
}

// A label map's mesh carries a second volume's values (input port 1, as reduce --labels --values
// does): the ramp 10 z over two touching cubes, fitted inside them, is at every mesh point within
// half a voxel's step (5; the boundary lies half a voxel outside the outer voxels' centres) and its
// statistics are recorded; without SetLabels it is refused.
TEST(ImageDomainMesher, LabelMapCarriesTheValuesInput)
{
  const auto labels = Image(24, [](int i, int j, int k) {
    if (i < 4 || i > 19 || j < 4 || j > 19 || k < 4 || k > 19)
      return 0;
    return k < 12 ? 1 : 2;
  });
  auto ramp = vtkSmartPointer<vtkImageData>::New();
  ramp->SetDimensions(24, 24, 24);
  vtkNew<vtkFloatArray> r;
  r->SetName("ramp");
  r->SetNumberOfTuples(24 * 24 * 24);
  for (vtkIdType p = 0; p < r->GetNumberOfTuples(); ++p)
    r->SetValue(p, static_cast<float>(10 * (p / (24 * 24))));
  ramp->GetPointData()->SetScalars(r);
  vtkNew<vtkAdaptiveTetReducer> red;
  red->SetInputData(labels);
  red->SetValuesData(ramp);
  EXPECT_EQ(red->GetValuesData(), ramp.Get());
  red->SetLabels(true);
  red->SetTargetTets(2000);
  red->Update();
  vtkUnstructuredGrid* g = red->GetOutput();
  ASSERT_GT(g->GetNumberOfCells(), 500);
  vtkDataArray* v = g->GetPointData()->GetScalars();
  ASSERT_NE(v, nullptr);
  EXPECT_STREQ(v->GetName(), "ramp");
  double worst = 0;
  for (vtkIdType p = 0; p < g->GetNumberOfPoints(); ++p)
    worst = std::max(worst, std::fabs(v->GetTuple1(p) - 10 * g->GetPoint(p)[2]));
  EXPECT_LT(worst, 5.0);
  EXPECT_LT(red->GetRMSError(), 0.5);
  EXPECT_NE(g->GetCellData()->GetArray("label"), nullptr);
  EXPECT_NE(g->GetFieldData()->GetArray("source_window"), nullptr);
  // A region's values are its input's own.
  red->SetLabels(false);
  red->SetRegion(0.5, 2.5);
  red->Update();
  EXPECT_EQ(red->GetOutput()->GetNumberOfCells(), 0);
  red->SetValuesData(nullptr);
  EXPECT_EQ(red->GetValuesData(), nullptr);
}
