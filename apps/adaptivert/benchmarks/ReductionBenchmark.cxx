// adaptivert bench reduction: the least-squares reducer at the paper's reduction levels on the
// real CT head, side by side (same run, same machine) with VTK's quadric decimation of the
// volume's tetrahedrisation at the same tet count and with uniform downsampling at the same
// vertex count: RMS and max error against the voxels, build time, peak memory.
#include "benchmarks/Bench.h"
#include "benchmarks/BenchUtil.h"
#include "cli/Command.h"

#ifdef ART_HAVE_Reduction
#include "DataLoader.h"
#include "Error.h"
#include "cli/Json.h"
#include "ParallelTiles.h"
#include "MeshQuality.h"
#include "ReducerVTK.h"
#include "ReductionBaselines.h"
#include "rendering/ReductionTargets.h"
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
#include <thread>

namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Peak memory of one step: Linux lets a process reset its high-water mark (clear_refs 5).
long long StatusKB(const char* key)
{
  std::ifstream f("/proc/self/status");
  std::string line;
  while (std::getline(f, line))
  {
    if (line.rfind(key, 0) == 0)
    {
      return std::atoll(line.c_str() + std::strlen(key) + 1);
    }
  }
  return 0;
}
void ResetPeak()
{
  std::ofstream("/proc/self/clear_refs") << "5";
}
// The process's peak resident memory since the reset: input volume included, as a user sees it.
double PeakMBSinceReset(long long)
{
  return StatusKB("VmHWM") / 1024.0;
}

long long ParseBudget(const std::string& s, long long voxels)
{
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (!(v > 0) || (*end && !(*end == '%' && end[1] == 0)))
  {
    throw cli::UsageError("--red-levels wants numbers or percentages, got '" + s + "'");
  }
  return *end == '%' ? std::llround(v / 100.0 * voxels) : std::llround(v);
}

void Declare(cli::Options& o)
{
  o.Add("red-input", 0, "FILE", "reduction: the volume (data/fetch gives the full CT in data/full/ct-head.mha)",
    cli::DataDir() + "/ct-head-128.mha");
  o.Add("red-levels", 0, "LIST", "reduction: budgets, % of the voxel count or tets",
    "0.01%,0.03%,0.05%,0.1%,0.2%,1%");
  o.Add("red-timed-tets", 0, "N", "reduction: also time a separate run to N tets (0: skip)", "200000");
  o.Add("red-no-quadric", 0, "", "reduction: skip VTK's quadric decimation (slow on big volumes)");
  o.Add("red-refinement", 0, "bisection|edge",
    "reduction: newest-vertex bisection, or splitting the edges that remove the most error", "bisection");
  o.Add("red-relocate", 0, "", "reduction: move each level's vertices off the lattice to lower its error (VertexRelocator)");
}

struct Row
{
  long long level = 0;
  // ours
  long long tets = 0, vertices = 0;
  double rms = 0, max = 0;
  double minDihedral = 0, minRadiusRatio = 0, meanRadiusRatio = 0;
  cli::BenchStats seconds;
  // quadric decimation at our tet count
  long long qTets = 0, qVertices = 0, qUncovered = 0, qInverted = 0;
  double qRms = -1, qMax = -1, qSeconds = 0, qCoveredRms = -1;
  // ours at the quadric's tet count, over the voxels its output covers (a like-for-like figure:
  // the quadric's RMS above counts its uncovered voxels as 0)
  long long oqTets = 0;
  double oqCoveredRms = -1;
  // uniform downsampling at our vertex count
  long long uVertices = 0, uTets = 0;
  double uRms = 0, uMax = 0;
  cli::BenchStats uSeconds;
};

int Run(const cli::Options& o)
{
  const std::string in = o.Get("red-input");
  const int runs = std::max(1, static_cast<int>(o.GetInt("runs")));
  const std::filesystem::path dir = o.Get("results");
  std::filesystem::create_directories(dir);
  auto image = art::LoadVolume(in);
  const art::VoxelVolume volume = art::VolumeFromImage(image, in);
  const long long voxels = volume.NumberOfVoxels();
  std::vector<long long> levels;
  {
    std::stringstream ss(o.Get("red-levels"));
    std::string item;
    while (std::getline(ss, item, ','))
    {
      levels.push_back(std::max(6LL, ParseBudget(item, voxels)));
    }
  }
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  if (levels.empty())
  {
    throw cli::UsageError("--red-levels is empty");
  }
  std::fprintf(stderr, "bench reduction: %s, %d x %d x %d = %lld voxels, %zu levels, %d runs + warm-up, %d threads\n",
    in.c_str(), volume.Dims[0], volume.Dims[1], volume.Dims[2], voxels, levels.size(), runs, art::GetThreadCount());

  // Ours: one nested run emits every level; each level's time is the build time up to it.
  const std::string refinement = o.Get("red-refinement");
  art::ReducerOptions opt;
  opt.Refine = cli::ParseRefinement(refinement, "--red-refinement");
  opt.Levels = levels;
  opt.RelocateVertices = o.Flag("red-relocate");
  std::vector<Row> rows(levels.size());
  std::vector<std::vector<double>> times(levels.size());
  std::vector<double> peaks;
  std::vector<art::ReducedMesh> meshes;
  for (int r = 0; r <= runs; ++r)
  {
    const long long base = StatusKB("VmRSS");
    ResetPeak();
    meshes = art::TetReducer(opt).Run(volume);
    if (r > 0) // r == 0 is the warm-up
    {
      peaks.push_back(PeakMBSinceReset(base));
      for (size_t i = 0; i < meshes.size() && i < levels.size(); ++i)
      {
        times[i].push_back(meshes[i].BuildSeconds);
      }
    }
  }
  for (size_t i = 0; i < levels.size(); ++i)
  {
    Row& w = rows[i];
    const auto& m = meshes[i];
    w.level = levels[i];
    w.tets = m.NumberOfTets();
    w.vertices = m.NumberOfVertices();
    w.rms = m.Rms;
    w.max = m.Max;
    w.seconds = cli::Summarise(times[i]);
    const art::QualityReport q = art::MeasureQuality(m.Points.data(), m.NumberOfVertices(), m.Tets.data(), m.NumberOfTets());
    w.minDihedral = q.MinDihedralDegrees;
    w.minRadiusRatio = q.MinRadiusRatio;
    w.meanRadiusRatio = q.MeanRadiusRatio;
    std::fprintf(stderr, "  ours     %8lld tets  RMS %8.3f  max %8.1f  %.2f s  min dihedral %.1f deg  radius ratio min %.3f mean %.3f\n",
      w.tets, w.rms, w.max, w.seconds.median, w.minDihedral, w.minRadiusRatio, w.meanRadiusRatio);
  }
  const cli::BenchStats ourPeak = cli::Summarise(peaks);

  // Uniform downsampling to our vertex count (cheap: every run timed).
  for (auto& w : rows)
  {
    std::vector<double> t;
    art::BaselineError e;
    for (int r = 0; r <= runs; ++r)
    {
      const auto t0 = Clock::now();
      e = art::UniformDownsampleError(volume, w.vertices);
      if (r > 0)
      {
        t.push_back(Seconds(t0));
      }
    }
    w.uVertices = e.Vertices;
    w.uTets = e.Tets;
    w.uRms = e.Rms;
    w.uMax = e.Max;
    w.uSeconds = cli::Summarise(t);
    std::fprintf(stderr, "  uniform  %8lld verts RMS %8.3f  max %8.1f\n", w.uVertices, w.uRms, w.uMax);
  }

  // Quadric decimation of the full tetrahedrisation, chained from the largest level down (each
  // level is decimated from the previous result, as nested as ours). One run: it is slow.
  double triSeconds = 0, quadricPeak = 0;
  long long fullTets = 0;
  const bool quadric = !o.Flag("red-no-quadric");
  if (quadric)
  {
    const long long base = StatusKB("VmRSS");
    ResetPeak();
    auto t0 = Clock::now();
    vtkSmartPointer<vtkUnstructuredGrid> grid = art::TetrahedralizeVolume(image);
    triSeconds = Seconds(t0);
    fullTets = grid->GetNumberOfCells();
    std::fprintf(stderr, "  quadric  input %lld tets (%.1f s)\n", fullTets, triSeconds);
    double cumulative = triSeconds;
    for (size_t i = rows.size(); i-- > 0;)
    {
      Row& w = rows[i];
      t0 = Clock::now();
      grid = art::QuadricDecimate(grid, w.tets, volume.Name.c_str());
      cumulative += Seconds(t0);
      std::vector<char> covered;
      const art::BaselineError e = art::ProbeError(image, grid, volume.Name.c_str(), &covered);
      w.qTets = e.Tets;
      w.qVertices = e.Vertices;
      w.qRms = e.Rms;
      w.qMax = e.Max;
      w.qUncovered = e.Uncovered;
      w.qCoveredRms = e.CoveredRms;
      w.qInverted = art::MeasureQuality(grid).Inverted;
      w.qSeconds = cumulative;
      art::ReducerOptions at = opt;
      at.Levels.clear();
      at.TargetTets = w.qTets;
      at.TargetError = -1;
      const auto same = art::TetReducer(at).Run(volume);
      const art::BaselineError oe =
        art::ProbeError(image, art::ToUnstructuredGrid(same.back(), true), volume.Name.c_str(), nullptr, &covered);
      w.oqTets = same.back().NumberOfTets();
      w.oqCoveredRms = oe.Rms;
      std::fprintf(stderr, "  ours at the quadric's count: %lld tets, RMS %.3f over the voxels it covers\n", w.oqTets,
        w.oqCoveredRms);
      std::fprintf(stderr, "  quadric  %8lld tets  RMS %8.3f  max %8.1f  %.1f s (%lld voxels uncovered, %lld flat or inverted tets)\n",
        w.qTets, w.qRms, w.qMax, w.qSeconds, w.qUncovered, w.qInverted);
    }
    quadricPeak = PeakMBSinceReset(base);
  }

  // The speed target: a separate run straight to N tets.
  const long long timedTets = o.GetInt("red-timed-tets");
  cli::BenchStats timed, timedPeak;
  art::ReducedMesh timedMesh;
  if (timedTets > 0)
  {
    std::vector<double> t, p;
    art::ReducerOptions topt;
    topt.TargetTets = timedTets;
    topt.Refine = opt.Refine;
    topt.RelocateVertices = opt.RelocateVertices;
    for (int r = 0; r <= runs; ++r)
    {
      const long long base = StatusKB("VmRSS");
      ResetPeak();
      auto out = art::TetReducer(topt).Run(volume);
      if (r > 0)
      {
        t.push_back(out.back().BuildSeconds);
        p.push_back(PeakMBSinceReset(base));
      }
      timedMesh = std::move(out.back());
    }
    timed = cli::Summarise(t);
    timedPeak = cli::Summarise(p);
    std::fprintf(stderr, "  timed    %8lld tets  RMS %8.3f  %.2f s  peak %.0f MB\n", timedMesh.NumberOfTets(),
      timedMesh.Rms, timed.median, timedPeak.median);
  }

  // JSON, markdown, chart.
  const cli::RunInfo run = cli::ThisRun();
  const std::string &src = run.source, &commit = run.commit, &cpu = run.cpu, &date = run.date;
  std::vector<cli::Json> jr;
  for (const auto& w : rows)
  {
    cli::Json j;
    j.Set("level_tets", w.level).Set("level_percent", 100.0 * w.level / voxels)
      .Set("tets", w.tets).Set("vertices", w.vertices).Set("rms", w.rms).Set("max", w.max)
      .Set("min_dihedral_degrees", w.minDihedral).Set("min_radius_ratio", w.minRadiusRatio)
      .Set("mean_radius_ratio", w.meanRadiusRatio).Set("seconds", w.seconds.median).Set("seconds_min", w.seconds.lo).Set("seconds_max", w.seconds.hi)
      .Set("uniform_vertices", w.uVertices).Set("uniform_tets", w.uTets).Set("uniform_rms", w.uRms)
      .Set("uniform_max", w.uMax).Set("uniform_seconds", w.uSeconds.median);
    if (quadric)
    {
      j.Set("quadric_tets", w.qTets).Set("quadric_vertices", w.qVertices).Set("quadric_rms", w.qRms)
        .Set("quadric_max", w.qMax).Set("quadric_uncovered_voxels", w.qUncovered)
        .Set("quadric_covered_rms", w.qCoveredRms).Set("quadric_inverted_tets", w.qInverted)
        .Set("quadric_cumulative_seconds", w.qSeconds).Set("ours_at_quadric_tets", w.oqTets)
        .Set("ours_at_quadric_tets_covered_rms", w.oqCoveredRms);
    }
    jr.push_back(j);
  }
  cli::Json js;
  js.Set("benchmark", "reduction").Set("input", in).Set("dims",
      std::vector<double>{ double(volume.Dims[0]), double(volume.Dims[1]), double(volume.Dims[2]) })
    .Set("refinement", refinement).Set("relocate", opt.RelocateVertices).Set("voxels", voxels).Set("scalar_range", std::vector<double>{ volume.Range[0], volume.Range[1] })
    .Set("machine", cpu).Set("hardware_threads", static_cast<long long>(std::thread::hardware_concurrency()))
    .Set("threads", art::GetThreadCount()).Set("date", date).Set("commit", commit).Set("runs", runs)
    .Set("ours_peak_mb", ourPeak.median).Set("ours_peak_mb_min", ourPeak.lo).Set("ours_peak_mb_max", ourPeak.hi)
    .Set("quadric", quadric).Set("quadric_input_tets", fullTets).Set("quadric_tetrahedralize_seconds", triSeconds)
    .Set("quadric_peak_mb", quadricPeak).Set("rows", jr);
  if (timedTets > 0)
  {
    js.Set("timed_target_tets", timedTets).Set("timed_tets", timedMesh.NumberOfTets())
      .Set("timed_rms", timedMesh.Rms).Set("timed_max", timedMesh.Max).Set("timed_seconds", timed.median)
      .Set("timed_seconds_min", timed.lo).Set("timed_seconds_max", timed.hi).Set("timed_peak_mb", timedPeak.median);
  }
  const std::string stem = (dir / "reduction").string();
  std::ofstream(stem + ".json") << js.Str() << "\n";

  std::ostringstream md;
  char line[1024];
  md << "# Reduction benchmark\n\n" << in << ": " << volume.Dims[0] << " x " << volume.Dims[1] << " x "
     << volume.Dims[2] << " = " << voxels << " voxels, range " << volume.Range[0] << " .. " << volume.Range[1]
     << " (HU). " << cpu << ", " << art::GetThreadCount() << " threads, commit " << commit << ", " << date
     << ". Refinement: " << refinement << (opt.RelocateVertices ? ", vertices relocated" : "") << ". Times: median of " << runs << " runs after a warm-up [min-max]; ours are cumulative over one nested run.\n\n";
  md << "| level | tets | verts | ours RMS | ours max | ours s | quadric tets | quadric RMS | quadric RMS covered | quadric max | quadric s | uniform verts | uniform RMS | uniform max | RMS vs quadric | RMS vs uniform | min dihedral | radius ratio min / mean |\n";
  md << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  std::ostringstream like; // ours and the quadric at its own tet count, on the voxels it covers
  like << "| level | quadric tets | voxels covered | quadric RMS covered | ours at that count: tets | ours RMS on those voxels | ours vs quadric |\n"
       << "|---|---|---|---|---|---|---|\n";
  for (const auto& w : rows)
  {
    char q[300] = "| - | - | - | - | - ";
    if (quadric)
    {
      std::snprintf(q, sizeof q, "| %lld | %.2f | %.2f (%.0f%% of voxels) | %.1f | %.1f ", w.qTets, w.qRms,
        w.qCoveredRms, 100.0 - 100.0 * w.qUncovered / voxels, w.qMax, w.qSeconds);
      std::snprintf(line, sizeof line, "| %.2f%% | %lld | %.0f%% | %.2f | %lld | %.2f | %.2f |\n", 100.0 * w.level / voxels,
        w.qTets, 100.0 - 100.0 * w.qUncovered / voxels, w.qCoveredRms, w.oqTets, w.oqCoveredRms,
        w.oqCoveredRms / w.qCoveredRms);
      like << line;
    }
    std::snprintf(line, sizeof line,
      "| %.2f%% | %lld | %lld | %.2f | %.1f | %.2f [%.2f-%.2f] %s| %lld | %.2f | %.1f | %s | %.2f | %.1f deg | %.3f / %.3f |\n",
      100.0 * w.level / voxels, w.tets, w.vertices, w.rms, w.max, w.seconds.median, w.seconds.lo, w.seconds.hi, q,
      w.uVertices, w.uRms, w.uMax, quadric ? (std::to_string(w.rms / w.qRms).substr(0, 4)).c_str() : "-",
      w.rms / w.uRms, w.minDihedral, w.minRadiusRatio, w.meanRadiusRatio);
    md << line;
  }
  std::snprintf(line, sizeof line, "\nOurs: process peak memory %.0f MB [%.0f-%.0f] (input volume included) for the whole nested run.", ourPeak.median,
    ourPeak.lo, ourPeak.hi);
  md << line;
  if (quadric)
  {
    std::snprintf(line, sizeof line,
      " Quadric decimation (vtkUnstructuredGridQuadricDecimation, 1 run, chained from the largest level down): "
      "input %lld tets from vtkDataSetTriangleFilter in %.1f s, process peak %.0f MB; its times include the triangulation. "
      "It stops short of small targets (its tet count is what it reached) and its output leaves voxel centres "
      "uncovered (probed as 0): 'RMS covered' is over the covered voxels only.",
      fullTets, triSeconds, quadricPeak);
    md << line;
    md << "\n\n'RMS vs quadric' counts the voxels the quadric's output leaves uncovered as 0, an error of the full "
          "air value there, and compares it at the tet count it reached, not ours. Like for like, ours reduced to the "
          "quadric's own tet count and measured on the voxels its output covers:\n\n"
       << like.str();
  }
  if (timedTets > 0)
  {
    std::snprintf(line, sizeof line, "\n\nSeparate run to %lld tets: %lld tets, RMS %.2f, max %.1f, %.2f s [%.2f-%.2f], peak %.0f MB.\n",
      timedTets, timedMesh.NumberOfTets(), timedMesh.Rms, timedMesh.Max, timed.median, timed.lo, timed.hi, timedPeak.median);
    md << line;
  }
  std::ofstream(stem + ".md") << md.str();
  std::printf("%s", md.str().c_str());

  cli::FinishResults(src + "/tests/benchmarks/reduction_chart.py", stem);
  return cli::ExitOk;
}

cli::BenchRegistrar reg({ "reduction",
  "least-squares tet reduction vs quadric decimation and uniform downsampling on the CT head", Declare, Run });
} // namespace
#endif
