// The default transfer function from the data and the frame it gets: an MRI's background is
// clear and its tissue is not, a label map gets one colour per label, MIP spans black to white, a
// reduced mesh's recorded statistics decide its function as its volume's samples decided the
// volume's, and the default camera fits the visible object (not the box) to 85% of the frame.
#include "Camera.h"
#include "DataTransferFunction.h"
#include "SourceStatistics.h"
#include "TetMesh.h"
#include "TetRayCaster.h"
#include "VisibleBounds.h"

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkShortArray.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>
#include <random>

using namespace art;

namespace
{
constexpr int N = 40;

// An MRI-like volume: noise 0..4 around an ellipsoid of tissue 100..200 centred off the box's
// centre, plus lone hot voxels at 255 in the background.
vtkSmartPointer<vtkImageData> MriLike()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(N, N, N);
  image->SetSpacing(2, 2, 2);
  vtkNew<vtkUnsignedCharArray> s;
  s->SetName("mri");
  s->SetNumberOfTuples(N * N * N);
  std::mt19937 rng(3);
  std::uniform_int_distribution<int> noise(0, 4), tissue(100, 200);
  for (int k = 0; k < N; ++k)
    for (int j = 0; j < N; ++j)
      for (int i = 0; i < N; ++i)
      {
        const double x = (i - 25) / 8.0, y = (j - 18) / 10.0, z = (k - 20) / 12.0;
        s->SetValue(i + N * (j + N * k), static_cast<unsigned char>(x * x + y * y + z * z < 1 ? tissue(rng) : noise(rng)));
      }
  for (int h = 0; h < 6; ++h)
  {
    s->SetValue(2 + 7 * h + N * (1 + N * (3 + 6 * h)), 255);
  }
  image->GetPointData()->SetScalars(s);
  return image;
}

RenderSettings With(const TransferFunction& tf)
{
  RenderSettings s;
  s.tf = tf;
  return s;
}
} // namespace

TEST(DataTransferFunction, MriBackgroundIsClearAndTissueIsNot)
{
  auto image = MriLike();
  double r[2];
  image->GetPointData()->GetScalars()->GetRange(r);
  const ScalarStatistics st = StatisticsFor(image, r[0], r[1]);
  ASSERT_TRUE(st.hasBackground);
  const TransferFunction tf = TransferFunction::PresetFor("auto", image, r[0], r[1]);
  EXPECT_TRUE(tf.Transparent(0, 4));           // the noise
  EXPECT_FALSE(tf.Transparent(150, 150));      // the tissue
  EXPECT_GT(tf.Alpha(200), tf.Alpha(150));     // brighter is more opaque
  EXPECT_NEAR(tf.Alpha(st.windowHigh), DataRampOpacity, 1e-9);
  // The grey ramp over the whole range (the old default) gave the noise opacity: the fog.
  EXPECT_FALSE(TransferFunction::Preset("grey-ramp", r[0], r[1]).Transparent(1, 4));
}

TEST(DataTransferFunction, MaximumIntensitySpansBlackToWhite)
{
  auto image = MriLike();
  double r[2];
  image->GetPointData()->GetScalars()->GetRange(r);
  const ScalarStatistics st = StatisticsFor(image, r[0], r[1]);
  const TransferFunction tf = TransferFunction::MaximumIntensityFor(image, r[0], r[1]);
  double rgb[3], tau;
  tf.Evaluate(st.windowHigh, rgb, tau);
  EXPECT_NEAR(rgb[0] * tf.Alpha(st.windowHigh), 1.0, 1e-9); // the window's top is white
  EXPECT_NEAR(tf.Alpha(2), 0.0, 1e-12);                       // the background black
  // Linear in between: mid-window is mid-grey.
  const double mid = 0.5 * (std::max(st.windowLow, st.backgroundTop) + st.windowHigh);
  tf.Evaluate(mid, rgb, tau);
  EXPECT_NEAR(rgb[0] * tf.Alpha(mid), 0.5, 1e-6);
}

TEST(DataTransferFunction, LabelsGetDistinctColoursAndBackgroundIsClear)
{
  ScalarStatistics s;
  s.lo = s.windowLow = 0;
  s.hi = s.windowHigh = 3;
  s.labels = true;
  s.labelValues = { 0, 1, 2, 3 };
  s.samples = 100;
  const TransferFunction tf = DataTransferFunction(s, 1.0);
  EXPECT_TRUE(tf.Transparent(-0.4, 0.4));
  double c[4][3], tau;
  for (int l = 1; l <= 3; ++l)
  {
    tf.Evaluate(l, c[l], tau);
    EXPECT_NEAR(tf.Alpha(l), LabelOpacity, 1e-9);
    EXPECT_NEAR(tf.Alpha(l + 0.3), LabelOpacity, 1e-9); // constant across the label's half-way points
  }
  for (int a = 1; a <= 3; ++a)
    for (int b = a + 1; b <= 3; ++b)
    {
      const double d = std::fabs(c[a][0] - c[b][0]) + std::fabs(c[a][1] - c[b][1]) + std::fabs(c[a][2] - c[b][2]);
      EXPECT_GT(d, 0.3) << "labels " << a << " and " << b;
    }
}

// A mesh that records its volume's statistics gets the volume's function, though its own
// vertex values (crowded at edges, overshooting) have no background pile at all.
TEST(DataTransferFunction, ReducedMeshUsesItsRecordedSourceStatistics)
{
  auto image = MriLike();
  double r[2];
  image->GetPointData()->GetScalars()->GetRange(r);
  const ScalarStatistics source = StatisticsFor(image, r[0], r[1]);

  // The mesh's vertex values: the tissue's, a few overshooting the range as a fit's do at edges.
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkFloatArray> values;
  for (int i = 0; i < 1000; ++i)
  {
    values->InsertNextValue(i % 100 == 0 ? (i % 200 == 0 ? -40.f : 300.f) : 100.f + 0.1f * static_cast<float>(i));
  }
  grid->GetPointData()->SetScalars(values);
  WriteSourceStatistics(grid->GetFieldData(), source);
  ScalarStatistics back;
  ASSERT_TRUE(ReadSourceStatistics(grid->GetFieldData(), back));
  EXPECT_EQ(back.windowLow, source.windowLow);
  EXPECT_EQ(back.windowHigh, source.windowHigh);
  EXPECT_EQ(back.hasBackground, source.hasBackground);
  EXPECT_EQ(back.backgroundTop, source.backgroundTop);

  const ScalarStatistics used = StatisticsFor(grid, -40, 300);
  EXPECT_EQ(used.windowHigh, source.windowHigh);
  EXPECT_EQ(used.backgroundTop, source.backgroundTop);
  // Rescaled since (a calculator's output), the record no longer applies: the values' own.
  for (vtkIdType i = 0; i < values->GetNumberOfTuples(); ++i)
  {
    values->SetValue(i, 4.f * values->GetValue(i));
  }
  const ScalarStatistics other = StatisticsFor(grid, -160, 1200);
  EXPECT_NE(other.windowHigh, source.windowHigh);
  EXPECT_GT(other.windowHigh, 600);
}

// The visible box is the tissue's (to a voxel), not the box's nor the hot voxels'; the default
// camera frames it at 85% of the frame's narrower side.
TEST(DataTransferFunction, DefaultFrameFitsTheVisibleObject)
{
  auto image = MriLike();
  double r[2];
  image->GetPointData()->GetScalars()->GetRange(r);
  const RenderSettings s = With(TransferFunction::PresetFor("auto", image, r[0], r[1]));
  const Box3 object = VisibleBounds(image, s);
  ASSERT_FALSE(object.Empty());
  // The ellipsoid spans i 17..33, j 8..28, k 8..32 (spacing 2), within a voxel either way.
  EXPECT_NEAR(object.lo.x, 2 * 17, 4.1);
  EXPECT_NEAR(object.hi.x, 2 * 33, 4.1);
  EXPECT_NEAR(object.lo.y, 2 * 8, 4.1);
  EXPECT_NEAR(object.hi.y, 2 * 28, 4.1);
  EXPECT_NEAR(object.lo.z, 2 * 8, 4.1);
  EXPECT_NEAR(object.hi.z, 2 * 32, 4.1);

  double b[6];
  image->GetBounds(b);
  vtkNew<vtkCamera> cam;
  Camera::DefaultView(cam, Box3::FromBounds(b));
  Camera::FrameObject(cam, object, Box3::FromBounds(b), 0, 0, 1.0, 400.0 / 300.0);
  const Camera c = Camera::FromVTK(cam, 400, 300);
  // Project the object's corners: the widest reach in the frame's half extents is 0.85.
  double reach = 0;
  for (int k = 0; k < 8; ++k)
  {
    const double p[4] = { (k & 1) ? object.hi.x : object.lo.x, (k & 2) ? object.hi.y : object.lo.y,
      (k & 4) ? object.hi.z : object.lo.z, 1.0 };
    double q[4];
    cam->GetCompositeProjectionTransformMatrix(400.0 / 300.0, -1, 1)->MultiplyPoint(p, q);
    reach = std::max({ reach, std::fabs(q[0] / q[3]), std::fabs(q[1] / q[3]) });
  }
  EXPECT_NEAR(reach, Camera::FitFraction, 0.01);
  // The eye stays outside the volume's box.
  const Vec3 eye = c.Position();
  EXPECT_FALSE(eye.x >= b[0] && eye.x <= b[1] && eye.y >= b[2] && eye.y <= b[3] && eye.z >= b[4] && eye.z <= b[5]);
}

// Nothing visible: an empty box (the camera then frames the data's box).
TEST(DataTransferFunction, NothingVisibleGivesAnEmptyBox)
{
  auto image = MriLike();
  std::vector<TransferFunction::Node> clear = { { 0, { 0, 0, 0 }, 0, 0 }, { 255, { 1, 1, 1 }, 0, 0 } };
  EXPECT_TRUE(VisibleBounds(image, With(TransferFunction(clear))).Empty());
}
