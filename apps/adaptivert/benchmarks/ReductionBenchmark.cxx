// adaptivert bench reduction: the least-squares reducer's refinements at the paper's reduction
// levels on the real CT head, side by side (same run, same machine) with VTK's quadric
// decimation of the volume's tetrahedrisation at the same tet count and with uniform
// downsampling at the same vertex count: RMS and max error against the voxels, build time,
// peak memory; and each refinement timed alone to a share of the voxels as vertices.
#include "benchmarks/Bench.h"
#include "benchmarks/BenchUtil.h"
#include "cli/Command.h"

#ifdef ART_HAVE_Reduction
#include "benchmarks/ReductionBenchmark.h"
#include "DataLoader.h"
#include "Error.h"
#include "MeshQuality.h"
#include "ParallelTiles.h"
#include "ReducerVTK.h"
#include "ReductionBaselines.h"
#include "TetReducer.h"
#include "cli/ResourcePath.h"

#include <vtkImageData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Peak memory of one step: Linux lets a process reset its high-water mark (clear_refs 5). The
// peak is the process's, input volume included, as a user sees it.
double PeakMB()
{
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
  {
    if (line.rfind("VmHWM:", 0) == 0)
    {
      return std::atoll(line.c_str() + 6) / 1024.0;
    }
  }
  return 0;
}
void ResetPeak()
{
  std::ofstream("/proc/self/clear_refs") << "5";
}

// "N" or "P%" of `of`, each item of a comma-separated list.
std::vector<long long> ParseList(const std::string& list, long long of, const char* what)
{
  std::vector<long long> out;
  std::stringstream ss(list);
  std::string s;
  while (std::getline(ss, s, ','))
  {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (!(v >= 0) || end == s.c_str() || (*end && !(*end == '%' && end[1] == 0)))
    {
      throw cli::UsageError(std::string(what) + " wants numbers or percentages, got '" + s + "'");
    }
    const long long n = *end == '%' ? std::llround(v / 100.0 * of) : std::llround(v);
    if (n > 0)
    {
      out.push_back(n);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

art::ReducerOptions SeriesOptions(const std::string& name)
{
  art::ReducerOptions o;
  if (name == "relocated")
  {
    o.RelocateVertices = true;
  }
  else if (name == "edge")
  {
    o.Refine = art::ReducerOptions::Refinement::EdgeSplit;
  }
  else if (name == "anisotropic")
  {
    o.Refine = art::ReducerOptions::Refinement::Anisotropic;
  }
  else if (name != "bisection")
  {
    throw cli::UsageError("--red-series takes bisection, relocated, edge and anisotropic, got '" + name + "'");
  }
  return o;
}

void Declare(cli::Options& o)
{
  o.Add("red-input", 0, "FILE", "reduction: the volume (data/fetch gives the full CT in data/full/ct-head.mha)",
    cli::DataDir() + "/ct-head-128.mha");
  o.Add("red-levels", 0, "LIST", "reduction: budgets, % of the voxel count or tets",
    "0.01%,0.03%,0.05%,0.1%,0.2%,1%");
  o.Add("red-series", 0, "LIST", "reduction: the refinements compared (bisection, relocated, edge, anisotropic)",
    "bisection,relocated,anisotropic");
  o.Add("red-timed-vertices", 0, "LIST",
    "reduction: also time each series alone to these vertex counts (or % of the voxels; 0: skip)", "1%");
  o.Add("red-no-quadric", 0, "", "reduction: skip VTK's quadric decimation (slow on big volumes)");
}

// A run's meshes measured: quality and uniform downsampling at their vertex counts.
cli::ReductionRow Measure(const art::ReducedMesh& m, const art::VoxelVolume& volume, long long level)
{
  cli::ReductionRow w;
  w.level = level;
  w.tets = m.NumberOfTets();
  w.vertices = m.NumberOfVertices();
  w.rms = m.Rms;
  w.max = m.Max;
  const art::QualityReport q = art::MeasureQuality(m.Points.data(), m.NumberOfVertices(), m.Tets.data(), m.NumberOfTets());
  w.minDihedral = q.MinDihedralDegrees;
  w.minRadiusRatio = q.MinRadiusRatio;
  w.meanRadiusRatio = q.MeanRadiusRatio;
  const art::BaselineError u = art::UniformDownsampleError(volume, w.vertices);
  w.uniformVertices = u.Vertices;
  w.uniformRms = u.Rms;
  w.uniformMax = u.Max;
  return w;
}

// One series: its levels in one run (timed `runs` times after a warm-up), then a run alone to
// each vertex count, its tets from the tets per vertex of the series' largest level.
cli::ReductionSeries RunSeries(const std::string& name, const art::VoxelVolume& volume,
  const std::vector<long long>& levels, const std::vector<long long>& timedVertices, int runs)
{
  cli::ReductionSeries s;
  s.name = name;
  art::ReducerOptions opt = SeriesOptions(name);
  opt.Levels = levels;
  std::vector<std::vector<double>> times(levels.size());
  std::vector<double> peaks;
  std::vector<art::ReducedMesh> meshes;
  for (int r = 0; r <= runs; ++r)
  {
    ResetPeak();
    meshes = art::TetReducer(opt).Run(volume);
    if (r > 0) // r == 0 is the warm-up
    {
      peaks.push_back(PeakMB());
      for (size_t i = 0; i < meshes.size() && i < levels.size(); ++i)
      {
        times[i].push_back(meshes[i].BuildSeconds);
      }
    }
  }
  s.peakMB = cli::Summarise(peaks);
  for (size_t i = 0; i < levels.size() && i < meshes.size(); ++i)
  {
    cli::ReductionRow w = Measure(meshes[i], volume, levels[i]);
    w.seconds = cli::Summarise(times[i]);
    std::fprintf(stderr, "  %-11s %8lld tets %7lld verts  RMS %8.3f (uniform %8.3f: %.2fx)  %.2f s\n", name.c_str(),
      w.tets, w.vertices, w.rms, w.uniformRms, w.rms / w.uniformRms, w.seconds.median);
    s.levels.push_back(w);
  }
  const double tetsPerVertex = meshes.empty() ? 5.5 : double(meshes.back().NumberOfTets()) / meshes.back().NumberOfVertices();
  for (long long v : timedVertices)
  {
    art::ReducerOptions t = SeriesOptions(name);
    t.TargetTets = std::llround(v * tetsPerVertex);
    std::vector<double> secs, peak;
    art::ReducedMesh m;
    for (int r = 0; r <= runs; ++r)
    {
      ResetPeak();
      auto out = art::TetReducer(t).Run(volume);
      if (r > 0)
      {
        secs.push_back(out.back().BuildSeconds);
        peak.push_back(PeakMB());
      }
      m = std::move(out.back());
    }
    cli::ReductionRow w = Measure(m, volume, t.TargetTets);
    w.seconds = cli::Summarise(secs);
    s.timed.push_back(w);
    s.timedPeakMB.push_back(cli::Summarise(peak));
    std::fprintf(stderr, "  %-11s timed: %lld tets %lld verts (%.2f%% of the voxels)  RMS %.3f (uniform %.3f: %.2fx)  %.2f s  peak %.0f MB\n",
      name.c_str(), w.tets, w.vertices, 100.0 * w.vertices / volume.NumberOfVoxels(), w.rms, w.uniformRms,
      w.rms / w.uniformRms, w.seconds.median, s.timedPeakMB.back().median);
  }
  return s;
}

// Quadric decimation of the full tetrahedrisation, chained from the largest level down (each
// level decimated from the previous result, as nested as the bisection's). One run: it is slow.
// Like for like, `first` (the first series' options) is also reduced to the quadric's own tet
// count and measured on the voxels the quadric's output covers.
void RunQuadric(vtkImageData* image, const art::VoxelVolume& volume, const std::vector<long long>& tets,
  const art::ReducerOptions& first, cli::ReductionResults& r)
{
  ResetPeak();
  auto t0 = Clock::now();
  vtkSmartPointer<vtkUnstructuredGrid> grid = art::TetrahedralizeVolume(image);
  r.quadricTetrahedralizeSeconds = Seconds(t0);
  r.quadricInputTets = grid->GetNumberOfCells();
  std::fprintf(stderr, "  quadric  input %lld tets (%.1f s)\n", r.quadricInputTets, r.quadricTetrahedralizeSeconds);
  double cumulative = r.quadricTetrahedralizeSeconds;
  r.quadricRows.assign(tets.size(), {});
  for (size_t i = tets.size(); i-- > 0;)
  {
    cli::QuadricRow& q = r.quadricRows[i];
    t0 = Clock::now();
    grid = art::QuadricDecimate(grid, tets[i], volume.Name.c_str());
    cumulative += Seconds(t0);
    std::vector<char> covered;
    const art::BaselineError e = art::ProbeError(image, grid, volume.Name.c_str(), &covered);
    q.tets = e.Tets;
    q.vertices = e.Vertices;
    q.rms = e.Rms;
    q.max = e.Max;
    q.uncovered = e.Uncovered;
    q.coveredRms = e.CoveredRms;
    q.inverted = art::MeasureQuality(grid).Inverted;
    q.seconds = cumulative;
    art::ReducerOptions at = first;
    at.TargetTets = q.tets;
    const auto same = art::TetReducer(at).Run(volume);
    const art::BaselineError oe =
      art::ProbeError(image, art::ToUnstructuredGrid(same.back(), true), volume.Name.c_str(), nullptr, &covered);
    q.oursTets = same.back().NumberOfTets();
    q.oursCoveredRms = oe.Rms;
    std::fprintf(stderr, "  quadric  %8lld tets  RMS %8.3f  max %8.1f  %.1f s (%lld voxels uncovered); ours there %.3f\n",
      q.tets, q.rms, q.max, q.seconds, q.uncovered, q.oursCoveredRms);
  }
  r.quadricPeakMB = PeakMB();
}

int Run(const cli::Options& o)
{
  const std::string in = o.Get("red-input");
  const int runs = std::max(1, static_cast<int>(o.GetInt("runs")));
  const std::filesystem::path dir = o.Get("results");
  std::filesystem::create_directories(dir);
  std::vector<std::string> names;
  {
    std::stringstream ss(o.Get("red-series"));
    std::string s;
    while (std::getline(ss, s, ','))
    {
      SeriesOptions(s); // a usage error before any work
      names.push_back(s);
    }
  }
  if (names.empty())
  {
    throw cli::UsageError("--red-series is empty");
  }
  auto image = art::LoadVolume(in);
  const art::VoxelVolume volume = art::VolumeFromImage(image, in);
  cli::ReductionResults r;
  r.input = in;
  r.voxels = volume.NumberOfVoxels();
  r.runs = runs;
  std::copy(volume.Dims, volume.Dims + 3, r.dims);
  std::copy(volume.Range, volume.Range + 2, r.range);
  std::vector<long long> levels = ParseList(o.Get("red-levels"), r.voxels, "--red-levels");
  for (long long& l : levels)
  {
    l = std::max(6LL, l);
  }
  if (levels.empty())
  {
    throw cli::UsageError("--red-levels is empty");
  }
  const std::vector<long long> timed = ParseList(o.Get("red-timed-vertices"), r.voxels, "--red-timed-vertices");
  std::fprintf(stderr, "bench reduction: %s, %d x %d x %d = %lld voxels, %zu levels, %zu series, %d runs + warm-up, %d threads\n",
    in.c_str(), volume.Dims[0], volume.Dims[1], volume.Dims[2], r.voxels, levels.size(), names.size(), runs,
    art::GetThreadCount());
  for (const std::string& name : names)
  {
    r.series.push_back(RunSeries(name, volume, levels, timed, runs));
  }
  r.quadric = !o.Flag("red-no-quadric");
  if (r.quadric)
  {
    std::vector<long long> tets;
    for (const auto& w : r.series.front().levels)
    {
      tets.push_back(w.tets);
    }
    RunQuadric(image, volume, tets, SeriesOptions(names.front()), r);
  }
  const std::string stem = (dir / "reduction").string();
  std::printf("%s", cli::WriteReductionReport(r, stem).c_str());
  cli::FinishResults(cli::ThisRun().source + "/tests/benchmarks/reduction_chart.py", stem);
  return cli::ExitOk;
}

cli::BenchRegistrar reg({ "reduction",
  "the reducer's refinements vs quadric decimation and uniform downsampling on the CT head", Declare, Run });
} // namespace
#endif
