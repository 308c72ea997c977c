// The segment integrators against closed forms, additivity (exact for any split) and the
// transfer function's conversions and error handling.
#include "Error.h"
#include "ExactIntegrator.h"
#include "TransferFunction.h"

#include <gtest/gtest.h>
#include <vtkColorTransferFunction.h>
#include <vtkNew.h>
#include <vtkPiecewiseFunction.h>
#include <vtkVolumeProperty.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <utility>
#include <vector>

using namespace art;

namespace
{
// Closed form for constant extinction and linear colour.
// C = c0 (1 - J) + c1 (J - T), J = (1 - e^-D) / D, in long double, by series below D = 1.
void ConstantTau(const double c0[3], const double c1[3], double tau, double l, double C[3], double& T)
{
  const long double D = (long double)tau * l;
  long double oneMinusJ = 0, jMinusT = 0;
  if (D < 1)
  {
    long double term = 1; // (-D)^n / (n+1)!
    for (int n = 1; n < 60; ++n)
    {
      term *= -D / (n + 1);
      oneMinusJ -= term;
      jMinusT -= n * term;
    }
  }
  else
  {
    const long double J = (1 - std::exp(-D)) / D;
    oneMinusJ = 1 - J;
    jMinusT = J - std::exp(-D);
  }
  T = double(std::exp(-D));
  for (int k = 0; k < 3; ++k)
    C[k] = double(c0[k] * oneMinusJ + c1[k] * jMinusT);
}
} // namespace

TEST(Integrators, LinearPieceMatchesClosedFormThinToThick)
{
  const double c0[3] = { 0.1, 0.9, 0.5 }, c1[3] = { 0.8, 0.2, 0.5 };
  for (double l : { 1e-9, 1e-6, 1e-3, 0.01, 0.3, 1.0, 7.0, 50.0, 1e3 })
  {
    double C[3], T, Ce[3], Te;
    IntegrateLinearPiece(c0, c1, 0.7, 0.7, l, C, T);
    ConstantTau(c0, c1, 0.7, l, Ce, Te);
    EXPECT_NEAR(T, Te, 1e-15 + 1e-13 * Te) << l;
    for (int k = 0; k < 3; ++k)
    {
      // Relative to the emitted amount: thin pieces must be as good as thick ones.
      EXPECT_NEAR(C[k], Ce[k], 1e-12 * (1 - Te) + 1e-300) << "l " << l << " ch " << k;
    }
  }
}

TEST(Integrators, RulePieceWithinItsBoundOfThePreciseOne)
{
  // The rule's piece (Gauss-Lobatto with the inline exponential, the closed form past a slope of
  // 6) against the piece to round-off, from thin to opaque, rising, falling and constant
  // extinction: within 2.4e-9 in colour and transmittance, as the rule states.
  const double c0[3] = { 0.1, 0.9, 0.5 }, c1[3] = { 0.8, 0.2, 1.0 };
  double worst = 0;
  int n = 0;
  for (double slope = 1e-9; slope < 60; slope *= 1.37)
  {
    for (double ratio : { 0.0, 0.1, 0.5, 0.9, 1.0, 1.1, 2.0, 10.0, 1e9 })
    {
      const double tau0 = ratio < 1 ? slope : slope / ratio, tau1 = ratio < 1 ? slope * ratio : slope;
      double C[3], T, Cp[3], Tp;
      IntegrateLinearPieceFast(c0, c1, tau0, tau1, 1.0, C, T);
      IntegrateLinearPiece(c0, c1, tau0, tau1, 1.0, Cp, Tp);
      worst = std::max(worst, std::fabs(T - Tp));
      for (int k = 0; k < 3; ++k)
        worst = std::max(worst, std::fabs(C[k] - Cp[k]));
      ++n;
    }
  }
  EXPECT_GT(n, 500);
  EXPECT_LE(worst, 2.4e-9);
  EXPECT_GT(worst, 1e-13) << "the quadrature is not round-off: the comparison sees it";
}

TEST(Integrators, DawsonMatchesReferenceValues)
{
  // 17-digit values from mpmath (sqrt(pi)/2 exp(-x^2) erfi(x)), across the table and the asymptotic
  // branch at 8; the maximum sits at 0.924.
  const double ref[][2] = { { 0.001, 0.0009999993333336 }, { 0.5, 0.4244363835020223 },
    { 0.9241388730, 0.5410442246351817 }, { 1, 0.53807950691276842 }, { 2, 0.30134038892379197 },
    { 3.5, 0.14962159308075648 }, { 5, 0.10213407442427684 }, { 7.96, 0.063321974780393548 },
    { 8.04, 0.062681703477882058 }, { 20, 0.025031367926403672 }, { 10000, 5.0000000250000004e-5 } };
  for (const auto& r : ref)
  {
    EXPECT_NEAR(Dawson(r[0]), r[1], 4e-15 * r[1]) << r[0];
    EXPECT_EQ(Dawson(-r[0]), -Dawson(r[0]));
  }
  EXPECT_EQ(Dawson(0.0), 0.0);
}

TEST(Integrators, ErfcxMatchesReferenceValues)
{
  // exp(x^2) erfc(x) from mpmath, across the table and the asymptotic branch at 8.
  const double ref[][2] = { { 0, 1.0 }, { 0.001, 0.99887262008115141 }, { 0.5, 0.61569034419292587 },
    { 1, 0.427583576155807 }, { 2, 0.25539567631050574 }, { 3.7, 0.14743499753718508 },
    { 7.96, 0.070331519699245948 }, { 8.04, 0.069642182711432696 }, { 20, 0.028174348741051319 },
    { 1000, 0.00056418930145338765 } };
  for (const auto& r : ref)
  {
    EXPECT_NEAR(Erfcx(r[0]), r[1], 4e-15 * r[1]) << r[0];
  }
}

TEST(Integrators, LinearPieceIsAdditive)
{
  // Exactness means any split composites to the same result, for rising and falling extinction.
  const double c0[3] = { 0.2, 0.4, 1.0 }, c1[3] = { 0.9, 0.1, 0.3 };
  for (double scale : { 1e-6, 1e-2, 1.0, 30.0 })
  {
    for (auto taus : { std::pair<double, double>{ 0.0, 2.0 }, { 3.0, 0.5 }, { 1.0, 1.0 } })
    {
      const double t0 = taus.first * scale, t1 = taus.second * scale, l = 2.0;
      double C[3], T;
      IntegrateLinearPiece(c0, c1, t0, t1, l, C, T);
      double acc[3] = { 0, 0, 0 }, Tacc = 1;
      const int n = 37;
      for (int i = 0; i < n; ++i)
      {
        const double a = double(i) / n, b = double(i + 1) / n;
        double ca[3], cb[3], P[3], Tp;
        for (int k = 0; k < 3; ++k)
        {
          ca[k] = c0[k] + a * (c1[k] - c0[k]);
          cb[k] = c0[k] + b * (c1[k] - c0[k]);
        }
        IntegrateLinearPiece(ca, cb, t0 + a * (t1 - t0), t0 + b * (t1 - t0), l / n, P, Tp);
        for (int k = 0; k < 3; ++k)
          acc[k] += Tacc * P[k];
        Tacc *= Tp;
      }
      EXPECT_NEAR(T, Tacc, 1e-13);
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(C[k], acc[k], 1e-12 * (1 - T) + 1e-300) << scale << " " << t0 << " " << t1;
    }
  }
}

TEST(Integrators, ExactSplitsAtControlPoints)
{
  // A narrow opacity spike inside one long segment: the exact rule sees it, the trapezoid rule
  // (ends only) does not; integrating in one call equals integrating in many small calls.
  TransferFunction tf({ { 0, { 0, 0, 0 }, 0.0, 0 }, { 0.49, { 1, 0, 0 }, 0.0, 0 }, { 0.5, { 1, 0.5, 0 }, 0.9, 0 },
                        { 0.51, { 1, 1, 0 }, 0.0, 0 }, { 1, { 1, 1, 1 }, 0.0, 0 } },
    0.01);
  ExactIntegrator ex(tf);
  TrapezoidRule tr(tf);
  RayAccum one, many, trap;
  ex.Integrate(0.0, 1.0, 1.0, one);
  for (int i = 0; i < 1000; ++i)
    ex.Integrate(i / 1000.0, (i + 1) / 1000.0, 1e-3, many);
  tr.Integrate(0.0, 1.0, 1.0, trap);
  EXPECT_GT(one.Alpha(), 0.5);
  EXPECT_NEAR(one.Alpha(), many.Alpha(), 1e-12);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(one.rgb[k], many.rgb[k], 1e-12);
  EXPECT_EQ(trap.Alpha(), 0.0);
  // Falling scalar too.
  RayAccum down, downMany;
  ex.Integrate(1.0, 0.0, 1.0, down);
  for (int i = 0; i < 1000; ++i)
    ex.Integrate(1.0 - i / 1000.0, 1.0 - (i + 1) / 1000.0, 1e-3, downMany);
  EXPECT_NEAR(down.rgb[0], downMany.rgb[0], 1e-12);
}

TEST(TransferFunction, TransparentRanges)
{
  // Extinction only between 0.3 and 0.6 (0 at both nodes' outsides), and again above 2.
  TransferFunction tf({ { 0, { 1, 1, 1 }, 0.0, 0 }, { 0.3, { 1, 1, 1 }, 0.0, 0 }, { 0.45, { 1, 1, 1 }, 0.5, 0 },
                        { 0.6, { 1, 1, 1 }, 0.0, 0 }, { 1, { 1, 1, 1 }, 0.0, 0 }, { 2, { 1, 1, 1 }, 0.2, 0 } });
  EXPECT_TRUE(tf.Transparent(-5.0, 0.29));
  EXPECT_TRUE(tf.Transparent(0.29, 0.0));
  EXPECT_FALSE(tf.Transparent(0.2, 0.35));
  EXPECT_FALSE(tf.Transparent(0.0, 0.9)); // passes through the opaque band
  EXPECT_FALSE(tf.Transparent(0.9, 0.0));
  EXPECT_TRUE(tf.Transparent(0.61, 0.99));
  EXPECT_FALSE(tf.Transparent(1.5, 1.6)); // extinction rises from 1 to 2
  EXPECT_FALSE(tf.Transparent(5.0, 6.0)); // above the last node its value holds
  TransferFunction one({ { 0.5, { 1, 1, 1 }, 0.0, 0 } });
  EXPECT_TRUE(one.Transparent(-1.0, 3.0));
  // By intervals, exactly (no buckets), as the segment rules test it.
  auto clear = [&](double a, double b) { return tf.TransparentIntervals(tf.Locate(a), tf.Locate(b)); };
  EXPECT_TRUE(clear(-5.0, 0.29));
  EXPECT_FALSE(clear(-5.0, 0.3)); // a node's interval is the one above it: conservative there
  EXPECT_FALSE(clear(0.2, 0.3001));
  EXPECT_TRUE(clear(0.6, 0.99));
  EXPECT_TRUE(clear(0.99, 0.6));
  EXPECT_FALSE(clear(0.59, 0.99));
  EXPECT_FALSE(clear(0.0, 5.0));
  EXPECT_FALSE(clear(7.0, 9.0));
  EXPECT_TRUE(one.TransparentIntervals(one.Locate(-1.0), one.Locate(3.0)));
  // LocateFrom gives Locate's interval whatever the guess.
  for (double s : { -1.0, 0.0, 0.1, 0.3, 0.45, 0.6, 0.99, 1.0, 1.5, 2.0, 3.0 })
    for (int i = -1; i < 6; ++i)
      EXPECT_EQ(tf.LocateFrom(s, i), tf.Locate(s)) << s << " " << i;
}

TEST(TransferFunction, LocateFromNeighboursAgreeWithLocate)
{
  // LocateFrom's guess, the neighbours it tries next and the table behind them give Locate's
  // interval for scalars on, next to and between the nodes, beyond the ends and infinite, from
  // every guess: the segment rules take the interval from it.
  TransferFunction tf({ { -1000, { 0, 0, 0 }, 0.0, 0 }, { -600, { 1, 0, 0 }, 0.0, 0 }, { -450, { 1, 1, 0 }, 0.1, 0 },
                        { -300, { 0, 1, 0 }, 0.0, 0 }, { 200, { 0, 1, 1 }, 0.0, 0 }, { 450, { 0, 0, 1 }, 0.3, 0 },
                        { 1200, { 1, 1, 1 }, 0.7, 0 } });
  std::vector<double> s = { -HUGE_VAL, HUGE_VAL, -1e300, 1e300 };
  for (const auto& n : tf.Nodes())
  {
    s.push_back(n.s), s.push_back(std::nextafter(n.s, -HUGE_VAL)), s.push_back(std::nextafter(n.s, HUGE_VAL));
  }
  for (int k = 0; k <= 4000; ++k)
  {
    s.push_back(-1500.0 + 3000.0 * k / 4000.0);
  }
  const int n = static_cast<int>(tf.Nodes().size());
  int neighbours = 0;
  for (double v : s)
  {
    const int at = tf.Locate(v);
    for (int i = -1; i < n; ++i)
    {
      ASSERT_EQ(tf.LocateFrom(v, i), at) << v << " from " << i;
      neighbours += std::abs(at - i) == 1;
    }
  }
  EXPECT_GT(neighbours, 6000); // guesses one interval off, the case LocateFrom tries second
  TransferFunction one({ { 0.5, { 1, 1, 1 }, 0.2, 0 } });
  for (double v : { -HUGE_VAL, 0.0, 0.5, 1.0, HUGE_VAL })
    for (int i = -1; i < 1; ++i)
      EXPECT_EQ(one.LocateFrom(v, i), one.Locate(v)) << v << " from " << i;
}

TEST(Integrators, TrapezoidConvergesToExact)
{
  TransferFunction tf = TransferFunction::Preset("grey-ramp", 0, 1);
  ExactIntegrator ex(tf);
  TrapezoidRule tr(tf);
  RayAccum e, t1, t2;
  ex.Integrate(0.1, 0.9, 5.0, e);
  tr.Integrate(0.1, 0.9, 5.0, t1);
  for (int i = 0; i < 64; ++i)
    tr.Integrate(0.1 + 0.8 * i / 64, 0.1 + 0.8 * (i + 1) / 64, 5.0 / 64, t2);
  const double err1 = std::fabs(t1.rgb[0] - e.rgb[0]), err2 = std::fabs(t2.rgb[0] - e.rgb[0]);
  EXPECT_GT(err1, 1e-3);
  EXPECT_LT(err2, err1 / 100); // second order: 64x finer is ~4000x better
}

TEST(TransferFunction, OpacityToExtinctionAndVTKRoundTrip)
{
  vtkNew<vtkVolumeProperty> p;
  vtkNew<vtkColorTransferFunction> c;
  vtkNew<vtkPiecewiseFunction> o;
  c->AddRGBPoint(0, 0, 0, 1);
  c->AddRGBPoint(100, 1, 0, 0);
  o->AddPoint(0, 0.0);
  o->AddPoint(50, 0.5);
  o->AddPoint(100, 1.0);
  p->SetColor(c);
  p->SetScalarOpacity(o);
  p->SetScalarOpacityUnitDistance(2.0);
  const TransferFunction tf = TransferFunction::FromVTK(p);
  ASSERT_EQ(tf.Nodes().size(), 3u); // union of {0, 100} and {0, 50, 100}
  double rgb[3], tau;
  tf.Evaluate(50, rgb, tau);
  EXPECT_NEAR(rgb[0], 0.5, 1e-12);
  EXPECT_NEAR(rgb[2], 0.5, 1e-12);
  EXPECT_NEAR(tau, -std::log(0.5) / 2.0, 1e-12);
  tf.Evaluate(-10, rgb, tau); // clamped below
  EXPECT_EQ(tau, 0.0);
  vtkNew<vtkVolumeProperty> back;
  tf.ToVTK(back);
  EXPECT_NEAR(back->GetScalarOpacity()->GetValue(50), 0.5, 1e-12);
  EXPECT_EQ(back->GetScalarOpacityUnitDistance(), 2.0);
}

TEST(TransferFunction, FollowsVTKColourSpacesMidpointsAndSharpness)
{
  // ParaView's default: a diverging colour map (white in the middle, not RGB's purple), and an
  // opacity with a midpoint and some sharpness. The transfer function must match VTK's own
  // functions everywhere, not only at their nodes.
  vtkNew<vtkVolumeProperty> p;
  vtkNew<vtkColorTransferFunction> c;
  vtkNew<vtkPiecewiseFunction> o;
  c->SetColorSpaceToDiverging();
  c->AddRGBPoint(-1, 0.23, 0.30, 0.75);
  c->AddRGBPoint(1, 0.71, 0.02, 0.15);
  o->AddPoint(-1, 0.0, 0.25, 0.0);
  o->AddPoint(0.2, 0.6, 0.5, 0.6);
  o->AddPoint(1, 0.9);
  p->SetColor(c);
  p->SetScalarOpacity(o);
  const TransferFunction tf = TransferFunction::FromVTK(p);
  EXPECT_GT(tf.Nodes().size(), 6u);
  EXPECT_LE(tf.Nodes().size(), 3u + 2u * 256u);
  double worstRgb = 0, worstAlpha = 0;
  for (int i = 0; i <= 1000; ++i)
  {
    const double x = -1 + 2.0 * i / 1000;
    double want[3], rgb[3], tau;
    c->GetColor(x, want);
    tf.Evaluate(x, rgb, tau);
    for (int k = 0; k < 3; ++k)
      worstRgb = std::max(worstRgb, std::fabs(rgb[k] - want[k]));
    worstAlpha = std::max(worstAlpha, std::fabs(tf.Alpha(x) - o->GetValue(x)));
  }
  EXPECT_LT(worstRgb, 5e-3);
  EXPECT_LT(worstAlpha, 5e-3);
  // Plain RGB functions keep exactly their nodes.
  c->SetColorSpaceToRGB();
  vtkNew<vtkPiecewiseFunction> linear;
  linear->AddPoint(-1, 0.0);
  linear->AddPoint(1, 0.5);
  p->SetScalarOpacity(linear);
  EXPECT_EQ(TransferFunction::FromVTK(p).Nodes().size(), 2u);
}

TEST(TransferFunction, ParaViewPresetFiles)
{
  // What ParaView's preset "Export" writes: a list of one preset, diverging colours and an
  // opacity with a midpoint.
  const std::string dir = ART_TEST_OUTPUT;
  const std::string file = dir + "/tf-paraview.json";
  std::ofstream(file) << R"([ { "ColorSpace" : "Diverging", "Name" : "Cool to Warm", "NanColor" : [1, 1, 0],
    "Points" : [ -1000, 0, 0.5, 0, 200, 0.3, 0.25, 0, 1500, 0.8, 0.5, 0 ],
    "RGBPoints" : [ -1000, 0.23, 0.299, 0.754, 1500, 0.706, 0.016, 0.15 ] } ])";
  const TransferFunction tf = TransferFunction::FromFile(file);
  vtkNew<vtkColorTransferFunction> c;
  c->SetColorSpaceToDiverging();
  c->AddRGBPoint(-1000, 0.23, 0.299, 0.754);
  c->AddRGBPoint(1500, 0.706, 0.016, 0.15);
  vtkNew<vtkPiecewiseFunction> o;
  o->AddPoint(-1000, 0, 0.5, 0);
  o->AddPoint(200, 0.3, 0.25, 0);
  o->AddPoint(1500, 0.8, 0.5, 0);
  for (int i = 0; i <= 500; ++i)
  {
    const double x = -1000 + 5.0 * i;
    double want[3], rgb[3], tau;
    c->GetColor(x, want);
    tf.Evaluate(x, rgb, tau);
    for (int k = 0; k < 3; ++k)
      ASSERT_NEAR(rgb[k], want[k], 5e-3) << x;
    ASSERT_NEAR(tf.Alpha(x), o->GetValue(x), 5e-3) << x;
  }
  // Colour only: opacity ramps from 0 to 1 over the colour points.
  std::ofstream(file) << R"({ "Name" : "grey", "RGBPoints" : [ 0, 0, 0, 0, 10, 1, 1, 1 ] })";
  const TransferFunction grey = TransferFunction::FromFile(file);
  EXPECT_NEAR(grey.Alpha(2.5), 0.25, 1e-12);
  // Each malformed preset is one clear error naming the file.
  const std::pair<const char*, const char*> bad[] = {
    { R"([ { "RGBPoints" : [0, 0, 0, 0] }, { "RGBPoints" : [0, 0, 0, 0] } ])", "holds 2 presets" },
    { R"([ { "Name" : "cats", "IndexedColors" : [1, 0, 0] } ])", R"(no "RGBPoints")" },
    { R"({ "RGBPoints" : [0, 0, 0] })", "4 numbers per point" },
    { R"({ "RGBPoints" : [0, 0, 0, "red"] })", "other than finite numbers" },
    { R"({ "RGBPoints" : [0, 0, 0, 0], "ColorSpace" : "CMYK" })", R"(unknown "ColorSpace" 'CMYK')" },
    { R"({ "RGBPoints" : [0, 0, 0, 0 )", "not a ParaView preset (JSON)" },
  };
  for (const auto& [text, why] : bad)
  {
    std::ofstream(file) << text;
    try
    {
      TransferFunction::FromFile(file);
      ADD_FAILURE() << "accepted " << text;
    }
    catch (const Error& e)
    {
      EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("tf-paraview.json"), std::string::npos) << e.what();
    }
  }
}

TEST(TransferFunction, FileAndPresetErrors)
{
  const std::string dir = ART_TEST_OUTPUT;
  const std::string good = dir + "/tf-good.txt", bad = dir + "/tf-bad.txt";
  std::ofstream(good) << "# skin and bone\nunit-distance 2\n-1000 0 0 0 0\n0 1 0.5 0.5 0.2\n1000 1 1 1 0.9\n";
  std::ofstream(bad) << "0 0 0 0 0\n10 1 1 zero 1\n";
  const TransferFunction tf = TransferFunction::FromFile(good);
  EXPECT_EQ(tf.Nodes().size(), 3u);
  EXPECT_EQ(tf.UnitDistance(), 2.0);
  try
  {
    TransferFunction::FromFile(bad);
    FAIL() << "accepted a malformed line";
  }
  catch (const Error& e)
  {
    EXPECT_NE(std::string(e.what()).find("line 2"), std::string::npos) << e.what();
  }
  // Notepad's byte-order mark, a spreadsheet's CSV (commas, a header line, CRLF): the same nodes.
  const std::string csv = dir + "/tf-csv.txt", json = dir + "/tf-bom.json";
  std::ofstream(csv) << "\xEF\xBB\xBFscalar,r,g,b,opacity\r\n-1000,0,0,0,0\r\n0,1,0.5,0.5,0.2\r\n1000,1,1,1,0.9\r\n";
  const TransferFunction fromCsv = TransferFunction::FromFile(csv);
  ASSERT_EQ(fromCsv.Nodes().size(), 3u);
  for (std::size_t i = 0; i < 3; ++i)
  {
    EXPECT_EQ(fromCsv.Nodes()[i].s, tf.Nodes()[i].s);
    EXPECT_EQ(fromCsv.Nodes()[i].alpha, tf.Nodes()[i].alpha);
  }
  std::ofstream(json) << "\xEF\xBB\xBF{ \"RGBPoints\" : [ 0, 0, 0, 0, 10, 1, 1, 1 ] }";
  EXPECT_EQ(TransferFunction::FromFile(json).Nodes().size(), 2u);
  EXPECT_THROW(TransferFunction::FromFile(dir + "/no-such-tf.txt"), Error);
  EXPECT_THROW(TransferFunction::Preset("rainbow", 0, 1), Error);
  for (const auto& name : TransferFunction::PresetNames())
  {
    EXPECT_GE(TransferFunction::Preset(name, -1024, 3071).Nodes().size(), 2u) << name;
    // A constant field sits inside the preset, not at its clear end: it renders as a haze.
    EXPECT_GT(TransferFunction::Preset(name, 7, 7).Alpha(7), 0.01) << name;
  }
}

// The default preset: skin and bone on CT in Hounsfield units; on other data (an MRI in 0..231)
// the CT preset's opaque top fifth drew the bright scalp as an opaque white blob, so a grey ramp.
TEST(TransferFunction, AutoPresetPicksByTheData)
{
  auto same = [](const TransferFunction& a, const TransferFunction& b) {
    if (a.Nodes().size() != b.Nodes().size())
    {
      return false;
    }
    for (std::size_t i = 0; i < a.Nodes().size(); ++i)
    {
      if (a.Nodes()[i].s != b.Nodes()[i].s || a.Nodes()[i].alpha != b.Nodes()[i].alpha)
      {
        return false;
      }
    }
    return true;
  };
  EXPECT_TRUE(same(TransferFunction::Preset("auto", -1024, 2697), TransferFunction::Preset("ct-skin-bone", -1024, 2697)));
  EXPECT_TRUE(same(TransferFunction::Preset("auto", 0, 231), TransferFunction::Preset("grey-ramp", 0, 231)));
  EXPECT_FALSE(same(TransferFunction::Preset("auto", 0, 231), TransferFunction::Preset("ct-skin-bone", 0, 231)));
}

// The CT presets on data that are not in Hounsfield units sit at fractions of the range, so data
// scaled by any factor get the same function scaled: the top node added 1 data unit, which put it
// far past the data of a range below ~5 (an MRI normalised to 0..1), paler and more transparent.
TEST(TransferFunction, CTPresetsScaleWithNonCTData)
{
  for (const char* name : { "ct-skin-bone", "ct-bone" })
  {
    const TransferFunction a = TransferFunction::Preset(name, 0, 231);
    for (double k : { 1.0 / 255, 1e-6 })
    {
      const TransferFunction b = TransferFunction::Preset(name, 0, 231 * k);
      ASSERT_EQ(a.Nodes().size(), b.Nodes().size()) << name;
      for (std::size_t i = 0; i < a.Nodes().size(); ++i)
      {
        EXPECT_NEAR(b.Nodes()[i].s, a.Nodes()[i].s * k, 1e-12 * 231 * k) << name << " node " << i << " scale " << k;
      }
    }
  }
}
