// The opacity-weighted reduction: exact on linear fields, fewer tets where nothing is seen, a
// lower weighted error than the plain reduction at the same budget, clear errors for bad input.
#include "BisectionMesh.h"
#include "Error.h"
#include "LeastSquaresFit.h"
#include "MeshQuality.h"
#include "OpacityImportance.h"
#include "ParallelTiles.h"
#include "ReducerVTK.h"
#include "TetReducer.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkProbeFilter.h>
#include <vtkUnstructuredGrid.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numeric>
#include <functional>
#include <limits>

namespace
{
art::VoxelVolume Volume(const int d[3], const std::function<double(double, double, double)>& f)
{
  art::VoxelVolume v;
  std::copy(d, d + 3, v.Dims);
  v.DoubleValues = true;
  v.Double.resize(static_cast<size_t>(v.NumberOfVoxels()));
  for (int k = 0; k < d[2]; ++k)
  {
    for (int j = 0; j < d[1]; ++j)
    {
      for (int i = 0; i < d[0]; ++i)
      {
        v.Double[(static_cast<size_t>(k) * d[1] + j) * d[0] + i] = f(i, j, k);
      }
    }
  }
  v.Validate();
  return v;
}

// Rebuilds an image from the volume and probes the reduced mesh at every voxel centre: the fit
// of any mesh, taken outside the reducer.
vtkSmartPointer<vtkDataArray> ProbedFit(const art::VoxelVolume& v, const art::ReducedMesh& m)
{
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(v.Dims);
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(v.Name.c_str());
  a->SetNumberOfTuples(v.NumberOfVoxels());
  for (long long i = 0; i < v.NumberOfVoxels(); ++i)
  {
    a->SetValue(i, v.Value(i));
  }
  img->GetPointData()->SetScalars(a);
  auto probe = vtkSmartPointer<vtkProbeFilter>::New();
  probe->SetInputData(img);
  probe->SetSourceData(art::ToUnstructuredGrid(m, true));
  probe->Update();
  return probe->GetOutput()->GetPointData()->GetArray(v.Name.c_str());
}

// The weighted error of any mesh, measured outside the reducer.
double ProbedWeightedRms(const art::VoxelVolume& v, const art::ReducedMesh& m, const art::OpacityImportance& imp)
{
  const auto fit = ProbedFit(v, m);
  double s = 0;
  for (long long i = 0; i < v.NumberOfVoxels(); ++i)
  {
    s += imp.Error2(i, v.Value(i), fit->GetTuple1(i));
  }
  return std::sqrt(s / v.NumberOfVoxels());
}

// Zero opacity up to 0.5, a ramp above: the opacity a renderer would see.
const std::vector<std::pair<double, double>> HalfRamp = { { 0.0, 0.0 }, { 0.5, 0.0 }, { 1.0, 1.0 } };
} // namespace

TEST(OpacityImportance, WeightsFollowTheOpacitySlope)
{
  art::OpacityImportance imp(HalfRamp);
  EXPECT_DOUBLE_EQ(imp.MaxSlope(0.1, 0.4), 0.0);
  EXPECT_DOUBLE_EQ(imp.MaxSlope(0.4, 0.6), 2.0);
  EXPECT_DOUBLE_EQ(imp.MaxSlope(2.0, 3.0), 0.0); // clamped beyond the last node
  EXPECT_DOUBLE_EQ(imp.Opacity(0.75), 0.5);
  const int d[3] = { 8, 4, 4 };
  const auto v = Volume(d, [](double x, double, double) { return x < 4 ? 0.2 : 0.8; });
  imp.Prepare(v, 0.05, 1);
  EXPECT_FLOAT_EQ(imp.Weight(0, 0.2, 0.2), 0.05);   // far from the ramp, fit in the flat band (a float)
  EXPECT_FLOAT_EQ(imp.Weight(0, 0.2, 0.45), 0.05);  // still flat: the ramp starts at 0.5
  EXPECT_DOUBLE_EQ(imp.Weight(0, 0.2, 0.7), 1.0);   // a fit straying into the ramp counts in full
  EXPECT_DOUBLE_EQ(imp.Weight(3, 0.2, 0.2), 1.0);   // its neighbour across the edge is in the ramp
  EXPECT_DOUBLE_EQ(imp.Weight(7, 0.8, 0.8), 1.0);   // in the ramp
}

TEST(OpacityImportance, WeightedFitReproducesALinearRamp)
{
  const int d[3] = { 25, 21, 17 };
  const auto v = Volume(d, [](double x, double y, double z) { return 0.02 * x + 0.01 * y + 0.015 * z; });
  art::ReducerOptions opt;
  opt.TargetTets = 48;
  opt.SolverTolerance = 1e-14;
  opt.ScalarOpacity = HalfRamp;
  const auto out = art::TetReducer(opt).Run(v);
  ASSERT_EQ(out.size(), 1u);
  const auto& m = out[0];
  EXPECT_TRUE(m.Weighted);
  EXPECT_LT(m.Rms, 1e-11);
  EXPECT_LT(m.Max, 1e-10);
  EXPECT_LT(m.WeightedRms, 1e-11);
  for (long long i = 0; i < m.NumberOfVertices(); ++i)
  {
    const double* p = &m.Points[3 * i];
    EXPECT_NEAR(m.Values[i], 0.02 * p[0] + 0.01 * p[1] + 0.015 * p[2], 1e-10);
  }
}

TEST(OpacityImportance, FewerTetsWhereNothingIsSeenAndALowerWeightedError)
{
  // The same ripples in both halves; the left half's values (0 .. 0.4) have no opacity, the
  // right half's (0.6 .. 1) sit on the ramp.
  const int d[3] = { 64, 40, 40 };
  const auto v = Volume(d, [](double x, double y, double z) {
    const double r = 0.2 + 0.2 * std::sin(0.45 * y) * std::sin(0.35 * z) * std::cos(0.3 * x);
    return x < 32 ? r : r + 0.6;
  });
  art::ReducerOptions opt;
  opt.TargetTets = 12000;
  opt.ImportanceRadius = 1; // the step's band of full weight stays narrow beside the ripples
  const auto plain = art::TetReducer(opt).Run(v).back();
  opt.ScalarOpacity = HalfRamp;
  const auto weighted = art::TetReducer(opt).Run(v).back();
  EXPECT_NEAR(double(plain.NumberOfTets()), 12000.0, 600.0);
  EXPECT_NEAR(double(weighted.NumberOfTets()), 12000.0, 600.0);
  EXPECT_FALSE(plain.Weighted);
  EXPECT_TRUE(weighted.Weighted);

  // Tets whose centroid lies in the left half, clear of the step at x = 31.5.
  auto leftTets = [](const art::ReducedMesh& m) {
    long long n = 0;
    for (long long t = 0; t < m.NumberOfTets(); ++t)
    {
      double cx = 0;
      for (int a = 0; a < 4; ++a)
      {
        cx += 0.25 * m.Points[3 * static_cast<size_t>(m.Tets[4 * t + a])];
      }
      n += cx < 28 ? 1 : 0;
    }
    return n;
  };
  const long long lp = leftTets(plain), lw = leftTets(weighted);
  EXPECT_GT(lp, 2000);          // the plain fit spends on both halves alike ...
  EXPECT_LT(lw, 0.8 * lp);      // ... the weighted one measurably fewer where nothing shows
  const auto q = art::MeasureQuality(weighted.Points.data(), weighted.NumberOfVertices(), weighted.Tets.data(),
    weighted.NumberOfTets());
  EXPECT_TRUE(q.Valid()) << q.Summary();

  art::OpacityImportance imp(HalfRamp);
  imp.Prepare(v, opt.ImportanceFloor, opt.ImportanceRadius);
  const double wPlain = ProbedWeightedRms(v, plain, imp), wWeighted = ProbedWeightedRms(v, weighted, imp);
  EXPECT_NEAR(wWeighted, weighted.WeightedRms, 1e-6 + 1e-4 * weighted.WeightedRms); // the reducer's own figure
  EXPECT_LT(wWeighted, 0.8 * wPlain);
  EXPECT_GT(weighted.Rms, plain.Rms); // the price: a worse fit where it is not seen
}

TEST(OpacityImportance, DeterministicForAnyThreadCount)
{
  const int d[3] = { 40, 30, 30 };
  const auto v = Volume(d, [](double x, double y, double z) { return std::sin(0.2 * x) * std::cos(0.3 * y) + 0.01 * z; });
  art::ReducerOptions opt;
  opt.TargetTets = 4000;
  opt.ScalarOpacity = { { -1, 0 }, { 0, 0 }, { 0.5, 0.8 }, { 1, 0.2 } };
  const int before = art::GetThreadCount();
  art::SetThreadCount(1);
  const auto a = art::TetReducer(opt).Run(v).back();
  art::SetThreadCount(2);
  const auto b = art::TetReducer(opt).Run(v).back();
  art::SetThreadCount(before);
  EXPECT_EQ(a.Tets, b.Tets);
  EXPECT_EQ(a.Values, b.Values);
  EXPECT_EQ(a.WeightedRms, b.WeightedRms);
}

TEST(OpacityImportance, ReweighEqualsGatheringEveryTet)
{
  // A ball of 100 in air of 0, with opacity only over 40..70: most tets (air, ball) keep flat
  // weights when the fit moves a little, and Reweigh keeps their moments; tets whose fit moves
  // into the ramp must be gathered again. Either way every tet's moments must equal, bit for
  // bit, those a full gather at the new fit gives.
  const int d[3] = { 28, 26, 24 };
  const auto v = Volume(d, [](double x, double y, double z) {
    return (x - 13.2) * (x - 13.2) + (y - 12.4) * (y - 12.4) + (z - 11.1) * (z - 11.1) < 60 ? 100.0 : 0.0;
  });
  art::OpacityImportance imp({ { 40, 0 }, { 70, 0.6 } });
  imp.Prepare(v, 0.02, 2);
  art::BisectionMesh mesh;
  const int cubes[3] = { 3, 3, 3 };
  mesh.InitKuhn(v.Dims, cubes);
  std::vector<int> touched;
  for (int i = 0; i < 400; ++i)
  {
    mesh.Refine((i * 7919) % mesh.NumberOfTets(), touched);
  }
  std::vector<int> all(static_cast<size_t>(mesh.NumberOfTets()));
  std::iota(all.begin(), all.end(), 0);
  art::LeastSquaresFit kept(v, 0.5, &imp), full(v, 0.5, &imp);
  kept.UpdateMoments(mesh, all);
  std::vector<double> x;
  kept.Solve(mesh, x, 1e-8);
  kept.UpdateMoments(mesh, all, &x);
  // Move the fit: a little everywhere, into the ramp at every 7th vertex.
  std::vector<double> y = x;
  for (std::size_t i = 0; i < y.size(); ++i)
  {
    y[i] += i % 7 == 0 ? 55.0 - y[i] : 0.3 * std::sin(double(i));
  }
  const long long gathered = kept.Reweigh(mesh, y);
  full.UpdateMoments(mesh, all, &y);
  EXPECT_GT(gathered, 0);
  EXPECT_LT(gathered, mesh.NumberOfTets() / 2) << "most tets keep flat weights";
  for (int t = 0; t < mesh.NumberOfTets(); ++t)
  {
    const art::TetMoments &a = kept.Moments(t), &b = full.Moments(t);
    ASSERT_EQ(std::memcmp(a.M, b.M, sizeof a.M), 0) << t;
    ASSERT_EQ(std::memcmp(a.Bf, b.Bf, sizeof a.Bf), 0) << t;
    ASSERT_EQ(a.G, b.G) << t;
    ASSERT_EQ(a.MeanWeight, b.MeanWeight) << t;
    ASSERT_EQ(a.Count, b.Count) << t;
  }
  // A refined tet is always gathered again: its old moments belong to its parent.
  mesh.Refine(0, touched);
  art::LeastSquaresFit::Extend(mesh, y);
  EXPECT_GE(kept.Reweigh(mesh, y), 2);
}

TEST(OpacityImportance, BadOpacityInputIsAClearError)
{
  EXPECT_THROW(art::OpacityImportance({}), art::Error);
  EXPECT_THROW(art::OpacityImportance({ { 0, 0 }, { 1, 0.5 }, { 0.5, 1 } }), art::Error); // not monotone
  EXPECT_THROW(art::OpacityImportance({ { 0, 0 }, { 0, 0.5 } }), art::Error);             // repeated scalar
  EXPECT_THROW(art::OpacityImportance({ { 0, 0 }, { std::nan(""), 0.5 } }), art::Error);
  EXPECT_THROW(art::OpacityImportance({ { 0, -0.1 }, { 1, 0.5 } }), art::Error);
  const int d[3] = { 8, 8, 8 };
  const auto v = Volume(d, [](double x, double, double) { return x; });
  art::ReducerOptions opt;
  opt.TargetTets = 100;
  opt.ScalarOpacity = { { 0, 0 }, { 5, 0.5 }, { 3, 1 } };
  try
  {
    art::TetReducer(opt).Run(v);
    FAIL() << "a non-monotone opacity function was accepted";
  }
  catch (const art::Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("strictly increase"), std::string::npos) << e.what();
  }
  opt.ScalarOpacity = { { 0, 0 }, { 5, 0.5 } };
  opt.ImportanceFloor = 0;
  EXPECT_THROW(art::TetReducer(opt).Run(v), art::Error);
}

TEST(OpacityImportance, IsoValuesWeighLikeTheSteepestRamp)
{
  art::OpacityImportance imp(HalfRamp);
  imp.SetIsoValues({ 0.25 });
  const int d[3] = { 8, 4, 4 };
  const auto v = Volume(d, [](double x, double, double) { return 0.05 * x; }); // 0 .. 0.35: all clear
  imp.Prepare(v, 0.05, 1);
  EXPECT_DOUBLE_EQ(imp.MaxSlope(0.2, 0.3), 2.0); // the iso-value counts as the ramp's slope
  EXPECT_DOUBLE_EQ(imp.MaxSlope(0.1, 0.2), 0.0);
  EXPECT_FLOAT_EQ(imp.Weight(1, 0.05, 0.05), 0.05); // 0 .. 0.1 around it: flat
  EXPECT_DOUBLE_EQ(imp.Weight(1, 0.05, 0.3), 1.0);  // a fit across the iso-value counts in full
  EXPECT_DOUBLE_EQ(imp.Weight(5, 0.25, 0.25), 1.0); // on the surface
  EXPECT_THROW(imp.SetIsoValues({ std::nan("") }), art::Error);

  // A ball whose surface (0.2) lies where the opacity is flat, beside ripples on the ramp that
  // draw the weighted refinement: reduced for the ramp alone the ball's voxels weigh the floor;
  // with the iso-value they weigh in full and its surface comes out in place.
  const int n[3] = { 64, 40, 40 };
  const auto ball = Volume(n, [](double x, double y, double z) {
    if (x >= 32)
    {
      return 0.8 + 0.2 * std::sin(0.45 * y) * std::sin(0.35 * z) * std::cos(0.3 * x);
    }
    const double r = std::sqrt((x - 15.5) * (x - 15.5) + (y - 18) * (y - 18) + (z - 21) * (z - 21));
    return r < 11 ? 0.4 : 0.0;
  });
  art::ReducerOptions opt;
  opt.TargetTets = 6000;
  opt.ScalarOpacity = HalfRamp;
  const auto without = art::TetReducer(opt).Run(ball).back();
  opt.IsoValues = { 0.2 };
  const auto with = art::TetReducer(opt).Run(ball).back();
  // Voxels whose fitted value is on the other side of 0.2 from their own: the surface misplaced.
  auto misplaced = [&](const art::ReducedMesh& m) {
    const auto fit = ProbedFit(ball, m);
    long long k = 0;
    for (long long i = 0; i < ball.NumberOfVoxels(); ++i)
    {
      k += i % n[0] < 28 && (ball.Value(i) > 0.2) != (fit->GetTuple1(i) > 0.2); // clear of the ripples' step
    }
    return k;
  };
  const long long mw = misplaced(with), mo = misplaced(without);
  EXPECT_LT(mw, 0.5 * mo) << mw << " vs " << mo;
}
