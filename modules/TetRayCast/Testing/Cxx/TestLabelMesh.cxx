// A label mesh split per label: each label's copies of a shared face's points, the values packed
// into one band per label, and the composed function equal to each label's own function of the
// values at every value (so the segment integral stays exact); the tint keeps a grey's luminance
// in the label's hue.
#include "DataTransferFunction.h"
#include "LabelMesh.h"
#include "TransferFunction.h"

#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>
#include <random>
#include <string>

using namespace art;

namespace
{
// Two tets sharing the face (0, 1, 2), labelled 3 and 7, values 10 z + x at the points, and the
// field data a reducer writes (the values' range).
vtkSmartPointer<vtkUnstructuredGrid> TwoLabels()
{
  const double p[5][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0, 0, -1 } };
  vtkNew<vtkPoints> pts;
  vtkNew<vtkFloatArray> v;
  v->SetName("ramp");
  for (const auto& q : p)
  {
    pts->InsertNextPoint(q);
    v->InsertNextValue(static_cast<float>(10 * q[2] + q[0]));
  }
  auto g = vtkSmartPointer<vtkUnstructuredGrid>::New();
  g->SetPoints(pts);
  const vtkIdType a[4] = { 0, 1, 2, 3 }, b[4] = { 0, 2, 1, 4 };
  g->InsertNextCell(VTK_TETRA, 4, a);
  g->InsertNextCell(VTK_TETRA, 4, b);
  g->GetPointData()->SetScalars(v);
  vtkNew<vtkIntArray> label;
  label->SetName("label");
  label->InsertNextValue(3);
  label->InsertNextValue(7);
  g->GetCellData()->AddArray(label);
  for (const char* name : { "scalar_range_min", "scalar_range_max" })
  {
    vtkNew<vtkDoubleArray> r;
    r->SetName(name);
    r->InsertNextValue(std::string(name).back() == 'n' ? -10 : 10);
    g->GetFieldData()->AddArray(r);
  }
  return g;
}
} // namespace

TEST(LabelMesh, SplitsSharedPointsPerLabel)
{
  auto g = TwoLabels();
  ASSERT_TRUE(LabelMesh::Has(g));
  const LabelMesh m(g, g->GetPointData()->GetScalars());
  EXPECT_EQ(m.Labels(), (std::vector<double>{ 3, 7 }));
  vtkUnstructuredGrid* s = m.Grid();
  ASSERT_EQ(s->GetNumberOfPoints(), 8); // the shared face's three points once per label
  ASSERT_EQ(s->GetNumberOfCells(), 2);
  EXPECT_DOUBLE_EQ(m.ValueLow(), -10);
  EXPECT_DOUBLE_EQ(m.ValueHigh(), 10);
  // Label 3's copies in band [0, 1], label 7's in [2, 3], each at its value's place in the range.
  vtkDataArray* band = s->GetPointData()->GetArray("label_values");
  ASSERT_NE(band, nullptr);
  for (vtkIdType c = 0; c < 2; ++c)
  {
    for (vtkIdType k = 0; k < 4; ++k)
    {
      const vtkIdType id = s->GetCell(c)->GetPointId(k);
      double x[3];
      s->GetPoint(id, x);
      const double t = (10 * x[2] + x[0] + 10) / 20;
      EXPECT_NEAR(band->GetTuple1(id), 2.0 * c + t, 1e-12) << "cell " << c << " corner " << k;
    }
  }
  // The values' range describes the values, not the bands.
  EXPECT_FALSE(s->GetFieldData()->HasArray("scalar_range_min"));
  // Without values the copies carry their label.
  const LabelMesh flat(g, nullptr);
  EXPECT_FALSE(flat.HasValues());
  vtkDataArray* l = flat.Grid()->GetPointData()->GetArray("label");
  ASSERT_NE(l, nullptr);
  EXPECT_EQ(l->GetRange()[0], 3);
  EXPECT_EQ(l->GetRange()[1], 7);
  EXPECT_EQ(flat.Grid()->GetNumberOfPoints(), 8);
}

TEST(LabelMesh, ComposedFunctionIsEachLabelsOwn)
{
  auto g = TwoLabels();
  const LabelMesh m(g, g->GetPointData()->GetScalars());
  // Label 3: a ramp with a node inside the range; label 7: its hue over another ramp.
  const TransferFunction f3({ { -12, { 0, 0, 0 }, 0.1, 0 }, { 2, { 1, 0.5, 0 }, 0.6, 0 }, { 9, { 0, 1, 1 }, 0.3, 0 } }, 0.5);
  const TransferFunction f7 = LabelValueRamp(7, -5, 5, 0.5);
  const TransferFunction all = m.Compose([&](double l) { return l == 3 ? f3 : f7; }, 0.5);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-10, 10);
  for (int i = 0; i < 200; ++i)
  {
    const double v = u(rng);
    for (int k = 0; k < 2; ++k)
    {
      const TransferFunction& f = k == 0 ? f3 : f7;
      double want[3], got[3], tw, tg;
      f.Evaluate(v, want, tw);
      all.Evaluate(2.0 * k + (v + 10) / 20, got, tg);
      for (int a = 0; a < 3; ++a)
      {
        EXPECT_NEAR(got[a], want[a], 1e-9) << "value " << v << " label " << (k ? 7 : 3);
      }
      EXPECT_NEAR(tg, tw, 1e-9 * (1 + tw)) << "value " << v;
    }
  }
}

TEST(LabelMesh, TintKeepsLuminanceInTheLabelsHue)
{
  const TransferFunction grey({ { 0, { 0.25, 0.25, 0.25 }, 0.1, 0 }, { 1, { 1, 1, 1 }, 0.4, 0 } }, 1.0);
  const TransferFunction t = TintedByLabel(grey, -2); // |label| picks the colour, as the labels preset does
  const double* c = TransferFunction::CategoricalColour(2);
  double rgb[3], tau, tg, g[3];
  t.Evaluate(0.5, rgb, tau);
  grey.Evaluate(0.5, g, tg);
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_NEAR(rgb[a], 0.625 * c[a], 1e-12);
  }
  EXPECT_DOUBLE_EQ(tau, tg);
  // The default inside a label: brightness 0.3 to 1 and opacity LabelOpacity / 5 to LabelOpacity
  // over the window, clamped outside it.
  const TransferFunction r = LabelValueRamp(1, 100, 200, 1.0);
  const double* o = TransferFunction::CategoricalColour(1);
  r.Evaluate(50, rgb, tau);
  EXPECT_NEAR(rgb[1], 0.3 * o[1], 1e-12);
  EXPECT_NEAR(tau, -std::log(1 - 0.2 * LabelOpacity), 1e-12);
  r.Evaluate(200, rgb, tau);
  EXPECT_NEAR(rgb[0], o[0], 1e-12);
  EXPECT_NEAR(tau, -std::log(1 - LabelOpacity), 1e-12);
}
