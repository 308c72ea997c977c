// Transfer-function presets on data: the unit distance follows the sample spacing of volumes and
// meshes, and 'auto' tells a CT in Hounsfield units from a signed field.
#include "MeanSpacing.h"
#include "DataTransferFunction.h"
#include "MeshFixtures.h"
#include "TetRayCaster.h"

#include <gtest/gtest.h>
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

using namespace art;
using fixtures::ViewOf;

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
// whole values, 0.8% near -1000) gets its own grey ramp (DataTransferFunction), not CT colours; the same values rounded to
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
    // ct-skin-bone has 8 nodes; the data's own function is clear at the field's bottom end.
    EXPECT_EQ(tf.Nodes().size() == 8u, k != 0) << "case " << k;
    if (k == 0)
    {
      EXPECT_NEAR(tf.Alpha(r[1]), DataRampOpacity, 1e-9) << "the field's own ramp";
      EXPECT_TRUE(tf.Transparent(r[0], r[0]));
    }
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
