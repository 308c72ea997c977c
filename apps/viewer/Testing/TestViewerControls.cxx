// The viewer's logic without a window: command line, key bindings, scripts, and the background
// reduction worker (real reductions of an analytic field, progress, cancellation).
#include "Error.h"
#include "ReductionWorker.h"
#include "ViewerControls.h"
#include "ViewerOptions.h"
#include "ViewerScript.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <thread>

using namespace view;

namespace
{
ViewerOptions Parse(std::vector<std::string> a)
{
  return ParseOptions(a);
}

std::string WriteTemp(const std::string& name, const std::string& text)
{
  const std::string path = std::string(ART_TEST_OUTPUT) + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// A sphere-distance field on n^3 voxels: smooth, so the reducer refines near nothing in particular.
art::VoxelVolume Sphere(int n)
{
  art::VoxelVolume v;
  v.Dims[0] = v.Dims[1] = v.Dims[2] = n;
  v.Float.resize(static_cast<size_t>(n) * n * n);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double c = 0.5 * (n - 1);
        v.Float[(static_cast<size_t>(k) * n + j) * n + i] =
          static_cast<float>(std::sqrt((i - c) * (i - c) + (j - c) * (j - c) + (k - c) * (k - c)));
      }
  v.Validate();
  return v;
}
} // namespace

TEST(ViewerOptions, DefaultsAndValues)
{
  const ViewerOptions d = Parse({ "head.mha" });
  EXPECT_EQ(d.File, "head.mha");
  EXPECT_EQ(d.Width, 800);
  EXPECT_EQ(d.Height, 600);
  EXPECT_EQ(d.Tets, (std::vector<long long>{ 2000, 10000, 40000 }));
  const ViewerOptions o =
    Parse({ "--size=300x200", "--tets", "5000,1000,1000", "--screenshot", "o.png", "--tf", "ct-bone", "x.vtu" });
  EXPECT_EQ(o.Width, 300);
  EXPECT_EQ(o.Height, 200);
  EXPECT_EQ(o.Tets, (std::vector<long long>{ 1000, 5000 })); // sorted, repeats dropped
  EXPECT_EQ(o.Screenshot, "o.png");
  EXPECT_EQ(o.TransferFunction, "ct-bone");
  EXPECT_TRUE(o.TfGiven); // --tf on a triangle scene is refused, as adaptivert render does
  EXPECT_FALSE(d.TfGiven);
  EXPECT_TRUE(Parse({ "--help" }).Help);
}

TEST(ViewerOptions, ArrayAndPercentBudgets)
{
  const ViewerOptions o = Parse({ "--tets", "0.5%,4000,1%", "--array", "density", "head.mha" });
  EXPECT_EQ(o.Array, "density");
  EXPECT_EQ(o.Tets, (std::vector<long long>{ 4000 }));
  // 0.5% and 1% of the 884,736 voxels of the default CT, merged with the count, ascending.
  EXPECT_EQ(Budgets(o, 884736), (std::vector<long long>{ 4000, 4424, 8847 }));
  EXPECT_EQ(Budgets(Parse({ "--tets", "1%", "a.mha" }), 884736), (std::vector<long long>{ 8847 })); // no defaults
  EXPECT_THROW(Budgets(Parse({ "--tets", "0.001%", "a.mha" }), 1000), UsageError); // 0 tets
  EXPECT_THROW(Parse({ "--tets", "x%", "a.mha" }), UsageError);
  EXPECT_THROW(Parse({ "--array", "", "a.mha" }), UsageError);
}

TEST(ViewerOptions, UsageErrors)
{
  EXPECT_THROW(Parse({}), UsageError);
  EXPECT_THROW(Parse({ "a.mha", "b.mha" }), UsageError);
  EXPECT_THROW(Parse({ "--size", "300", "a.mha" }), UsageError);
  EXPECT_THROW(Parse({ "--size", "10x10", "a.mha" }), UsageError);
  EXPECT_THROW(Parse({ "--tets", "1000,5", "a.mha" }), UsageError);
  EXPECT_THROW(Parse({ "--tets", "abc", "a.mha" }), UsageError);
  EXPECT_THROW(Parse({ "--screenshot", "out.jpg", "a.mha" }), UsageError);
  EXPECT_THROW(Parse({ "--tf", "rainbow", "a.mha" }), UsageError);
  EXPECT_NO_THROW(Parse({ "--tf", "my/tf.txt", "a.mha" })); // a file, read at load time
  EXPECT_THROW(Parse({ "--offscreen", "a.mha" }), UsageError);
  EXPECT_THROW(Parse({ "a.mha", "--script" }), UsageError);
  EXPECT_THROW(Parse({ "--refinement", "octree", "a.mha" }), UsageError);
}

TEST(ViewerOptions, Refinement)
{
  EXPECT_EQ(Parse({ "a.mha" }).Refinement, "bisection");
  EXPECT_EQ(Parse({ "--refinement", "anisotropic", "a.mha" }).Refinement, "anisotropic");
  EXPECT_EQ(Parse({ "--refinement=edge", "a.mha" }).Refinement, "edge");
  // Anisotropic levels are each adapted anew (MMG3D), not relocated; the lattice ones are.
  const art::TransferFunction tf = art::TransferFunction::Preset("grey-ramp", 0, 1);
  const art::ReducerOptions a = ReductionWorker::ShowingWith(tf, "anisotropic");
  EXPECT_EQ(a.Refine, art::ReducerOptions::Refinement::Anisotropic);
  EXPECT_FALSE(a.RelocateVertices);
  EXPECT_FALSE(a.ScalarOpacity.empty());
  EXPECT_TRUE(ReductionWorker::ShowingWith(tf).RelocateVertices);
}

TEST(ViewerControls, LevelsStayInRange)
{
  ViewerState s;
  s.Level = 2;
  EXPECT_EQ(ApplyKey(s, ']', 3), KeyResult::Ignored);
  EXPECT_TRUE(s.FollowNewest);
  EXPECT_EQ(ApplyKey(s, '[', 3), KeyResult::LevelChanged);
  EXPECT_EQ(s.Level, 1);
  EXPECT_FALSE(s.FollowNewest); // a level the user picked is kept while new ones arrive
  EXPECT_EQ(ApplyKey(s, '1', 3), KeyResult::LevelChanged);
  EXPECT_EQ(s.Level, 0);
  EXPECT_EQ(ApplyKey(s, '[', 3), KeyResult::Ignored);
  EXPECT_EQ(ApplyKey(s, '4', 3), KeyResult::Ignored);
  EXPECT_EQ(s.Level, 0);
  ViewerState none;
  EXPECT_EQ(ApplyKey(none, ']', 0), KeyResult::Ignored);
}

TEST(ViewerControls, SettingsKeys)
{
  ViewerState s;
  s.IsoValue = 100;
  s.IsoStep = 10;
  EXPECT_EQ(ApplyKey(s, 'i', 1), KeyResult::Changed);
  EXPECT_TRUE(s.Iso);
  ApplyKey(s, 'i', 1);
  EXPECT_FALSE(s.Iso);
  ApplyKey(s, '+', 1);
  ApplyKey(s, '+', 1);
  ApplyKey(s, '-', 1);
  EXPECT_DOUBLE_EQ(s.IsoValue, 110);
  EXPECT_TRUE(s.Iso); // changing the value shows the surface
  // + and - stop at the data's range ('on at 3069.1' over data up to 2697, nothing drawn).
  s.IsoLo = 95;
  s.IsoHi = 125;
  for (int i = 0; i < 5; ++i)
  {
    ApplyKey(s, '+', 1);
  }
  EXPECT_DOUBLE_EQ(s.IsoValue, 125);
  for (int i = 0; i < 5; ++i)
  {
    ApplyKey(s, '-', 1);
  }
  EXPECT_DOUBLE_EQ(s.IsoValue, 95);
  s.IsoValue = 110;

  int n = 0;
  const double* steps = ErtSteps(&n);
  ASSERT_GE(n, 3);
  EXPECT_DOUBLE_EQ(s.Ert(), 0.99);
  bool sawOff = false;
  for (int i = 1; i < n; ++i)
  {
    ApplyKey(s, 't', 1);
    EXPECT_DOUBLE_EQ(s.Ert(), steps[i]);
    sawOff |= s.Ert() >= 1.0;
  }
  EXPECT_TRUE(sawOff);
  ApplyKey(s, 't', 1);
  EXPECT_DOUBLE_EQ(s.Ert(), 0.99); // wraps around

  EXPECT_EQ(ApplyKey(s, 'x', 1), KeyResult::Changed);
  EXPECT_TRUE(s.Trapezoid);
  EXPECT_EQ(ApplyKey(s, 'm', 1), KeyResult::Changed);
  EXPECT_TRUE(s.Edges);
  EXPECT_EQ(ApplyKey(s, 'c', 1), KeyResult::Changed);
  EXPECT_TRUE(s.Clip);
  EXPECT_FALSE(s.Shade);
  EXPECT_EQ(ApplyKey(s, 'l', 1), KeyResult::Changed);
  EXPECT_TRUE(s.Shade);
  const std::string help = HelpText(s, true);
  EXPECT_NE(help.find("lighting (shade): on"), std::string::npos) << help;
  EXPECT_NE(help.find("integrator: trapezoid"), std::string::npos) << help;
  EXPECT_NE(help.find("mesh edges: on"), std::string::npos) << help;
  EXPECT_NE(help.find("clipping plane: on"), std::string::npos) << help;
  EXPECT_NE(help.find("iso-surface: on at 110"), std::string::npos) << help;
  EXPECT_EQ(HelpText(s, false).find("iso"), std::string::npos); // a triangle scene has no tet controls

  EXPECT_EQ(ApplyKey(s, 's', 1), KeyResult::Screenshot);
  EXPECT_EQ(ApplyKey(s, 'r', 1), KeyResult::ResetCamera);
  EXPECT_EQ(ApplyKey(s, 'q', 1), KeyResult::Quit);
  EXPECT_EQ(ApplyKey(s, 'w', 1), KeyResult::Ignored); // VTK's wireframe key does nothing here
}

// The progress line said "reduced: 1 levels from one run" for one --tets level.
TEST(ViewerControls, ReducedTextCountsLevels)
{
  EXPECT_EQ(ReducedText(1), "reduced: 1 level from one run");
  EXPECT_EQ(ReducedText(3), "reduced: 3 levels from one run");
}

TEST(ViewerScript, ReadsEveryAction)
{
  const std::string path = WriteTemp("viewer-all.script",
    "# comment\n\nwait 0.5\nwait-reduction\nkey ]\nazimuth 30  # trailing comment\nelevation -10\n"
    "roll 5\nzoom 1.5\ndrag 40 -20\nscreenshot out.png\n");
  const auto s = ReadScript(path);
  ASSERT_EQ(s.size(), 9u);
  EXPECT_EQ(s[0].What, ScriptAction::Kind::Wait);
  EXPECT_DOUBLE_EQ(s[0].Value, 0.5);
  EXPECT_EQ(s[0].Line, 3);
  EXPECT_EQ(s[1].What, ScriptAction::Kind::WaitReduction);
  EXPECT_EQ(s[2].What, ScriptAction::Kind::Key);
  EXPECT_EQ(s[2].Text, "]");
  EXPECT_DOUBLE_EQ(s[3].Value, 30);
  EXPECT_DOUBLE_EQ(s[4].Value, -10);
  EXPECT_EQ(s[5].What, ScriptAction::Kind::Roll);
  EXPECT_EQ(s[6].What, ScriptAction::Kind::Zoom);
  EXPECT_EQ(s[7].What, ScriptAction::Kind::Drag);
  EXPECT_DOUBLE_EQ(s[7].Value2, -20);
  EXPECT_EQ(s[8].Text, "out.png");
}

// A screenshot's name is the rest of its line, spaces and non-ASCII letters included; it was cut at
// the first space ("line 1: unexpected 'view'"). Blanks and a CRLF's CR around it are dropped.
TEST(ViewerScript, ScreenshotNameWithSpaces)
{
  const auto s = ReadScript(WriteTemp("viewer-spaces.script",
    "screenshot my view \xC3\xA9.png\nscreenshot \t out dir/b.png  \r\nscreenshot c.png # a comment\n"));
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].Text, "my view \xC3\xA9.png");
  EXPECT_EQ(s[1].Text, "out dir/b.png");
  EXPECT_EQ(s[2].Text, "c.png");
}

// A script saved by a Windows editor: a UTF-8 byte-order mark before the first action (it was
// "unknown action '\xEF\xBB\xBFkey'") and CRLF line ends.
TEST(ViewerScript, ByteOrderMarkAndCrlf)
{
  const auto s = ReadScript(WriteTemp("viewer-bom.script", "\xEF\xBB\xBFkey h\r\nazimuth 30\r\n"));
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].What, ScriptAction::Kind::Key);
  EXPECT_EQ(s[0].Text, "h");
  EXPECT_DOUBLE_EQ(s[1].Value, 30);
}

TEST(ViewerScript, MalformedLinesNameFileAndLine)
{
  const char* bad[] = { "jump 3\n", "wait\n", "wait -1\n", "zoom 0\n", "key ab\n", "azimuth 30 40\n", "drag 5\n",
    "screenshot\n" };
  for (const char* text : bad)
  {
    const std::string path = WriteTemp("viewer-bad.script", std::string("wait 0\n") + text);
    try
    {
      ReadScript(path);
      ADD_FAILURE() << "accepted: " << text;
    }
    catch (const art::Error& e)
    {
      EXPECT_NE(std::string(e.what()).find("viewer-bad.script: line 2: "), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(ReadScript(std::string(ART_TEST_OUTPUT) + "/no-such.script"), art::Error);
  // A folder opened as an empty script: nothing ran and nothing was said.
  EXPECT_THROW(ReadScript(ART_TEST_OUTPUT), art::Error);
}

namespace
{
// Runs w to the end (failing the test after 60 s): its levels, its last status, and whether its
// progress fraction never went back.
struct WorkerRun
{
  std::vector<art::ReducedMesh> levels;
  ReductionWorker::Status status;
  bool monotone = true;
};
WorkerRun RunToEnd(ReductionWorker& w)
{
  w.Start();
  WorkerRun run;
  double lastFraction = 0;
  const auto t0 = std::chrono::steady_clock::now();
  do
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    run.status = w.Poll();
    run.monotone &= run.status.Fraction >= lastFraction;
    lastFraction = run.status.Fraction;
    for (auto& m : w.TakeLevels())
    {
      run.levels.push_back(std::move(m));
    }
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 60.0);
  } while (!run.status.Finished);
  for (auto& m : w.TakeLevels())
  {
    run.levels.push_back(std::move(m));
  }
  EXPECT_TRUE(run.status.Error.empty()) << run.status.Error;
  return run;
}
} // namespace

TEST(ReductionWorker, DeliversNestedLevelsWithProgress)
{
  ReductionWorker w(Sphere(24), { 100, 400, 1500 });
  const WorkerRun run = RunToEnd(w);
  const auto& levels = run.levels;
  EXPECT_TRUE(run.monotone);
  EXPECT_DOUBLE_EQ(run.status.Fraction, 1.0);
  EXPECT_EQ(run.status.LevelsReady, 3);
  ASSERT_EQ(levels.size(), 3u);
  const long long budgets[] = { 100, 400, 1500 };
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_GE(levels[i].NumberOfTets(), budgets[i]);
    EXPECT_LT(levels[i].NumberOfTets(), budgets[i] * 1.25);
  }
  EXPECT_GT(levels[0].Rms, levels[2].Rms); // finer levels fit better
}

// The viewer reduces as `render` does: weighted by the transfer function's opacity (here a shell
// at distance 6-8 of the sphere field), then relocated, which fits that shell better than the
// weighted lattice fit at the same tets. Unweighted options (the viewer before) gave plain levels.
TEST(ReductionWorker, ReducesForTheTransferFunctionShown)
{
  using Node = art::TransferFunction::Node;
  const art::TransferFunction tf({ Node{ 5, { 1, 1, 1 }, 0, 0 }, Node{ 6, { 1, 1, 1 }, 0.8, 0 },
    Node{ 8, { 1, 1, 1 }, 0.8, 0 }, Node{ 9, { 1, 1, 1 }, 0, 0 } });
  const art::ReducerOptions shown = ReductionWorker::ShowingWith(tf);
  art::ReducerOptions lattice = shown;
  lattice.RelocateVertices = false;
  ReductionWorker a(Sphere(24), { 800 }, shown), b(Sphere(24), { 800 }, lattice);
  const auto relocated = RunToEnd(a).levels, onLattice = RunToEnd(b).levels;
  ASSERT_EQ(relocated.size(), 1u);
  ASSERT_EQ(onLattice.size(), 1u);
  EXPECT_TRUE(relocated[0].Weighted);
  EXPECT_EQ(relocated[0].NumberOfTets(), onLattice[0].NumberOfTets());
  EXPECT_LT(relocated[0].WeightedRms, 0.9 * onLattice[0].WeightedRms)
    << relocated[0].WeightedRms << " vs " << onLattice[0].WeightedRms;
}

TEST(ReductionWorker, DeliversAnisotropicLevels)
{
  // Levels made by MMG3D, each within 5% of its budget, with a progress that only rises.
  ReductionWorker w(Sphere(24), { 1000, 2500 },
    ReductionWorker::ShowingWith(art::TransferFunction::Preset("grey-ramp", 0, 21), "anisotropic"));
  const WorkerRun run = RunToEnd(w);
  ASSERT_EQ(run.levels.size(), 2u);
  EXPECT_TRUE(run.monotone);
  for (const auto& m : run.levels)
  {
    EXPECT_EQ(m.Refinement, "anisotropic");
    EXPECT_FALSE(m.Nested);
    EXPECT_LE(std::fabs(double(m.NumberOfTets() - m.TargetTets)), 0.05 * m.TargetTets) << m.NumberOfTets();
  }
}

TEST(ReductionWorker, DestroyingCancelsPromptly)
{
  const auto t0 = std::chrono::steady_clock::now();
  {
    ReductionWorker w(Sphere(48), { 600000 });
    w.Start();
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    EXPECT_FALSE(w.Poll().Finished);
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 5.0); // uncancelled: ~20 s
}

TEST(ReductionWorker, BadBudgetIsReportedNotThrown)
{
  ReductionWorker w(Sphere(8), { 3 });
  w.Start();
  ReductionWorker::Status st;
  while (!(st = w.Poll()).Finished)
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_NE(st.Error.find("at least 6"), std::string::npos) << st.Error;
}
