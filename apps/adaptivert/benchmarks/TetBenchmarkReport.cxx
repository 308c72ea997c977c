// The files of `adaptivert bench tets`: raw figures as JSON (fields kept from run to run), a
// markdown table with the ratios against VTK's mappers and, per mesh series, the smallest mesh
// drawn at FixedPoint's own PSNR.
#include "benchmarks/TetBenchmark.h"
#include "cli/Json.h"
#include "ParallelTiles.h"

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

namespace cli
{
namespace
{
const char* const kOurs = "ours exact, ERT 0.99";

Json RowJson(const TetBenchRow& r)
{
  Json j;
  j.Set("method", r.method).Set("mesh", r.mesh).Set("series", r.series).Set("tets", r.tets)
    .Set("vertices", r.vertices).Set("seconds", r.seconds.median).Set("seconds_min", r.seconds.lo)
    .Set("seconds_max", r.seconds.hi).Set("psnr", r.err.psnr).Set("ssim", r.err.ssim).Set("rmse", r.err.rmse)
    .Set("tets_per_ray", r.tetsPerRay).Set("ns_per_tet_crossed_per_thread", r.nsPerTet);
  return j;
}

Json MatchJson(const TetBenchMatch& m)
{
  Json j;
  j.Set("series", m.series).Set("fixedpoint_seconds", m.fixedPoint->seconds.median)
    .Set("fixedpoint_psnr", m.fixedPoint->err.psnr).Set("reached", m.mesh != nullptr);
  const TetBenchRow* r = m.mesh ? m.mesh : m.largest;
  j.Set("mesh", r->mesh).Set("tets", r->tets).Set("seconds", r->seconds.median).Set("psnr", r->err.psnr)
    .Set("fixedpoint_speedup", m.fixedPoint->seconds.median / r->seconds.median);
  return j;
}

void WriteJson(const std::string& path, const TetBenchSetup& s, const std::vector<TetBenchRow>& rows,
  const std::vector<TetBenchMatch>& matches, const RunInfo& run)
{
  std::vector<Json> jr, jm;
  for (const TetBenchRow& r : rows)
  {
    jr.push_back(RowJson(r));
  }
  for (const TetBenchMatch& m : matches)
  {
    jm.push_back(MatchJson(m));
  }
  Json js;
  js.Set("benchmark", "tets").Set("input", s.input).Set("input_label", s.inputLabel).Set("resample", s.resample)
    .Set("dimensions", std::vector<double>{ double(s.dims[0]), double(s.dims[1]), double(s.dims[2]) })
    .Set("voxels", s.voxels).Set("width", s.width).Set("height", s.height)
    .Set("transfer_function", s.transferFunction).Set("machine", run.cpu)
    .Set("hardware_threads", static_cast<long long>(std::thread::hardware_concurrency()))
    .Set("threads", art::GetThreadCount()).Set("date", run.date).Set("commit", run.commit).Set("runs", s.runs)
    .Set("reference_seconds", s.referenceSeconds).Set("rows", jr).Set("at_fixedpoint_psnr", jm);
  std::ofstream(path) << js.Str() << "\n";
}

void TableMarkdown(std::ostringstream& md, const TetBenchSetup& s, const std::vector<TetBenchRow>& rows)
{
  md << "| method | mesh | tets | vertices (% of voxels) | time s [min-max] | PSNR dB | SSIM | RMSE | tets/ray | ns/tet crossed/thread |\n"
     << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  char line[512];
  for (const TetBenchRow& r : rows)
  {
    std::snprintf(line, sizeof line, "| %s | %s | %lld | %lld (%.2f%%) | %.3f [%.3f-%.3f] | %.2f | %.4f | %.5f | %.1f | %.0f |\n",
      r.method.c_str(), r.mesh.c_str(), r.tets, r.vertices, 100.0 * r.vertices / s.voxels, r.seconds.median,
      r.seconds.lo, r.seconds.hi, r.err.psnr, r.err.ssim, r.err.rmse, r.tetsPerRay, r.nsPerTet);
    md << line;
  }
}

void RatiosMarkdown(std::ostringstream& md, const TetBenchSetup& s, const std::vector<TetBenchRow>& rows)
{
  md << "\n## Ratios\n\n";
  const TetBenchRow* fullOurs = nullptr;
  for (const TetBenchRow& r : rows)
  {
    fullOurs = r.mesh == "full resolution" && r.method == kOurs ? &r : fullOurs;
  }
  char line[512];
  for (const TetBenchRow& r : rows)
  {
    if (r.method.rfind("VTK Bunyk", 0) == 0)
    {
      for (const TetBenchRow& q : rows)
      {
        if (q.mesh == r.mesh && q.method == kOurs)
        {
          std::snprintf(line, sizeof line,
            "- %s: ours %.2fx Bunyk's frame rate (%.3f s vs %.3f s), PSNR %.2f vs %.2f dB\n", r.mesh.c_str(),
            r.seconds.median / q.seconds.median, q.seconds.median, r.seconds.median, q.err.psnr, r.err.psnr);
          md << line;
        }
        if (q.mesh == r.mesh && q.method == "ours mapper in a window")
        {
          std::snprintf(line, sizeof line, "- %s, mapper against mapper (both in a window): %.2fx (%.3f s vs %.3f s)\n",
            r.mesh.c_str(), r.seconds.median / q.seconds.median, q.seconds.median, r.seconds.median);
          md << line;
        }
      }
    }
    if (fullOurs && r.method == kOurs && r.mesh != "full resolution")
    {
      std::snprintf(line, sizeof line,
        "- %s (%.2f%% of the vertices): %.2fx faster than our full-resolution render, %.0f%% of its time, PSNR %.2f dB\n",
        r.mesh.c_str(), 100.0 * r.vertices / s.voxels, fullOurs->seconds.median / r.seconds.median,
        100.0 * r.seconds.median / fullOurs->seconds.median, r.err.psnr);
      md << line;
    }
  }
}

void MatchMarkdown(std::ostringstream& md, const std::vector<TetBenchMatch>& matches)
{
  if (matches.empty())
  {
    return;
  }
  md << "\n## At FixedPoint's PSNR\n\n"
     << "| series | FixedPoint s | FixedPoint PSNR dB | smallest mesh reaching it | its time s | its PSNR dB | FixedPoint's time / its time |\n"
     << "|---|---:|---:|---|---:|---:|---:|\n";
  char line[512];
  for (const TetBenchMatch& m : matches)
  {
    const TetBenchRow* r = m.mesh ? m.mesh : m.largest;
    std::snprintf(line, sizeof line, "| %s | %.3f | %.2f | %s%s | %.3f | %.2f | %.2fx |\n", m.series.c_str(),
      m.fixedPoint->seconds.median, m.fixedPoint->err.psnr, m.mesh ? "" : "none; best: ", r->mesh.c_str(),
      r->seconds.median, r->err.psnr, m.fixedPoint->seconds.median / r->seconds.median);
    md << line;
  }
}
} // namespace

std::vector<TetBenchMatch> MatchFixedPointPsnr(const std::vector<TetBenchRow>& rows)
{
  const TetBenchRow* fp = nullptr;
  for (const TetBenchRow& r : rows)
  {
    fp = r.method == "VTK FixedPoint (voxels)" ? &r : fp;
  }
  std::vector<TetBenchMatch> out;
  if (!fp)
  {
    return out;
  }
  std::map<std::string, TetBenchMatch> bySeries; // full resolution is a series of its own
  for (const TetBenchRow& r : rows)
  {
    if (r.method != kOurs)
    {
      continue;
    }
    TetBenchMatch& m = bySeries[r.series];
    m.series = r.series, m.fixedPoint = fp;
    if (r.err.psnr >= fp->err.psnr && (!m.mesh || r.tets < m.mesh->tets))
    {
      m.mesh = &r;
    }
    if (!m.largest || r.err.psnr > m.largest->err.psnr)
    {
      m.largest = &r;
    }
  }
  for (auto& kv : bySeries)
  {
    out.push_back(kv.second);
  }
  return out;
}

std::string WriteTetBenchResults(const std::string& stem, const TetBenchSetup& s, const std::vector<TetBenchRow>& rows)
{
  const RunInfo run = ThisRun();
  const std::vector<TetBenchMatch> matches = MatchFixedPointPsnr(rows);
  WriteJson(stem + ".json", s, rows, matches, run);
  std::ostringstream md;
  md << "# Tet ray casting: " << s.inputLabel << " (" << s.width << " x " << s.height << ")\n\n"
     << s.inputLabel << " (" << s.dims[0] << " x " << s.dims[1] << " x " << s.dims[2] << " voxels), transfer function "
     << s.transferFunction << " (" << s.reduction << ")"
     << ", reference: voxel ray caster (trilinear, 2 samples/voxel, exact steps, no ERT; " << s.referenceSeconds
     << " s). " << run.cpu << ", " << art::GetThreadCount() << " threads, commit " << run.commit << ", " << run.date
     << ". Times: median of " << s.runs << " runs after a warm-up [min-max]; a mesh's methods are timed in turn, one frame each per round.\n\n";
  TableMarkdown(md, s, rows);
  RatiosMarkdown(md, s, rows);
  MatchMarkdown(md, matches);
  std::ofstream(stem + ".md") << md.str();
  return md.str();
}
} // namespace cli
