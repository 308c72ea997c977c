#include "batch/BatchJob.h"
#include "DataLoader.h"
#include "Error.h"
#include "rendering/Render.h"
#include "TransferFunction.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>
#include <type_traits>
#include <fstream>

namespace fs = std::filesystem;
using nlohmann::json;

namespace cli
{
namespace
{
struct Cam
{
  double azimuth = 0, elevation = 0, zoom = 1;
};

std::string Scalar(const json& v)
{
  if (v.is_string())
  {
    return v.get<std::string>();
  }
  return v.dump(); // numbers print as in JSON
}

// A setting's file (a transfer function: "tf": "bone.tf") is relative to the job file, as its data
// sets and output are; it was taken relative to the folder the batch ran in, so a job run from
// elsewhere failed every frame with "cannot open transfer-function file". Preset names stay.
std::string SettingValue(const std::string& key, const json& value, const fs::path& base)
{
  std::string v = Scalar(value);
  if (key == "tf" && value.is_string() && !v.empty() && fs::path(v).is_relative())
  {
    const auto presets = art::TransferFunction::PresetNames();
    if (std::find(presets.begin(), presets.end(), v) == presets.end())
    {
      v = (base / v).lexically_normal().string();
    }
  }
  return v;
}

// Options that change what the picture shows, not how closely it is approximated: a setting
// that sets one of them otherwise than the reference is scored against another picture.
std::vector<std::string> LookNotes(const json& settings, const json& reference)
{
  static const std::set<std::string> approximation = { "tets", "max-error", "refinement", "relocate", "no-relocate",
    "plain-reduction", "mesh-cache", "ert", "integrator", "threads", "verbose", "accelerator", "threshold",
    "subdivisions", "plane-weight", "no-top-grid", "reference", "no-error" };
  std::vector<std::string> notes;
  if (!reference.is_object())
  {
    return notes;
  }
  for (size_t s = 0; s < settings.size(); ++s)
  {
    if (!settings[s].is_object())
    {
      continue;
    }
    std::set<std::string> keys;
    for (const json* side : { &settings[s], &reference })
    {
      for (const auto& item : side->items())
      {
        const std::string& k = item.key();
        if (!k.empty() && k[0] != '_' && !approximation.count(k) &&
          (!settings[s].contains(k) || !reference.contains(k) || settings[s][k] != reference[k]))
        {
          keys.insert(k);
        }
      }
    }
    if (!keys.empty())
    {
      std::string list;
      for (const auto& k : keys)
      {
        list += (list.empty() ? "" : ", ") + k;
      }
      notes.push_back("setting " + std::to_string(s) + " " + settings[s].dump() + " differs from the reference in " +
        list + ": its error is against the reference's picture (give the reference the same " + list +
        ", or such settings a job of their own)");
    }
  }
  return notes;
}

// {"tets": 20000, "exact": true} -> --tets 20000 --exact; false drops the flag, and so does a
// setting only another kind of data takes (a job may hold volumes and triangle scenes alike).
std::vector<std::string> OptionsToArgs(const json& s, std::string& text, const std::string& file, const fs::path& base,
  const art::DataKind* kind, std::vector<std::string>* dropped = nullptr)
{
  if (!s.is_object())
  {
    throw art::Error("a setting must be an object of render options, got " + s.dump(), file);
  }
  std::vector<std::string> args;
  for (const auto& [key, value] : s.items())
  {
    if (!key.empty() && key[0] == '_')
    {
      continue; // free for comments, as everywhere in a job
    }
    // A key render does not know ({"name": "fine"}, "tet" for "tets") failed every frame, each
    // after the job had started, with render's 'unknown option'.
    if (!cli::IsRenderOption(key))
    {
      throw art::Error("setting '" + key + "' is not a render option (a setting's keys are render's long options, "
                       "as 'adaptivert render --help' lists them; '_' keys are comments)",
        file);
    }
    // The batch gives every frame its own file, size and camera, and reads render's --json:
    // {"output": "x.png"} overwrote x.png beside the job, {"help": true} left no image yet
    // counted the frame as rendered.
    static const std::set<std::string> own = { "output", "o", "help", "h", "json", "quiet", "q" };
    static const std::set<std::string> job = { "size", "s", "azimuth", "elevation", "zoom" };
    if (own.count(key))
    {
      throw art::Error("setting '" + key + "' is the batch's own: it sets it for every frame", file);
    }
    if (job.count(key))
    {
      throw art::Error("setting '" + key + "' belongs in the job's \"size\" or \"cameras\", not in a setting", file);
    }
    if (kind && !cli::OptionAppliesTo(key, *kind))
    {
      if (dropped)
      {
        dropped->push_back(key);
      }
      continue;
    }
    if (value.is_boolean())
    {
      if (value.get<bool>())
      {
        args.push_back("--" + key);
        text += (text.empty() ? "" : " ") + key;
      }
      continue;
    }
    if (value.is_object() || value.is_array() || value.is_null())
    {
      throw art::Error("setting '" + key + "' must be a number, string or boolean", file);
    }
    args.push_back("--" + key);
    args.push_back(SettingValue(key, value, base));
    text += (text.empty() ? "" : " ") + key + "=" + Scalar(value);
  }
  return args;
}

// A job field of the expected JSON type, or an error naming the field and what it holds.
template <class T>
T Field(const json& o, const char* key, T fallback, const std::string& file)
{
  if (!o.is_object() || !o.contains(key))
  {
    return fallback;
  }
  const json& v = o.at(key);
  if constexpr (std::is_same_v<T, std::string>)
  {
    if (v.is_string())
    {
      return v.get<std::string>();
    }
    throw art::Error(std::string("\"") + key + "\" must be a string, got " + v.dump(), file);
  }
  else
  {
    if (v.is_number())
    {
      return v.get<T>();
    }
    throw art::Error(std::string("\"") + key + "\" must be a number, got " + v.dump(), file);
  }
}

// A misspelt key ("setting", "refrence", "azimut") was ignored without a word: the batch rendered
// the default settings, no reference or camera 0 and reported success. Keys starting with '_' are
// left for comments.
void KnownKeys(const json& o, const std::set<std::string>& known, const std::string& where, const std::string& file)
{
  if (!o.is_object())
  {
    return;
  }
  for (const auto& [key, value] : o.items())
  {
    if (!known.count(key) && (key.empty() || key[0] != '_'))
    {
      std::string list;
      for (const auto& k : known)
      {
        list += (list.empty() ? "" : ", ") + k;
      }
      throw art::Error("unknown key \"" + key + "\" in " + where + " (known: " + list + ")", file);
    }
  }
}

std::vector<Cam> Cameras(const json& j, const std::string& file)
{
  std::vector<Cam> cams;
  if (j.is_null())
  {
    cams.push_back({});
  }
  else if (j.is_object())
  {
    KnownKeys(j, { "orbit", "elevation", "zoom" }, "cameras", file);
    // Read as a double: 2.5 became 2 frames, and 1e10 overflowed an int.
    const double orbit = Field(j, "orbit", 1.0, file);
    if (!(orbit >= 1 && orbit <= 100000) || orbit != std::floor(orbit))
    {
      throw art::Error("cameras.orbit must be a whole number 1..100000, got " + j["orbit"].dump(), file);
    }
    const int n = static_cast<int>(orbit);
    for (int i = 0; i < n; ++i)
    {
      cams.push_back({ 360.0 * i / n, Field(j, "elevation", 0.0, file), Field(j, "zoom", 1.0, file) });
    }
  }
  else if (j.is_array())
  {
    if (j.empty())
    {
      throw art::Error("cameras must not be an empty list", file);
    }
    for (const auto& c : j)
    {
      KnownKeys(c, { "azimuth", "elevation", "zoom" }, "a camera", file);
      cams.push_back({ Field(c, "azimuth", 0.0, file), Field(c, "elevation", 0.0, file), Field(c, "zoom", 1.0, file) });
    }
  }
  else
  {
    throw art::Error("cameras must be {\"orbit\": N, ...} or a list of cameras", file);
  }
  return cams;
}

std::string Num(const char* fmt, int v)
{
  char b[32];
  std::snprintf(b, sizeof b, fmt, v);
  return b;
}
} // namespace

namespace
{
json ReadJobFile(const std::string& path)
{
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
  {
    throw art::Error(fs::exists(path, ec) ? "is not a file" : "no such file", path);
  }
  try
  {
    std::ifstream in(path);
    return json::parse(in);
  }
  catch (const json::exception& e)
  {
    throw art::Error(std::string("not valid JSON: ") + e.what(), path);
  }
}

// Frames are named after the file; two files of one name (a/ct.mha, b/ct.mha) shared their
// frames, and the second was never rendered. Later ones get -2, -3, .. (stable per job file).
// A DICOM folder written with its trailing slash ("series/") has no stem: its frames were
// named "_c000_s00.png". A folder is named whole (a dot in it is no extension).
std::string FrameStem(const std::string& ds, std::set<std::string>& stems)
{
  std::error_code ec;
  fs::path named(ds);
  named = named.has_filename() ? named : named.parent_path();
  // "brain.nii.gz" is "brain", not "brain.nii".
  fs::path leaf = named.filename();
  if (leaf.extension() == ".gz" || leaf.extension() == ".GZ")
  {
    leaf = leaf.stem();
  }
  const std::string plain = fs::is_directory(named, ec) ? named.filename().string() : leaf.stem().string();
  std::string stem = plain;
  for (int n = 2; !stems.insert(stem).second; ++n)
  {
    stem = plain + "-" + std::to_string(n);
  }
  return stem;
}

// What the job file says beyond its data sets, checked once.
struct JobPlan
{
  fs::path base;
  std::string size;
  std::vector<Cam> cams;
  json settings, reference;
  bool withReference = false;
};

// One data set's reference frames (into refs) and frames (into frames), camera by camera.
void DatasetTasks(const JobPlan& plan, const std::string& ds, const std::string& stem, const std::string& path,
  BatchJob& job, std::vector<BatchTask>& refs, std::vector<BatchTask>& frames)
{
  art::DataKind dsKind;
  const art::DataKind* kind = nullptr;
  try
  {
    dsKind = art::KindOf(ds);
    kind = &dsKind;
  }
  catch (const art::Error&)
  {
    // a missing or unknown file fails its frames with the loader's own message
  }
  const std::vector<Cam>& cams = plan.cams;
  for (size_t c = 0; c < cams.size(); ++c)
  {
    const std::vector<std::string> view = { "--size", plan.size, "--azimuth", std::to_string(cams[c].azimuth),
      "--elevation", std::to_string(cams[c].elevation), "--zoom", std::to_string(cams[c].zoom), "--fit",
      cams.size() > 1 ? "orbit" : "view" }; // one distance for every view
    const std::string camName = stem + "_c" + Num("%03d", static_cast<int>(c));
    std::string refName;
    if (plan.withReference)
    {
      BatchTask r;
      r.name = refName = camName + "_reference";
      r.dataset = ds;
      r.args = OptionsToArgs(plan.reference, r.setting, path, plan.base, kind);
      r.args.insert(r.args.begin(), view.begin(), view.end());
      r.isReference = true;
      r.camera = static_cast<int>(c);
      refs.push_back(std::move(r));
    }
    for (size_t s = 0; s < plan.settings.size(); ++s)
    {
      BatchTask t;
      t.name = camName + "_s" + Num("%02d", static_cast<int>(s));
      t.dataset = ds;
      std::vector<std::string> dropped;
      t.args = OptionsToArgs(plan.settings[s], t.setting, path, plan.base, kind, &dropped);
      if (c == 0 && !dropped.empty())
      {
        // Its frames of this data set may repeat another setting's (a surface takes no tets).
        std::string list;
        for (const auto& k : dropped)
        {
          list += (list.empty() ? "" : ", ") + k;
        }
        job.notes.push_back("setting " + std::to_string(s) + "'s " + list + " do" + (dropped.size() == 1 ? "es" : "") +
          " not apply to " + art::KindName(dsKind) + "s: left out for " + ds);
      }
      t.args.insert(t.args.begin(), view.begin(), view.end());
      t.reference = refName;
      t.camera = static_cast<int>(c);
      frames.push_back(std::move(t));
    }
  }
}
} // namespace

BatchJob LoadBatchJob(const std::string& path)
{
  const json j = ReadJobFile(path);
  try
  {
    if (!j.is_object())
    {
      throw art::Error("a job is a JSON object of \"datasets\", \"settings\", ...; got " + std::string(j.type_name()), path);
    }
    KnownKeys(j, { "output", "datasets", "size", "cameras", "settings", "reference" }, "the job", path);
    JobPlan plan;
    plan.base = fs::absolute(path).parent_path();
    BatchJob job;
    job.file = path;
    job.outputDir = (plan.base / Field(j, "output", std::string("frames"), path)).lexically_normal().string();
    if (!j.contains("datasets") || !j["datasets"].is_array() || j["datasets"].empty())
    {
      throw art::Error("needs \"datasets\": a non-empty list of files", path);
    }
    plan.size = Field(j, "size", std::string("400x400"), path);
    plan.cams = Cameras(j.contains("cameras") ? j["cameras"] : json(), path);
    plan.settings = j.contains("settings") ? j["settings"] : json::array({ json::object() });
    if (!plan.settings.is_array() || plan.settings.empty())
    {
      throw art::Error("\"settings\" must be a non-empty list", path);
    }
    plan.withReference = j.contains("reference");
    if (plan.withReference)
    {
      plan.reference = j["reference"];
      job.notes = LookNotes(plan.settings, plan.reference);
    }
    std::vector<BatchTask> refs, frames;
    std::set<std::string> stems;
    for (const auto& d : j["datasets"])
    {
      if (!d.is_string())
      {
        throw art::Error("\"datasets\" must list file names, got " + d.dump(), path);
      }
      const std::string ds = (plan.base / d.get<std::string>()).lexically_normal().string();
      DatasetTasks(plan, ds, FrameStem(ds, stems), path, job, refs, frames);
    }
    job.tasks = std::move(refs);
    job.tasks.insert(job.tasks.end(), frames.begin(), frames.end());
    return job;
  }
  catch (const json::exception& e)
  {
    throw art::Error(std::string("bad job: ") + e.what(), path);
  }
}
} // namespace cli
