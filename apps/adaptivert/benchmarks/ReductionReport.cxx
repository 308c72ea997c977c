// The JSON and markdown of `adaptivert bench reduction` (ReductionBenchmark.h).
#include "benchmarks/ReductionBenchmark.h"
#include "cli/Json.h"
#include "ParallelTiles.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <thread>

namespace cli
{
namespace
{
Json RowJson(const ReductionRow& w, long long voxels)
{
  Json j;
  j.Set("level_tets", w.level).Set("level_percent", 100.0 * w.level / voxels).Set("tets", w.tets)
    .Set("vertices", w.vertices).Set("vertices_percent", 100.0 * w.vertices / voxels).Set("rms", w.rms)
    .Set("max", w.max).Set("seconds", w.seconds.median).Set("seconds_min", w.seconds.lo)
    .Set("seconds_max", w.seconds.hi).Set("min_dihedral_degrees", w.minDihedral)
    .Set("min_radius_ratio", w.minRadiusRatio).Set("mean_radius_ratio", w.meanRadiusRatio)
    .Set("uniform_vertices", w.uniformVertices).Set("uniform_rms", w.uniformRms).Set("uniform_max", w.uniformMax)
    .Set("rms_vs_uniform", w.rms / w.uniformRms);
  return j;
}

std::string ResultsJson(const ReductionResults& r)
{
  const RunInfo run = ThisRun();
  std::vector<cli::Json> series;
  for (const auto& s : r.series)
  {
    std::vector<cli::Json> rows, timed;
    for (const auto& w : s.levels)
    {
      rows.push_back(RowJson(w, r.voxels));
    }
    for (size_t i = 0; i < s.timed.size(); ++i)
    {
      timed.push_back(RowJson(s.timed[i], r.voxels).Set("peak_mb", s.timedPeakMB[i].median));
    }
    cli::Json j;
    j.Set("name", s.name).Set("peak_mb", s.peakMB.median).Set("peak_mb_min", s.peakMB.lo)
      .Set("peak_mb_max", s.peakMB.hi).Set("rows", rows).Set("timed", timed);
    series.push_back(j);
  }
  std::vector<cli::Json> quadric;
  for (const auto& q : r.quadricRows)
  {
    cli::Json j;
    j.Set("tets", q.tets).Set("vertices", q.vertices).Set("rms", q.rms).Set("max", q.max)
      .Set("uncovered_voxels", q.uncovered).Set("covered_rms", q.coveredRms).Set("inverted_tets", q.inverted)
      .Set("cumulative_seconds", q.seconds).Set("ours_tets", q.oursTets).Set("ours_covered_rms", q.oursCoveredRms);
    quadric.push_back(j);
  }
  cli::Json js;
  js.Set("benchmark", "reduction").Set("input", r.input)
    .Set("dims", std::vector<double>{ double(r.dims[0]), double(r.dims[1]), double(r.dims[2]) })
    .Set("voxels", r.voxels).Set("scalar_range", std::vector<double>{ r.range[0], r.range[1] })
    .Set("machine", run.cpu).Set("hardware_threads", static_cast<long long>(std::thread::hardware_concurrency()))
    .Set("threads", art::GetThreadCount()).Set("date", run.date).Set("commit", run.commit).Set("runs", r.runs)
    .Set("series", series).Set("quadric", r.quadric).Set("quadric_input_tets", r.quadricInputTets)
    .Set("quadric_tetrahedralize_seconds", r.quadricTetrahedralizeSeconds).Set("quadric_peak_mb", r.quadricPeakMB)
    .Set("quadric_rows", quadric);
  return js.Str();
}

std::string Markdown(const ReductionResults& r)
{
  const RunInfo run = ThisRun();
  std::ostringstream md;
  char line[1024];
  md << "# Reduction benchmark\n\n" << r.input << ": " << r.dims[0] << " x " << r.dims[1] << " x " << r.dims[2]
     << " = " << r.voxels << " voxels, range " << r.range[0] << " .. " << r.range[1] << ". " << run.cpu << ", "
     << art::GetThreadCount() << " threads, commit " << run.commit << ", " << run.date << ". Times: median of "
     << r.runs << " runs after a warm-up [min-max], cumulative over one run of the levels (anisotropic levels are "
     << "each remeshed, not nested). 'vs uniform': RMS over that of uniform downsampling to the same vertices.\n\n";
  // The series side by side at each level.
  md << "| level |";
  for (const auto& s : r.series)
  {
    md << " " << s.name << " tets / verts | RMS | vs uniform |";
  }
  md << (r.quadric ? " quadric tets | quadric RMS (covered) |" : "") << "\n|---|";
  for (size_t i = 0; i < r.series.size(); ++i)
  {
    md << "---|---|---|";
  }
  md << (r.quadric ? "---|---|" : "") << "\n";
  for (size_t l = 0; l < r.series.front().levels.size(); ++l)
  {
    std::snprintf(line, sizeof line, "| %.2f%% |", 100.0 * r.series.front().levels[l].level / r.voxels);
    md << line;
    for (const auto& s : r.series)
    {
      if (l < s.levels.size())
      {
        const ReductionRow& w = s.levels[l];
        std::snprintf(line, sizeof line, " %lld / %lld | %.2f | %.3f |", w.tets, w.vertices, w.rms, w.rms / w.uniformRms);
        md << line;
      }
      else
      {
        md << " - | - | - |";
      }
    }
    if (r.quadric && l < r.quadricRows.size())
    {
      const QuadricRow& q = r.quadricRows[l];
      std::snprintf(line, sizeof line, " %lld | %.2f (%.2f) |", q.tets, q.rms, q.coveredRms);
      md << line;
    }
    md << "\n";
  }
  // Each series in full.
  for (const auto& s : r.series)
  {
    std::snprintf(line, sizeof line, "\n## %s (process peak %.0f MB [%.0f-%.0f] over the run of levels)\n\n",
      s.name.c_str(), s.peakMB.median, s.peakMB.lo, s.peakMB.hi);
    md << line << "| level | tets | verts | RMS | max | s | uniform verts | uniform RMS | uniform max | vs uniform | min dihedral | radius ratio min / mean |\n"
       << "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& w : s.levels)
    {
      std::snprintf(line, sizeof line,
        "| %.2f%% | %lld | %lld | %.2f | %.1f | %.2f [%.2f-%.2f] | %lld | %.2f | %.1f | %.3f | %.1f deg | %.3f / %.3f |\n",
        100.0 * w.level / r.voxels, w.tets, w.vertices, w.rms, w.max, w.seconds.median, w.seconds.lo, w.seconds.hi,
        w.uniformVertices, w.uniformRms, w.uniformMax, w.rms / w.uniformRms, w.minDihedral, w.minRadiusRatio,
        w.meanRadiusRatio);
      md << line;
    }
  }
  // The timed runs to a share of the voxels as vertices.
  bool anyTimed = false;
  for (const auto& s : r.series)
  {
    anyTimed = anyTimed || !s.timed.empty();
  }
  if (anyTimed)
  {
    md << "\n## Each series alone to a share of the voxels as vertices\n\n"
       << "| series | tets | vertices | RMS | uniform RMS | vs uniform | s [min-max] | peak MB | min dihedral |\n"
       << "|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& s : r.series)
    {
      for (size_t i = 0; i < s.timed.size(); ++i)
      {
        const ReductionRow& w = s.timed[i];
        std::snprintf(line, sizeof line, "| %s | %lld | %lld (%.2f%%) | %.2f | %.2f | %.3f | %.2f [%.2f-%.2f] | %.0f | %.1f deg |\n",
          s.name.c_str(), w.tets, w.vertices, 100.0 * w.vertices / r.voxels, w.rms, w.uniformRms, w.rms / w.uniformRms,
          w.seconds.median, w.seconds.lo, w.seconds.hi, s.timedPeakMB[i].median, w.minDihedral);
        md << line;
      }
    }
  }
  if (r.quadric)
  {
    std::snprintf(line, sizeof line,
      "\nQuadric decimation (vtkUnstructuredGridQuadricDecimation, 1 run, chained from the largest level down): "
      "input %lld tets from vtkDataSetTriangleFilter in %.1f s, process peak %.0f MB; its times include the "
      "triangulation. It stops short of small targets and its output leaves voxel centres uncovered (probed as 0): "
      "'covered' is over the covered voxels only. Like for like, %s reduced to the quadric's own tet count and "
      "measured on the voxels its output covers:\n\n",
      r.quadricInputTets, r.quadricTetrahedralizeSeconds, r.quadricPeakMB, r.series.front().name.c_str());
    md << line << "| quadric tets | voxels covered | quadric RMS covered | quadric s | ours: tets | ours RMS there | ours vs quadric |\n"
       << "|---|---|---|---|---|---|---|\n";
    for (const auto& q : r.quadricRows)
    {
      std::snprintf(line, sizeof line, "| %lld | %.0f%% | %.2f | %.1f | %lld | %.2f | %.2f |\n", q.tets,
        100.0 - 100.0 * q.uncovered / r.voxels, q.coveredRms, q.seconds, q.oursTets, q.oursCoveredRms,
        q.oursCoveredRms / q.coveredRms);
      md << line;
    }
  }
  return md.str();
}
} // namespace

std::string WriteReductionReport(const ReductionResults& r, const std::string& stem)
{
  std::ofstream(stem + ".json") << ResultsJson(r) << "\n";
  const std::string md = Markdown(r);
  std::ofstream(stem + ".md") << md;
  return md;
}
} // namespace cli
