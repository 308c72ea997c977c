// adaptivert batch JOB.json: renders every data set x camera x setting of a job file, with the
// error of each image against its camera's reference, a CSV of time and error per image and a
// speed-against-accuracy chart. Each frame runs as its own `adaptivert render` process; finished
// frames leave a result file (written atomically), so a killed batch resumes where it stopped
// and several processes can share one job without doing a frame twice (FrameClaim).
#include "AtomicFile.h"
#include "batch/BatchJob.h"
#include "cli/Command.h"
#include "Error.h"
#include "batch/FrameClaim.h"
#include "ImageIO.h"
#include "ImageMetrics.h"
#include "cli/ProgressBar.h"
#include "cli/Subprocess.h"
#include "cli/ResourcePath.h"

#include <nlohmann/json.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

namespace fs = std::filesystem;
using nlohmann::json;

namespace
{
std::string ResultPath(const cli::BatchJob& job, const std::string& name)
{
  return job.outputDir + "/" + name + ".result.json";
}

bool ReadResult(const std::string& path, json& out)
{
  std::ifstream in(path);
  if (!in)
  {
    return false;
  }
  try
  {
    out = json::parse(in);
    return true;
  }
  catch (const json::exception&)
  {
    return false; // cannot happen for files written atomically; treat as not done
  }
}

// The last line of the renderer's stdout that is a JSON object.
json LastJsonLine(const std::string& out)
{
  std::istringstream lines(out);
  std::string line;
  json j;
  while (std::getline(lines, line))
  {
    if (!line.empty() && line[0] == '{')
    {
      try
      {
        j = json::parse(line);
      }
      catch (const json::exception&)
      {
      }
    }
  }
  return j;
}

// What a frame was rendered from: its data set, its render arguments and its reference's. A result
// whose key differs was rendered for another version of the job file (a setting, size or camera
// changed) and is rendered again; it used to count as done, so an edited job kept its old images.
json TaskKey(const cli::BatchJob& job, const cli::BatchTask& t)
{
  json ref;
  for (const auto& r : job.tasks)
  {
    ref = !t.reference.empty() && r.name == t.reference ? json(r.args) : ref;
  }
  return { { "dataset", t.dataset }, { "args", t.args }, { "reference_args", ref } };
}

// The frame's --background (black unless its setting says otherwise): the colour its object's
// pixels are told apart from.
std::array<float, 3> BackgroundOf(const std::vector<std::string>& args)
{
  std::array<float, 3> bg = { 0.f, 0.f, 0.f };
  for (std::size_t i = 0; i + 1 < args.size(); ++i)
  {
    if (args[i] == "--background")
    {
      char c1 = 0, c2 = 0;
      std::istringstream in(args[i + 1]);
      std::array<float, 3> v{};
      if (in >> v[0] >> c1 >> v[1] >> c2 >> v[2] && c1 == ',' && c2 == ',')
      {
        bg = v;
      }
    }
  }
  return bg;
}


json RunTask(const cli::BatchJob& job, const cli::BatchTask& t)
{
  const std::string image = job.outputDir + "/" + t.name + ".png";
  const std::string log = job.outputDir + "/" + t.name + ".log";
  std::vector<std::string> argv = { cli::SelfExecutable(), "render", t.dataset, "-o", image };
  argv.insert(argv.end(), t.args.begin(), t.args.end());
  // Frames reducing one volume alike (an orbit, other sizes) share the reduced mesh.
  for (const std::string& a : t.args)
  {
    if (a.rfind("--tets", 0) == 0 || a.rfind("--max-error", 0) == 0)
    {
      argv.insert(argv.end(), { "--mesh-cache", job.outputDir + "/mesh-cache" });
      break;
    }
  }
  argv.insert(argv.end(), { "--json", "--quiet" });
  const auto start = std::chrono::steady_clock::now();
  const cli::SubprocessResult r = cli::RunProgram(argv, log);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  json res = { { "name", t.name }, { "dataset", t.dataset }, { "camera", t.camera },
    { "setting", t.setting }, { "reference", t.isReference }, { "image", image },
    { "wall_seconds", wall }, { "key", TaskKey(job, t) } };
  if (r.exitCode != 0)
  {
    // The renderer's error is its last line (a warning may come first), less the
    // "adaptivert: DATASET: " the batch's own message and the CSV's dataset column already give.
    std::ifstream in(log);
    std::string line, last;
    while (std::getline(in, line))
    {
      last = line.empty() ? last : line;
    }
    for (const std::string& prefix : { std::string("adaptivert: "), t.dataset + ": " })
    {
      if (last.compare(0, prefix.size(), prefix) == 0)
      {
        last.erase(0, prefix.size());
      }
    }
    res["status"] = "failed";
    res["error"] = last.empty() ? "render exited with code " + std::to_string(r.exitCode) : last;
    return res;
  }
  std::error_code ec;
  if (!std::filesystem::exists(image, ec))
  {
    res["status"] = "failed";
    res["error"] = "render wrote no image";
    return res;
  }
  const json out = LastJsonLine(r.out);
  res["status"] = "ok";
  res["render"] = out;
  if (!t.reference.empty())
  {
    json ref;
    if (ReadResult(ResultPath(job, t.reference), ref) && ref.value("status", "") == "ok")
    {
      const auto m = art::CompareOnBackground(
        art::ReadImage(ref["image"].get<std::string>()), art::ReadImage(image), BackgroundOf(t.args));
      const auto finite = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
      res["rmse"] = m.rmse;
      res["psnr_db"] = finite(m.psnr);
      res["ssim"] = m.ssim;
      res["object_rmse"] = m.objectRmse;
      res["object_psnr_db"] = finite(m.objectPsnr);
      res["object_ssim"] = m.objectSsim;
    }
  }
  return res;
}

// The reduction's time (a volume's frames), as the renderer reports it.
json ReduceSeconds(const json& out)
{
  const bool reduced = out.is_object() && out.contains("mesh") && out["mesh"].is_string() &&
    out["mesh"].get<std::string>().rfind("adaptive tets", 0) == 0;
  return reduced && out.contains("build_seconds") ? out["build_seconds"] : json();
}

std::string CsvField(const json& v)
{
  if (v.is_null())
  {
    return "";
  }
  std::string s = v.is_string() ? v.get<std::string>() : v.dump();
  if (s.find_first_of(",\"\n") != std::string::npos)
  {
    std::string q = "\"";
    for (char c : s)
    {
      q += (c == '"') ? std::string("\"\"") : std::string(1, c);
    }
    return q + "\"";
  }
  return s;
}

// Render time as the renderer measured it when it says so, else the process wall time.
json RenderSeconds(const json& r)
{
  const json& out = r.contains("render") ? r["render"] : json();
  for (const char* k : { "render_seconds", "seconds" })
  {
    if (out.is_object() && out.contains(k) && out[k].is_number())
    {
      return out[k];
    }
  }
  return r.value("wall_seconds", 0.0);
}

void WriteSummary(const cli::BatchJob& job, const std::string& csvPath, const std::string& chartPath, bool quiet)
{
  std::ostringstream csv;
  csv << "name,dataset,camera,setting,status,render_seconds,reduce_seconds,tets,rmse,psnr_db,ssim,object_rmse,"
         "object_psnr_db,object_ssim,image,error\n";
  for (const auto& t : job.tasks)
  {
    json r;
    if (!ReadResult(ResultPath(job, t.name), r))
    {
      continue;
    }
    const json& out = r.contains("render") ? r["render"] : json();
    csv << CsvField(r["name"]) << "," << CsvField(r["dataset"]) << "," << CsvField(r["camera"]) << ","
        << CsvField(r.value("setting", "")) << "," << CsvField(r["status"]) << ","
        << CsvField(RenderSeconds(r)) << "," << CsvField(ReduceSeconds(out)) << ","
        << CsvField(out.is_object() && out.contains("tets") ? out["tets"] : json()) << ","
        << CsvField(r.value("rmse", json())) << "," << CsvField(r.value("psnr_db", json())) << ","
        << CsvField(r.value("ssim", json())) << "," << CsvField(r.value("object_rmse", json())) << ","
        << CsvField(r.value("object_psnr_db", json())) << "," << CsvField(r.value("object_ssim", json())) << ","
        << CsvField(r["image"]) << ","
        << CsvField(r.value("error", json())) << "\n";
  }
  art::WriteFileAtomic(csvPath, csv.str());
  // The chart is drawn by matplotlib; a machine without it still gets the CSV.
  const std::string script = cli::ResourcePath("scripts", ART_SCRIPT_DIR) + "/speed_accuracy_chart.py";
  if (fs::exists("/usr/bin/python3") && fs::exists(script))
  {
    const auto r = cli::RunProgram({ "/usr/bin/python3", script, csvPath, chartPath,
                                     "Batch: render time against error (" + fs::path(job.file).filename().string() + ")" },
      job.outputDir + "/chart.log");
    if (r.exitCode != 0 && !quiet)
    {
      std::fprintf(stderr, "adaptivert: %s: chart not drawn (see %s/chart.log)\n", chartPath.c_str(),
        job.outputDir.c_str());
    }
  }
}

void Declare(cli::Options& o)
{
  o.Add("poll", 0, "S", "seconds between looks at frames other processes hold", "1");
  o.Add("retry-failed", 0, "", "render again the frames that failed in an earlier run");
}

// Results of frames rendered for another version of the job (another setting, size, camera or
// reference) are dropped, and with --retry-failed the failed ones too.
void DropStaleResults(const cli::Options& o, const cli::BatchJob& job)
{
  std::error_code ec;
  size_t stale = 0;
  for (const auto& t : job.tasks)
  {
    json r;
    if (ReadResult(ResultPath(job, t.name), r) && r.contains("key") && r["key"] != TaskKey(job, t))
    {
      fs::remove(ResultPath(job, t.name), ec);
      ++stale;
    }
  }
  if (stale && !o.Flag("quiet"))
  {
    std::fprintf(stderr, "adaptivert: %s: %zu frame%s in %s %s rendered with other settings: rendering again\n",
      job.file.c_str(), stale, stale == 1 ? "" : "s", job.outputDir.c_str(), stale == 1 ? "was" : "were");
  }
  if (o.Flag("retry-failed"))
  {
    for (const auto& t : job.tasks)
    {
      json r;
      if (ReadResult(ResultPath(job, t.name), r) && r.value("status", "") != "ok")
      {
        fs::remove(ResultPath(job, t.name), ec);
      }
    }
  }
}

struct RunCounts
{
  size_t rendered = 0, failed = 0;
  // A data set's frames that fail alike (a missing file: one per camera and setting, 120 lines
  // for 40 cameras) are named once, then counted.
  std::map<std::pair<std::string, std::string>, size_t> alike;
};

// Renders every frame no process has rendered or claimed, references first, until all are done
// (some perhaps by other processes sharing the job).
RunCounts RenderFrames(const cli::BatchJob& job, cli::ProgressBar& bar, double poll)
{
  RunCounts n;
  for (;;)
  {
    size_t done = 0;
    bool progressed = false;
    for (const auto& t : job.tasks)
    {
      json r;
      if (ReadResult(ResultPath(job, t.name), r))
      {
        ++done;
        continue;
      }
      json ref;
      if (!t.reference.empty() && !ReadResult(ResultPath(job, t.reference), ref))
      {
        continue; // its reference is still being rendered (here or by another process)
      }
      cli::FrameClaim claim(job.outputDir + "/" + t.name + ".lock");
      if (!claim.Held() || ReadResult(ResultPath(job, t.name), r))
      {
        continue;
      }
      bar.Update(double(done) / job.tasks.size(), t.name);
      const json res = RunTask(job, t);
      art::WriteFileAtomic(ResultPath(job, t.name), res.dump(2));
      ++n.rendered;
      if (res["status"] != "ok")
      {
        ++n.failed;
        const std::string error = res["error"].get<std::string>();
        if (n.alike[{ t.dataset, error }]++ == 0)
        {
          bar.Finish();
          std::fprintf(stderr, "adaptivert: %s: frame %s failed: %s\n", t.dataset.c_str(), t.name.c_str(), error.c_str());
        }
      }
      progressed = true;
      ++done;
    }
    if (done == job.tasks.size())
    {
      return n;
    }
    if (!progressed)
    {
      std::this_thread::sleep_for(std::chrono::duration<double>(poll));
    }
  }
}

int Run(const cli::Options& o)
{
  if (o.Positional().size() != 1)
  {
    throw cli::UsageError("needs exactly one JOB.json");
  }
  const cli::BatchJob job = cli::LoadBatchJob(o.Positional()[0]);
  for (const auto& note : job.notes)
  {
    std::fprintf(stderr, "adaptivert: %s: note: %s\n", job.file.c_str(), note.c_str());
  }
  std::error_code ec;
  fs::create_directories(job.outputDir, ec);
  if (!fs::is_directory(job.outputDir))
  {
    throw art::Error("cannot create output folder '" + job.outputDir + "'", job.file);
  }
  DropStaleResults(o, job);
  const bool quiet = o.Flag("quiet") || o.Flag("json");
  cli::ProgressBar bar(quiet);
  const RunCounts n = RenderFrames(job, bar, o.GetDouble("poll"));
  bar.Update(1.0, "batch");
  bar.Finish();
  for (const auto& [key, count] : n.alike)
  {
    if (count > 1)
    {
      std::fprintf(stderr, "adaptivert: %s: %zu more frames failed alike (%s)\n", key.first.c_str(), count - 1,
        key.second.c_str());
    }
  }
  // Frames that failed in an earlier run fail this one too: a re-run (a CI step, a resumed job)
  // reported 'tasks 6 (0 rendered now, 0 failed)' and exited 0 over four failed frames.
  size_t failedAll = 0;
  for (const auto& t : job.tasks)
  {
    json r;
    failedAll += ReadResult(ResultPath(job, t.name), r) && r.value("status", "") != "ok" ? 1 : 0;
  }
  const size_t earlier = failedAll > n.failed ? failedAll - n.failed : 0;
  const std::string csv = job.outputDir + "/results.csv", chart = job.outputDir + "/speed_accuracy.png";
  WriteSummary(job, csv, chart, quiet);
  if (o.Flag("json"))
  {
    // Paths are escaped: a folder named with a quote or backslash gave JSON no parser reads.
    const nlohmann::ordered_json j = { { "tasks", job.tasks.size() }, { "rendered", n.rendered },
      { "failed", failedAll }, { "failed_earlier", earlier }, { "csv", csv }, { "chart", chart } };
    std::printf("%s\n", j.dump().c_str());
  }
  else
  {
    std::printf("tasks        %zu (%zu rendered now, %zu failed%s)\n", job.tasks.size(), n.rendered, failedAll,
      earlier ? (", " + std::to_string(earlier) + " of them in an earlier run: --retry-failed renders them again").c_str()
              : "");
    std::printf("results      %s\n", csv.c_str());
    std::printf("chart        %s\n", chart.c_str());
  }
  return failedAll ? cli::ExitFailure : cli::ExitOk;
}

cli::Registrar reg({ "batch",
  "render a job file of data sets x cameras x settings; CSV of time and error; resumable",
  "adaptivert batch [options] JOB.json",
  "  adaptivert batch tests/jobs/orbit_small.json\n"
  "  adaptivert batch job.json & adaptivert batch job.json   # two processes share the frames\n",
  Declare, Run });
} // namespace
