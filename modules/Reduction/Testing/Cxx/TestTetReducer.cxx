// The reducer on analytic fields (exact answers) and on the real CT head (independent check).
#include "DataLoader.h"
#include "Error.h"
#include "MeshQuality.h"
#include "ParallelTiles.h"
#include "Progress.h"
#include "ReducerVTK.h"
#include "ReductionFixtures.h"
#include "TetReducer.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkProbeFilter.h>
#include <vtkShortArray.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

using fixtures::ExpectValid;
using fixtures::Field;

namespace
{
double FieldValue(vtkFieldData* fd, const char* name)
{
  vtkDataArray* a = fd->GetArray(name);
  return a ? a->GetTuple1(0) : std::nan("");
}
} // namespace

TEST(TetReducer, LinearRampIsReproducedByTheCoarseMesh)
{
  const int d[3] = { 33, 29, 21 };
  const double s[3] = { 0.5, 1.0, 2.0 }, o[3] = { -3, 2, 1 };
  auto img = Field(d, s, o, [](double x, double y, double z) { return 2 * x - 3 * y + 0.5 * z + 7; });
  art::ReducerOptions opt;
  opt.TargetTets = 48;
  opt.SolverTolerance = 1e-14;
  const auto vol = art::VolumeFromImage(img);
  const auto out = art::TetReducer(opt).Run(vol);
  ASSERT_EQ(out.size(), 1u);
  const auto& m = out[0];
  EXPECT_LE(m.NumberOfTets(), 48);
  const double range = vol.Range[1] - vol.Range[0];
  EXPECT_LT(m.Rms, 1e-11 * range);
  EXPECT_LT(m.Max, 1e-10 * range);
  // The fit at each vertex is the ramp itself.
  for (long long v = 0; v < m.NumberOfVertices(); ++v)
  {
    const double* p = &m.Points[3 * v];
    EXPECT_NEAR(m.Values[v], 2 * p[0] - 3 * p[1] + 0.5 * p[2] + 7, 1e-9 * range);
  }
  ExpectValid(m);
}

// The stage reaches 1 only once the output is made: the output's values and their errors over every
// voxel (seconds on a large volume) must not come after the bar shows 100%.
TEST(TetReducer, ProgressReachesOneAfterTheOutput)
{
  const int d[3] = { 24, 20, 18 };
  const double s[3] = { 1, 1, 1 }, o[3] = { 0, 0, 0 };
  auto img = Field(d, s, o, [](double x, double y, double z) { return x * x + y * y - z * z; });
  for (bool weighted : { false, true })
  {
    art::ReducerOptions opt;
    opt.Levels = { 200 };
    opt.TargetTets = 2000;
    if (weighted)
    {
      opt.ScalarOpacity = { { 0, 0 }, { 300, 0.2 }, { 900, 0.9 } };
    }
    double last = -1;
    std::vector<std::string> stages;
    art::Progress p([&](double f, const std::string& stage) {
      last = f;
      stages.push_back(stage);
    });
    std::vector<double> atLevel;
    art::TetReducer(opt).Run(art::VolumeFromImage(img), &p, [&](const art::ReducedMesh&) { atLevel.push_back(last); });
    ASSERT_EQ(atLevel.size(), 2u);
    EXPECT_LT(atLevel.back(), 1.0) << (weighted ? "weighted" : "plain");
    EXPECT_EQ(last, 1.0);
    EXPECT_EQ(stages.front(), "reduce");
  }
}

// The first fit's passes over every voxel move the bar (on a large weighted volume they take
// tens of seconds). Here one refinement level is left (the coarse mesh is nearly the budget), so
// without them reporting the bar would jump from 0 to 95%. After relocation the stage resumes
// where it was, not from 0.
TEST(TetReducer, ProgressMovesDuringTheFirstFit)
{
  const int d[3] = { 40, 36, 30 };
  const double s[3] = { 1, 1, 1 }, o[3] = { 0, 0, 0 };
  auto img = Field(d, s, o, [](double x, double y, double z) { return std::sin(x / 5) * y + z * z; });
  for (bool weighted : { false, true })
  {
    art::ReducerOptions opt;
    opt.CoarseTets = 3000;
    opt.TargetTets = 3300;
    opt.RelocateVertices = true;
    opt.RelocateSweeps = 1;
    if (weighted)
    {
      opt.ScalarOpacity = { { 0, 0 }, { 300, 0.2 }, { 900, 0.9 } };
    }
    std::vector<std::pair<std::string, double>> seen;
    art::Progress p([&](double f, const std::string& stage) { seen.emplace_back(stage, f); });
    art::TetReducer(opt).Run(art::VolumeFromImage(img), &p);
    const auto relocate = std::find_if(seen.begin(), seen.end(), [](const auto& e) { return e.first == "relocate"; });
    ASSERT_NE(relocate, seen.end());
    int before = 0;
    for (auto e = seen.begin(); e != relocate; ++e)
    {
      before += e->second > 0.0 && e->second < 0.5 ? 1 : 0;
    }
    EXPECT_GE(before, 10) << (weighted ? "weighted" : "plain");
    // After relocation the refit is its own stage, from 0% to 100% (the bar fell back to
    // "reduce 90%" after "relocate 100%" and sat there).
    EXPECT_EQ(std::find_if(relocate, seen.end(), [](const auto& e) { return e.first == "reduce"; }), seen.end());
    const auto refit = std::find_if(relocate, seen.end(), [](const auto& e) { return e.first == "refit"; });
    ASSERT_NE(refit, seen.end());
    EXPECT_EQ(refit->second, 0.0);
    for (auto e = refit; e + 1 != seen.end(); ++e)
    {
      EXPECT_LE(e->second, (e + 1)->second);
    }
    EXPECT_EQ(seen.back().first, "refit");
    EXPECT_EQ(seen.back().second, 1.0);
  }
}

TEST(TetReducer, QuadraticErrorFallsAsTheBudgetGrowsAndBudgetsAreMet)
{
  const int d[3] = { 48, 40, 36 };
  const double s[3] = { 1, 1, 1.25 }, o[3] = { 0, 0, 0 };
  auto img = Field(d, s, o, [](double x, double y, double z) {
    return 0.05 * ((x - 20) * (x - 20) + 2 * (y - 15) * (y - 15) + 0.5 * (z - 30) * (z - 30));
  });
  art::ReducerOptions opt;
  opt.Levels = { 100, 400, 1600 };
  opt.TargetTets = 6400;
  const auto out = art::TetReducer(opt).Run(art::VolumeFromImage(img));
  ASSERT_EQ(out.size(), 4u);
  for (size_t i = 0; i < out.size(); ++i)
  {
    const long long want = out[i].TargetTets;
    EXPECT_NEAR(double(out[i].NumberOfTets()), double(want), 0.05 * want) << "level " << i;
    if (i > 0)
    {
      EXPECT_LT(out[i].Rms, 0.7 * out[i - 1].Rms) << "level " << i;
      EXPECT_LT(out[i].Max, out[i - 1].Max) << "level " << i;
      EXPECT_GE(out[i].BuildSeconds, out[i - 1].BuildSeconds);
      EXPECT_GT(out[i].NumberOfVertices(), out[i - 1].NumberOfVertices());
    }
    ExpectValid(out[i]);
  }
}

TEST(TetReducer, ErrorTargetsAreMet)
{
  const int d[3] = { 40, 40, 40 };
  const double s[3] = { 1, 1, 1 }, o[3] = { 0, 0, 0 };
  auto img = Field(d, s, o, [](double x, double y, double z) {
    return 100.0 * std::sin(0.15 * x) * std::cos(0.1 * y) + 0.2 * z;
  });
  const auto vol = art::VolumeFromImage(img);
  art::ReducerOptions opt;
  opt.TargetError = 0.01; // 1% of the range, RMS
  opt.ErrorRelative = true;
  auto rms = art::TetReducer(opt).Run(vol);
  ASSERT_FALSE(rms.empty());
  EXPECT_TRUE(rms.back().TargetReached);
  EXPECT_LE(rms.back().Rms, 0.01 * (vol.Range[1] - vol.Range[0]));
  opt.ErrorMetric = art::ReducerOptions::Metric::Max;
  opt.TargetError = 2.0; // data units
  opt.ErrorRelative = false;
  auto mx = art::TetReducer(opt).Run(vol);
  ASSERT_FALSE(mx.empty());
  EXPECT_TRUE(mx.back().TargetReached);
  EXPECT_LE(mx.back().Max, 2.0);
  ExpectValid(mx.back());
}

// A budget past the full-resolution tetrahedrisation (5 tets per voxel cell) stops there and says
// so, for the last level and every level above it, instead of refining past the voxels.
TEST(TetReducer, BudgetsBeyondTheVoxelsStopAtFullResolution)
{
  const int d[3] = { 9, 8, 7 };
  const double s[3] = { 1, 1, 1 }, o[3] = { 0, 0, 0 };
  auto img = Field(d, s, o, [](double x, double y, double z) { return std::sin(x) * std::cos(0.7 * y) + z * z; });
  art::ReducerOptions opt;
  opt.TargetTets = 1000000;
  opt.Levels = { 100, 500000 };
  const auto out = art::TetReducer(opt).Run(art::VolumeFromImage(img));
  ASSERT_EQ(out.size(), 3u);
  EXPECT_TRUE(out[0].TargetReached);
  const long long full = 5LL * 8 * 7 * 6;
  for (int i = 1; i < 3; ++i)
  {
    EXPECT_FALSE(out[i].TargetReached) << i;
    // The last bisection's closure may overshoot by a few tets; refining on to the edge-length
    // limit (as before the cap) gave 2176 here.
    EXPECT_GE(out[i].NumberOfTets(), full) << i;
    EXPECT_LE(out[i].NumberOfTets(), full + 16) << i;
    ExpectValid(out[i]);
  }
  EXPECT_EQ(out[1].TargetTets, 500000);
  EXPECT_EQ(out[2].TargetTets, 1000000);
}

TEST(TetReducer, ThickSlicesDoNotStopTheRefinement)
{
  // A cylinder across 8 slices of 5 mm under 0.4 mm pixels, and the same voxels 1 mm apart: the
  // coarse boxes, cubic in world units, were one voxel thick along the slices, so bisection
  // stopped at the edges along them and the pixels' axes stayed coarse (RMS 354 against 80).
  const int d[3] = { 30, 30, 8 };
  const double o[3] = { 0, 0, 0 };
  auto cylinder = [&](const double sp[3]) {
    return art::VolumeFromImage(Field(d, sp, o, [&](double x, double y, double) {
      const double i = x / sp[0] - 15, j = y / sp[1] - 15;
      return i * i + j * j < 60 ? 1000.0 : -1000.0;
    }));
  };
  const double thick[3] = { 0.4, 0.4, 5 }, cubic[3] = { 1, 1, 1 };
  art::ReducerOptions opt;
  opt.TargetTets = 2000;
  const art::ReducedMesh a = art::TetReducer(opt).Run(cylinder(thick)).back();
  const art::ReducedMesh b = art::TetReducer(opt).Run(cylinder(cubic)).back();
  ExpectValid(a);
  EXPECT_TRUE(a.TargetReached);
  EXPECT_LT(a.Rms, 3.2 * b.Rms) << a.Rms << " against " << b.Rms;
}

// A ball of 100 in air of 0 on a 24^3 grid: the least-squares fit overshoots on both sides of the jump.
static art::VoxelVolume BallInAir()
{
  const int d[3] = { 24, 24, 24 };
  const double sp[3] = { 1, 1, 1 }, o[3] = { 0, 0, 0 };
  return art::VolumeFromImage(Field(d, sp, o, [](double x, double y, double z) {
    return (x - 11.3) * (x - 11.3) + (y - 12.1) * (y - 12.1) + (z - 11.7) * (z - 11.7) < 49 ? 100.0 : 0.0;
  }));
}

TEST(TetReducer, ClampToVoxelsRemovesTheOvershootAtAJump)
{
  const auto vol = BallInAir();
  art::ReducerOptions opt;
  opt.TargetTets = 3000;
  const art::ReducedMesh plain = art::TetReducer(opt).Run(vol).back();
  opt.ClampToVoxels = true;
  const art::ReducedMesh clamped = art::TetReducer(opt).Run(vol).back();
  ExpectValid(clamped);
  ASSERT_EQ(clamped.Tets, plain.Tets) << "clamping changes the values only";
  const auto [mn, mx] = std::minmax_element(plain.Values.begin(), plain.Values.end());
  ASSERT_TRUE(*mx > 100.5 || *mn < -0.5) << "the plain fit should overshoot";
  // Each clamped value lies within the voxels under the bounding box of the vertex's tets (a box
  // that holds every voxel its tets own), and is their value where they all hold one.
  const std::size_t nv = clamped.Values.size();
  std::vector<std::array<double, 6>> box(nv, { { 1e300, -1e300, 1e300, -1e300, 1e300, -1e300 } });
  for (std::size_t t = 0; t < clamped.Tets.size() / 4; ++t)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int k = 0; k < 3; ++k)
        {
          auto& bx = box[clamped.Tets[4 * t + a]];
          const double c = clamped.Points[3 * clamped.Tets[4 * t + b] + k];
          bx[2 * k] = std::min(bx[2 * k], c);
          bx[2 * k + 1] = std::max(bx[2 * k + 1], c);
        }
  int changed = 0;
  for (std::size_t v = 0; v < nv; ++v)
  {
    double lo = 1e300, hi = -1e300;
    for (int k = static_cast<int>(std::ceil(box[v][4])); k <= box[v][5]; ++k)
      for (int j = static_cast<int>(std::ceil(box[v][2])); j <= box[v][3]; ++j)
        for (int i = static_cast<int>(std::ceil(box[v][0])); i <= box[v][1]; ++i)
        {
          const double f = vol.Value(i + vol.Dims[0] * (j + vol.Dims[1] * static_cast<long long>(k)));
          lo = std::min(lo, f);
          hi = std::max(hi, f);
        }
    EXPECT_GE(clamped.Values[v], lo - 1e-9) << v;
    EXPECT_LE(clamped.Values[v], hi + 1e-9) << v;
    if (lo == hi)
    {
      EXPECT_EQ(clamped.Values[v], lo) << v << ": all its voxels hold " << lo;
    }
    changed += clamped.Values[v] != plain.Values[v] ? 1 : 0;
  }
  EXPECT_GT(changed, 10);
}

TEST(TetReducer, CapOpacityClampsOnlyTheOvershootThatShowsMoreOpacity)
{
  // The ball, reduced for a transfer function: a value past its voxels' range is clamped only on
  // the side where the opacity is higher than theirs.
  const auto vol = BallInAir();
  for (const bool rising : { true, false })
  {
    art::ReducerOptions opt;
    opt.TargetTets = 3000;
    opt.ScalarOpacity = rising ? std::vector<std::pair<double, double>>{ { 0, 0 }, { 200, 1 } }
                               : std::vector<std::pair<double, double>>{ { -100, 1 }, { 100, 0 } };
    opt.CapOpacity = false;
    const art::ReducedMesh fit = art::TetReducer(opt).Run(vol).back();
    opt.CapOpacity = true;
    const art::ReducedMesh capped = art::TetReducer(opt).Run(vol).back();
    ExpectValid(capped);
    ASSERT_EQ(capped.Tets, fit.Tets) << "the cap changes the values only";
    const auto [fmn, fmx] = std::minmax_element(fit.Values.begin(), fit.Values.end());
    ASSERT_GT(*fmx, 100.5) << "the fit should overshoot the ball";
    ASSERT_LT(*fmn, -0.5) << "and undershoot the air";
    const auto [mn, mx] = std::minmax_element(capped.Values.begin(), capped.Values.end());
    if (rising)
    {
      EXPECT_LE(*mx, 100.0) << "more opaque than any voxel: clamped";
      EXPECT_EQ(*mn, *fmn) << "clearer than the air: kept";
    }
    else
    {
      EXPECT_GE(*mn, 0.0);
      EXPECT_EQ(*mx, *fmx);
    }
    int changed = 0;
    for (std::size_t v = 0; v < capped.Values.size(); ++v)
    {
      changed += capped.Values[v] != fit.Values[v];
    }
    EXPECT_GT(changed, 0);
    EXPECT_GE(capped.WeightedRms, fit.WeightedRms) << "the fit was the least-squares optimum";
  }
  // An error bound holds for the capped values, not only for the fit's.
  for (double bound = 7.0; bound <= 15.0; bound += 1.0)
  {
    art::ReducerOptions opt;
    opt.TargetError = bound;
    opt.ScalarOpacity = { { 0, 0 }, { 200, 1 } };
    const art::ReducedMesh m = art::TetReducer(opt).Run(vol).back();
    EXPECT_TRUE(m.TargetReached) << bound;
    EXPECT_LE(m.WeightedRms, bound);
  }
}

TEST(TetReducer, SmallVariationsOnALargeOffset)
{
  // 1000 + 1e-6 g: the solver's stopping rule must follow the variation, not the offset (it used
  // to stop at an RMS error of 7x the range: a flat blob).
  const int d[3] = { 24, 24, 24 };
  const double sp[3] = { 1, 1, 1 }, o[3] = { 0, 0, 0 };
  auto img = Field(d, sp, o, [](double x, double y, double z) {
    return 1000.0 + 1e-6 * std::exp(-((x - 11.5) * (x - 11.5) + (y - 11.5) * (y - 11.5) + (z - 11.5) * (z - 11.5)) / 40);
  });
  art::ReducerOptions opt;
  opt.TargetTets = 2000;
  const art::ReducedMesh m = art::TetReducer(opt).Run(art::VolumeFromImage(img)).back();
  ExpectValid(m);
  EXPECT_LT(m.Rms, 0.03 * 1e-6) << "RMS " << m.Rms << " against a range of 1e-6";
}

TEST(TetReducer, DeterministicForAnyThreadCount)
{
  auto vol = art::LoadVolume(std::string(ART_SOURCE_DIR) + "/data/ct-head-128.mha");
  art::ReducerOptions opt;
  opt.TargetTets = 3000;
  fixtures::ExpectSameForOneAndTwoThreads(opt, art::VolumeFromImage(vol));
}

TEST(TetReducer, RealCTHeadErrorMatchesAProbeAtTheVoxelCentres)
{
  auto img = art::LoadVolume(std::string(ART_SOURCE_DIR) + "/data/ct-head-128.mha");
  const auto vol = art::VolumeFromImage(img);
  art::ReducerOptions opt;
  opt.Levels = { 900, 9000 };
  opt.TargetTets = 40000;
  const auto out = art::TetReducer(opt).Run(vol);
  ASSERT_EQ(out.size(), 3u);
  double previous = 1e300;
  for (const auto& m : out)
  {
    EXPECT_NEAR(double(m.NumberOfTets()), double(m.TargetTets), 0.05 * m.TargetTets);
    ExpectValid(m);
    auto grid = art::ToUnstructuredGrid(m);
    // Independent check: VTK's probe interpolates the output grid at every voxel centre.
    auto probe = vtkSmartPointer<vtkProbeFilter>::New();
    probe->SetInputData(img);
    probe->SetSourceData(grid);
    probe->Update();
    vtkDataArray* fit = probe->GetOutput()->GetPointData()->GetArray(vol.Name.c_str());
    vtkDataArray* valid = probe->GetOutput()->GetPointData()->GetArray("vtkValidPointMask");
    ASSERT_TRUE(fit && valid);
    vtkDataArray* orig = img->GetPointData()->GetScalars();
    double sse = 0, mx = 0;
    long long invalid = 0;
    for (vtkIdType i = 0; i < img->GetNumberOfPoints(); ++i)
    {
      invalid += valid->GetTuple1(i) == 0 ? 1 : 0;
      const double e = orig->GetTuple1(i) - fit->GetTuple1(i);
      sse += e * e;
      mx = std::max(mx, std::fabs(e));
    }
    const double rms = std::sqrt(sse / img->GetNumberOfPoints());
    EXPECT_EQ(invalid, 0);
    // The grid stores float values: agreement to float precision of the HU range.
    EXPECT_NEAR(rms, m.Rms, 1e-3 + 1e-5 * m.Rms);
    EXPECT_NEAR(mx, m.Max, 1e-2);
    EXPECT_NEAR(FieldValue(grid->GetFieldData(), "rms_error"), m.Rms, 1e-12);
    EXPECT_EQ(FieldValue(grid->GetFieldData(), "tets"), double(m.NumberOfTets()));
    EXPECT_LT(m.Rms, previous);
    previous = m.Rms;
  }
}

TEST(TetReducer, BadInputIsAClearError)
{
  const double s[3] = { 1, 1, 1 }, o[3] = { 0, 0, 0 };
  const int flat[3] = { 10, 10, 1 };
  auto img = Field(flat, s, o, [](double x, double, double) { return x; });
  EXPECT_THROW(
    {
      try
      {
        art::VolumeFromImage(img, "flat.vti");
      }
      catch (const art::Error& e)
      {
        EXPECT_NE(std::string(e.what()).find("2-D image"), std::string::npos) << e.what();
        throw;
      }
    },
    art::Error);
  const int one[3] = { 1, 1, 1 };
  try
  {
    art::VolumeFromImage(Field(one, s, o, [](double, double, double) { return 3.0; }), "one.vti");
    ADD_FAILURE() << "a single voxel accepted";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("a single voxel (1 x 1 x 1)"), std::string::npos) << e.what();
  }
  const int d[3] = { 5, 5, 5 };
  auto vec = Field(d, s, o, [](double x, double, double) { return x; });
  auto three = vtkSmartPointer<vtkDoubleArray>::New();
  three->SetNumberOfComponents(3);
  three->SetNumberOfTuples(125);
  three->Fill(1.0);
  vec->GetPointData()->SetScalars(three);
  try
  {
    art::VolumeFromImage(vec);
    FAIL() << "accepted 3 components";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("3 components"), std::string::npos) << e.what();
  }
  auto empty = vtkSmartPointer<vtkImageData>::New();
  EXPECT_THROW(art::VolumeFromImage(empty), art::Error);
  // NaN voxels (a masked map) are counted and the first one placed in the world, past an extent
  // that does not start at 0; it said only "the scalars hold NaN or infinite values".
  auto masked = Field(d, s, o, [](double x, double, double) { return x; });
  masked->SetExtent(10, 14, 0, 4, 5, 9);
  masked->SetSpacing(0.5, 0.5, 0.5);
  masked->SetOrigin(100, 0, 0);
  masked->GetPointData()->GetScalars()->SetComponent(1 + 5 * (1 + 5 * 1), 0, std::nan(""));
  masked->GetPointData()->GetScalars()->SetComponent(124, 0, -std::numeric_limits<double>::infinity());
  try
  {
    art::VolumeFromImage(masked, "masked.vti");
    FAIL() << "accepted NaN voxels";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("NaN or infinite values: 2 voxels, the first at x, y, z = 105.5, 0.5, 3"),
      std::string::npos)
      << e.what();
  }
  // A zero spacing is an error naming the axis (it gave zero-volume tets); a negative one is a
  // flipped axis, reduced like the same voxels stored the other way round.
  auto zero = Field(d, s, o, [](double x, double, double) { return x; });
  zero->SetSpacing(1, 0, 1);
  try
  {
    art::VolumeFromImage(zero);
    FAIL() << "accepted a zero spacing";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("spacing along axis 1 is 0"), std::string::npos) << e.what();
  }
  auto flipped = Field(d, s, o, [](double x, double, double) { return x; });
  flipped->SetSpacing(-s[0], s[1], s[2]);
  const auto fv = art::VolumeFromImage(flipped);
  EXPECT_EQ(fv.Spacing[0], s[0]);
  EXPECT_EQ(fv.Direction[0], -1.0);
  EXPECT_EQ(fv.Origin[0], o[0]);
  art::ReducerOptions none;
  auto ok = art::VolumeFromImage(Field(d, s, o, [](double x, double, double) { return x; }));
  EXPECT_THROW(art::TetReducer(none).Run(ok), art::Error);
}

TEST(TetReducer, TurnedAndShearedVolumesPassTheConformityCheck)
{
  // An oblique MRI's direction matrix turns the mesh's box: its outer faces are the faces of the
  // turned box, not of the points' axis-aligned box, and `reduce` called the mesh broken
  // ("internal: ... failed its conformity check", 128 of 192 outer faces counted as cracks).
  const int d[3] = { 12, 10, 9 };
  const double s[3] = { 1.0, 1.2, 2.0 }, o[3] = { -30, 40, 7 };
  const double c = std::cos(0.5), sn = std::sin(0.5);
  const double turned[9] = { c, -sn, 0, sn * 0.6, c * 0.6, -0.8, sn * 0.8, c * 0.8, 0.6 };
  const double sheared[9] = { 1, 0.5, 0, 0, 1, 0.25, 0, 0, 1 };
  for (const double* m : { turned, sheared })
  {
    auto img = Field(d, s, o, [](double x, double y, double z) { return std::sin(0.3 * x) * y + z * z; });
    img->SetDirectionMatrix(m);
    art::ReducerOptions opt;
    opt.TargetTets = 600;
    const art::ReducedMesh mesh = art::TetReducer(opt).Run(art::VolumeFromImage(img)).back();
    ExpectValid(mesh);
    // A crack is still one: drop a tet and its four faces show as open.
    art::ReducedMesh cracked = mesh;
    cracked.Tets.erase(cracked.Tets.begin() + 4 * (mesh.NumberOfTets() / 2), cracked.Tets.begin() + 4 * (mesh.NumberOfTets() / 2 + 1));
    const auto q = art::MeasureQuality(cracked.Points.data(), cracked.NumberOfVertices(), cracked.Tets.data(), cracked.NumberOfTets());
    EXPECT_GT(q.OpenFaces, 0) << q.Summary();
    EXPECT_FALSE(q.Valid());
  }
}

// A volume whose reduction would not fit in the memory available is refused before anything is
// allocated, naming its file, voxels, the memory needed and available and the way out; it was
// killed by the system half-way (a 1024^3 CT weighted by a transfer function needs ~34 GB).
TEST(TetReducer, MemoryCheckRefusesAVolumeTooLargeForTheMachine)
{
  art::VoxelVolume big; // only its size and name count: no samples are allocated
  big.Dims[0] = big.Dims[1] = big.Dims[2] = 1024;
  big.File = "big.mha";
  const long long voxels = 1LL << 30;
  art::ReducerOptions plain;
  plain.TargetTets = voxels / 100;
  art::ReducerOptions weighted = plain;
  weighted.ScalarOpacity = { { 0, 0 }, { 100, 1 } };
  art::ReducerOptions relocated = plain;
  relocated.RelocateVertices = true;
  EXPECT_NEAR(art::TetReducer(plain).MemoryNeeded(voxels), 350.0 * plain.TargetTets, 1.0);
  EXPECT_NEAR(art::TetReducer(weighted).MemoryNeeded(voxels), 350.0 * plain.TargetTets + 28.0 * voxels, 1.0);
  EXPECT_GT(art::TetReducer(relocated).MemoryNeeded(voxels), art::TetReducer(plain).MemoryNeeded(voxels));
  art::ReducerOptions levels = plain; // the largest of the levels counts
  levels.Levels = { 1000, voxels / 10 };
  EXPECT_NEAR(art::TetReducer(levels).MemoryNeeded(voxels), 350.0 * (voxels / 10), 1.0);

  EXPECT_NO_THROW(art::TetReducer(plain).CheckMemory(big, 24e9));   // 3.8 GB of tets
  EXPECT_NO_THROW(art::TetReducer(weighted).CheckMemory(big, 0.0)); // memory unknown
  try
  {
    art::TetReducer(weighted).CheckMemory(big, 24e9);
    FAIL() << "34 GB accepted with 24 GB available";
  }
  catch (const art::Error& e)
  {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("big.mha: reducing this volume of 1024 x 1024 x 1024 = 1073741824 voxels weighted", 0), 0u)
      << what;
    EXPECT_NE(what.find("needs about 33.8 GB more, more than the 24 GB of memory available"), std::string::npos)
      << what;
    EXPECT_NE(what.find("vtkImageResample"), std::string::npos) << what;
    EXPECT_NE(what.find("without a transfer function"), std::string::npos) << what;
  }
  EXPECT_THROW(art::TetReducer(plain).CheckMemory(big, 3e9), art::Error);
}

// Values of 1e300 overflow the fit's squares: one error naming the file instead of a coarse mesh
// with 'RMS inf' (vtkAdaptiveTetReducer and library callers reach here without the CLI's check).
TEST(TetReducer, ValuesWhoseSquaresOverflowAreRefused)
{
  vtkNew<vtkImageData> img;
  img->SetDimensions(4, 4, 4);
  vtkNew<vtkDoubleArray> s;
  s->SetNumberOfTuples(64);
  for (int i = 0; i < 64; ++i)
  {
    s->SetValue(i, i % 2 ? 1e300 : -1e300);
  }
  img->GetPointData()->SetScalars(s);
  try
  {
    art::VolumeFromImage(img, "big.vti");
    FAIL() << "values of 1e300 accepted";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("big.vti: the scalars' range -1e+300 .. 1e+300 reaches beyond 1e150"),
      std::string::npos)
      << e.what();
  }
  for (int i = 0; i < 64; ++i)
  {
    s->SetValue(i, i % 2 ? 1e150 : -1e150); // the largest that stays
  }
  s->Modified();
  EXPECT_NO_THROW(art::VolumeFromImage(img, "big.vti"));
}

// An error bound alone may refine up to a tet per voxel, which no up-front check can count: each
// refinement's added tets are checked against the memory available, naming the way out.
TEST(TetReducer, GrowthUnderAnErrorBoundIsChecked)
{
  art::VoxelVolume big;
  big.Dims[0] = big.Dims[1] = big.Dims[2] = 1024;
  big.File = "big.mha";
  art::ReducerOptions bound;
  bound.TargetError = 0.1;
  EXPECT_NO_THROW(art::TetReducer(bound).CheckGrowth(big, 1000000, 1200000, 24e9)); // 0.42 GB
  EXPECT_NO_THROW(art::TetReducer(bound).CheckGrowth(big, 100000000, 120000000, 0.0)); // memory unknown
  try
  {
    art::TetReducer(bound).CheckGrowth(big, 40000000, 50000000, 16e9); // 17.5 GB
    FAIL() << "17.5 GB accepted with 16 GB available";
  }
  catch (const art::Error& e)
  {
    EXPECT_EQ(std::string(e.what()),
      "big.mha: the error bound is not met at 40000000 tets, and refining to 50000000 would need about 17.5 GB, "
      "more than the 16 GB of memory available; set a tet budget (--tets N) or a larger error bound, or crop "
      "or resample the volume first");
  }
}
