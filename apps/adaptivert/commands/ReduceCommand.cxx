// adaptivert reduce IN OUT.vtu: the least-squares reducer from voxels to an adaptive tet grid
// (AdaptiveRT::Reduction), to a tet budget or an error bound, optionally with levels on the way.
#include "cli/NumberFormat.h"
#include "cli/Command.h"

#ifdef ART_HAVE_Reduction
#include "DataLoader.h"
#include "FullResolutionMesh.h"
#include "Error.h"
#include "cli/Json.h"
#include "cli/LoadOptions.h"
#include "MeshQuality.h"
#include "Progress.h"
#include "cli/ProgressBar.h"
#include "commands/RegionReduction.h"
#include "rendering/DefaultFrame.h"
#include "rendering/ReductionTargets.h"
#include "rendering/TransferFunctionChoice.h"
#include "ReducerVTK.h"
#include "TetReducer.h"

#ifdef ART_HAVE_TetRayCast
#include "TransferFunction.h"
#endif

#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace
{
using cli::Grouped;

void Declare(cli::Options& o)
{
  o.Add("output", 'o', "FILE", "the output .vtu, as render takes it (or give it after the input)");
  o.Add("array", 0, "NAME", "point array to reduce (default: the active scalars, else the first one-component array); NAME:magnitude or NAME:N for a vector's magnitude or component N");
  o.Add("tets", 't', "N", "stop at N tetrahedra (or N% of the voxel count)");
  o.Add("max-error", 'e', "E",
    "stop when the error (opacity-weighted with --tf) is at most E data units (E% of the scalar range)");
  o.Add("metric", 0, "rms|max", "which error --max-error bounds", "rms");
  o.Add("levels", 0, "LIST", "also write coarser levels from the same run, e.g. 0.01%,0.1%,5000: OUT_<n>.vtu "
    "(nested with bisection and edge; not with anisotropic, where each is adapted from the calibration of the one "
    "before, nor with --relocate)");
  o.Add("refine-fraction", 0, "F", "tet growth per refinement level (0: automatic, 0.5 then 0.2 near a budget with bisection, 0.2 with edge)", "0");
  o.Add("tolerance", 0, "T", "conjugate-gradient relative residual", "1e-8");
  o.Add("refinement", 0, "bisection|edge|anisotropic",
    "bisection: newest-vertex, near-regular tets; edge: split the edges that remove the most error "
    "(thin tets along sharp surfaces, lower error per tet, slower); anisotropic: MMG3D remeshes to the "
    "voxels' Hessian metric (tets long along surfaces and thin across them, far lower error per vertex; "
    "a budget is met within 5%)", "bisection");
  o.Add("relocate", 0, "", "move each output's vertices off the bisection lattice toward the surfaces they fit "
    "(lower error at the same tets; levels no longer nested; slower)");
  o.Add("clamp", 0, "", "clamp each vertex value to the range of the voxels under its tets (no overshoot at sharp edges; for maximum-intensity projection)");
  o.Add("tf", 0, "NAME|FILE",
    "reduce for this transfer function's opacity (a preset, e.g. ct-skin-bone, or a file of "
    "'scalar r g b opacity' lines, or a ParaView preset .json): tets go where opacity changes, "
    "and a value fitted past its voxels into a more opaque range is clamped to theirs");
  cli::DeclareRegionOptions(o);
  cli::AddLoadOptions(o);
}

// The output path, -o OUT as render takes it or OUT after the input ('reduce in.mha -o out.vtu'
// was an unknown option), and the input.
std::pair<std::string, std::string> InputAndOutput(const cli::Options& o)
{
  const auto& pos = o.Positional();
  if (pos.size() != (o.Has("output") ? 1u : 2u))
  {
    throw cli::UsageError(o.Has("output") && pos.size() == 2 ? "give the output once: after the input or with -o"
                                                           : "needs an input volume and an output .vtu");
  }
  const std::string in = pos[0], outPath = o.Has("output") ? o.Get("output") : pos[1];
  std::string ext = std::filesystem::path(outPath).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".vtu") // any case, as SaveMesh takes it (OUT.VTU)
  {
    throw cli::UsageError("the output must be a .vtu file, got '" + outPath + "'");
  }
  return { in, outPath };
}

// The options that need no data: checked before the volume is read.
art::ReducerOptions OptionsBeforeLoading(const cli::Options& o)
{
  if (!o.Has("tets") && !o.Has("max-error"))
  {
    throw cli::UsageError("give --tets N or --max-error E");
  }
  art::ReducerOptions opt;
  const std::string metric = o.Get("metric");
  if (metric != "rms" && metric != "max")
  {
    throw cli::UsageError("--metric is rms or max, got '" + metric + "'");
  }
  opt.ErrorMetric = metric == "max" ? art::ReducerOptions::Metric::Max : art::ReducerOptions::Metric::RMS;
  opt.Refine = cli::ParseRefinement(o.Get("refinement"), "--refinement");
  opt.RefineFraction = o.GetDouble("refine-fraction");
  opt.ClampToVoxels = o.Flag("clamp");
  opt.RelocateVertices = o.Flag("relocate");
  opt.RelocateVoxelsPerTet = 0; // asked for: every mesh, however fine
  opt.SolverTolerance = o.GetDouble("tolerance");
  if (!(opt.RefineFraction >= 0.0 && opt.RefineFraction <= 4.0) || !(opt.SolverTolerance > 0 && opt.SolverTolerance < 1))
  {
    throw cli::UsageError("--refine-fraction must be in [0, 4] and --tolerance in (0, 1)");
  }
  if (o.Has("tf"))
  {
    cli::CheckTransferFunctionName(o.Get("tf"));
  }
  return opt;
}

// --tf's opacity as the fit's weights.
// `image`: the samples, for a preset ("auto" looks at them, as render does).
void WeightByTransferFunction(
  const cli::Options& o, vtkImageData* image, const art::VoxelVolume& volume, art::ReducerOptions& opt)
{
  if (!o.Has("tf"))
  {
    return;
  }
#ifdef ART_HAVE_TetRayCast
  const std::string tf = o.Get("tf");
  const art::TransferFunction f = art::TransferFunction::NamesFile(tf)
    ? art::TransferFunction::FromFile(tf)
    : art::TransferFunction::PresetFor(tf, image, volume.Range[0], volume.Range[1]);
  opt.ScalarOpacity = f.OpacityPoints();
#else
  (void)image;
  (void)volume;
  (void)opt;
  throw cli::UsageError("--tf needs the TetRayCast module (transfer functions), which is not in this build");
#endif
}

// --tets, --max-error and --levels, whose percentages need the volume.
void SetBudgets(const cli::Options& o, long long voxels, art::ReducerOptions& opt)
{
  if (o.Has("tets"))
  {
    opt.TargetTets = cli::ParseBudget(o.Get("tets"), voxels, "--tets");
  }
  if (o.Has("max-error"))
  {
    opt.TargetError = cli::ParseMaxError(o.Get("max-error"), opt.ErrorRelative);
  }
  if (o.Has("levels"))
  {
    std::string list = o.Get("levels");
    size_t a = 0;
    while (a <= list.size())
    {
      const size_t b = std::min(list.find(',', a), list.size());
      const long long n = cli::ParseBudget(list.substr(a, b - a), voxels, "--levels");
      // A level is a coarser mesh met on the way to the output; one at or past --tets never is
      // (it was dropped without a word).
      if (opt.TargetTets > 0 && n >= opt.TargetTets)
      {
        throw cli::UsageError("--levels: " + std::to_string(n) + " tets is not below --tets " +
          std::to_string(opt.TargetTets) + " (levels are the coarser meshes written on the way)");
      }
      opt.Levels.push_back(n);
      a = b + 1;
    }
  }
  for (long long b : opt.Levels)
  {
    if (b < 6)
    {
      throw cli::UsageError("a level below 6 tets is not possible (" + std::to_string(b) + ")");
    }
  }
  if (opt.TargetTets > 0 && opt.TargetTets < 6)
  {
    throw cli::UsageError("--tets must be at least 6 (one box)");
  }
}

// The meshes, coarsest first. A budget at the full resolution (`full`) is the voxels' own mesh,
// its coarser levels reduced as usual.
std::vector<art::ReducedMesh> Reduce(
  const art::ReducerOptions& opt, const art::VoxelVolume& volume, bool full, art::Progress& progress)
{
  if (!full)
  {
    return art::TetReducer(opt).Run(volume, &progress);
  }
  std::vector<art::ReducedMesh> meshes;
  if (!opt.Levels.empty())
  {
    art::ReducerOptions coarser = opt;
    coarser.TargetTets = *std::max_element(opt.Levels.begin(), opt.Levels.end());
    coarser.Levels.erase(
      std::remove(coarser.Levels.begin(), coarser.Levels.end(), coarser.TargetTets), coarser.Levels.end());
    meshes = art::TetReducer(coarser).Run(volume, &progress);
  }
  meshes.push_back(art::FullResolutionMesh(volume));
  return meshes;
}

// Writes each mesh (levels as OUT_<tets>.vtu, the last as OUT.vtu), once every one has passed its
// conformity check: a failed check must not have replaced an existing OUT.vtu already.
// `placement`: the volume's field data, whose IndexToWorld, Frame and source_visible_bounds each
// mesh takes.
std::vector<cli::Json> WriteMeshes(const std::vector<art::ReducedMesh>& meshes, const std::string& outPath,
  const art::VoxelVolume& volume, const art::ReducerOptions& opt, bool json, vtkFieldData* placement,
  art::QualityReport& finalQuality)
{
  std::vector<art::QualityReport> quality;
  for (const auto& m : meshes)
  {
    const auto& mq = quality.emplace_back(
      art::MeasureQuality(m.Points.data(), m.NumberOfVertices(), m.Tets.data(), m.NumberOfTets()));
    if (!mq.Valid())
    {
      throw art::Error("internal: a reduced mesh failed its conformity check: " + mq.Summary(), outPath);
    }
  }
  finalQuality = quality.back();
  const double range = volume.Range[1] - volume.Range[0];
  const double pct = range > 0 ? 100.0 / range : 0.0;
  const std::filesystem::path op(outPath);
  std::vector<cli::Json> levels;
  for (size_t i = 0; i < meshes.size(); ++i)
  {
    const auto& m = meshes[i];
    const bool last = i + 1 == meshes.size();
    const std::string file = last ? outPath
                                  : (op.parent_path() / (op.stem().string() + "_" +
                                        std::to_string(m.TargetTets > 0 ? m.TargetTets : m.NumberOfTets()) + ".vtu")).string();
    auto grid = art::ToUnstructuredGrid(m, volume.DoubleValues, &quality[i]);
    // The volume's placement goes with the mesh (its points are in that frame).
    for (const char* name : { "IndexToWorld", "Frame", "source_visible_bounds" })
    {
      if (vtkAbstractArray* a = placement ? placement->GetAbstractArray(name) : nullptr)
      {
        grid->GetFieldData()->AddArray(a);
      }
    }
    art::SaveMesh(grid, file);
    cli::Json j;
    j.Set("file", file).Set("tets", m.NumberOfTets()).Set("vertices", m.NumberOfVertices())
      .Set("target_tets", m.TargetTets).Set("rms_error", m.Rms).Set("max_error", m.Max)
      .Set("rms_error_percent", m.Rms * pct).Set("max_error_percent", m.Max * pct)
      .Set("build_seconds", m.BuildSeconds).Set("target_reached", m.TargetReached);
    if (m.Weighted)
    {
      j.Set("weighted_rms_error", m.WeightedRms).Set("weighted_max_error", m.WeightedMax);
    }
    levels.push_back(j);
    if (!json)
    {
      std::printf("%-12s %s: %s tets, %s vertices, RMS %.4g (%.3f%% of range), max %.4g (%.2f%%), %.2f s%s\n",
        last ? "output" : "level", file.c_str(), Grouped(m.NumberOfTets()).c_str(),
        Grouped(m.NumberOfVertices()).c_str(), m.Rms, m.Rms * pct, m.Max, m.Max * pct, m.BuildSeconds,
        m.TargetReached ? "" : (" (" + cli::UnreachedReason(m, volume, opt.TargetTets == 0) + ")").c_str());
    }
  }
  return levels;
}

void PrintSummary(const cli::Options& o, const std::string& in, const std::string& outPath,
  const art::VoxelVolume& volume, const std::vector<art::ReducedMesh>& meshes, const std::vector<cli::Json>& levels,
  const std::vector<long long>& missing, const std::string& note, const art::QualityReport& q)
{
  const auto& f = meshes.back();
  const long long voxels = volume.NumberOfVoxels();
  const double range = volume.Range[1] - volume.Range[0];
  const double pct = range > 0 ? 100.0 / range : 0.0;
  if (o.Flag("json"))
  {
    cli::Json j;
    j.Set("input", in).Set("output", outPath).Set("voxels", voxels)
      .Set("tets", f.NumberOfTets()).Set("vertices", f.NumberOfVertices())
      .Set("rms_error", f.Rms).Set("max_error", f.Max).Set("rms_error_percent", f.Rms * pct)
      .Set("max_error_percent", f.Max * pct).Set("build_seconds", f.BuildSeconds)
      .Set("target_reached", f.TargetReached).Set("scalar_range", std::vector<double>{ volume.Range[0], volume.Range[1] })
      .Set("min_dihedral_degrees", q.MinDihedralDegrees).Set("min_radius_ratio", q.MinRadiusRatio)
      .Set("mean_radius_ratio", q.MeanRadiusRatio).Set("weighted", f.Weighted);
    if (!note.empty())
    {
      j.Set("note", note);
    }
    if (f.Weighted)
    {
      j.Set("weighted_rms_error", f.WeightedRms).Set("weighted_max_error", f.WeightedMax);
    }
    j.Set("levels", levels);
    j.Set("levels_not_written", std::vector<double>(missing.begin(), missing.end()));
    j.Set("refinement", f.Refinement).Set("levels_nested", f.Nested).Set("vertices_relocated", f.Relocated);
    std::printf("%s\n", j.Str().c_str());
    return;
  }
  std::printf("input        %s (%d x %d x %d = %s voxels, range %g .. %g)\n", in.c_str(), volume.Dims[0],
    volume.Dims[1], volume.Dims[2], Grouped(voxels).c_str(), volume.Range[0], volume.Range[1]);
  std::printf("tets         %s (%.4g%% of the voxel count), %s vertices (%.4g%% of the voxels)\n",
    Grouped(f.NumberOfTets()).c_str(), 100.0 * f.NumberOfTets() / voxels, Grouped(f.NumberOfVertices()).c_str(),
    100.0 * f.NumberOfVertices() / voxels);
  std::printf("error        RMS %.4g, max %.4g data units (%.3f%% / %.2f%% of the range)\n", f.Rms, f.Max,
    f.Rms * pct, f.Max * pct);
  if (f.Weighted)
  {
    std::printf("weighted     RMS %.4g, max %.4g data units (opacity-weighted error of --tf %s)\n", f.WeightedRms,
      f.WeightedMax, o.Get("tf").c_str());
  }
  std::printf("quality      min dihedral %.1f deg, radius ratio min %.3f mean %.3f, 0 inverted, conforming\n",
    q.MinDihedralDegrees, q.MinRadiusRatio, q.MeanRadiusRatio);
  if (meshes.size() > 1)
  {
    const bool aniso = f.Refinement == "anisotropic";
    const std::string how = aniso ? (f.Relocated ? " (each remeshed by MMG3D from a uniform start, its vertices relocated)"
                                                 : " (each remeshed by MMG3D from a uniform start)")
                                  : (f.Relocated ? " (vertices relocated at each level)" : "");
    std::printf("levels       %s%s\n", f.Nested ? "nested" : "not nested", how.c_str());
  }
  std::printf("time         %.2f s\n", f.BuildSeconds);
}

int Run(const cli::Options& o)
{
  const auto [in, outPath] = InputAndOutput(o);
  art::ReducerOptions opt = OptionsBeforeLoading(o);
  const bool region = cli::WantsRegion(o);

  auto image = art::LoadVolume(in, cli::LoadOptionsFrom(o));
  art::RequireOneComponent(image, in);
  if (region)
  {
    return cli::RunRegionReduction(o, in, outPath, image);
  }
  const art::VoxelVolume volume = art::VolumeFromImage(image, in);
  WeightByTransferFunction(o, image, volume, opt);
  SetBudgets(o, volume.NumberOfVoxels(), opt);
  const std::string note = opt.TargetTets > 0 ? cli::CapToFullResolution(opt.TargetTets, volume, "--tets") : "";
  if (!note.empty() && !o.Flag("json"))
  {
    std::fprintf(stderr, "adaptivert: %s: %s\n", in.c_str(), note.c_str());
  }

  cli::ProgressBar bar(o.Flag("quiet"));
  art::Progress progress(bar.Callback());
  const std::vector<art::ReducedMesh> meshes = Reduce(opt, volume, !note.empty(), progress);
  bar.Finish();
  if (meshes.empty())
  {
    throw art::Error("the reduction produced no mesh", in);
  }
  if (auto frame = cli::SourceVisibleBounds(image)) // so the mesh's default view is the volume's
  {
    image->GetFieldData()->AddArray(frame);
  }
  art::QualityReport quality;
  const std::vector<cli::Json> levels =
    WriteMeshes(meshes, outPath, volume, opt, o.Flag("json"), image->GetFieldData(), quality);
  // With --max-error the run may stop before a level's budget: say which files were not written.
  const std::vector<long long> missing = art::UnreachedLevels(opt.Levels, meshes);
  for (long long b : missing)
  {
    std::fprintf(stderr, "adaptivert: %s: level %lld not written: the reduction stopped at %lld tets\n",
      outPath.c_str(), b, static_cast<long long>(meshes.back().NumberOfTets()));
  }
  PrintSummary(o, in, outPath, volume, meshes, levels, missing, note, quality);
  return cli::ExitOk;
}

cli::Registrar reg({ "reduce",
  "reduce a volume to an adaptive tetrahedral grid by least squares (to a tet count or an error)",
  "adaptivert reduce [options] IN OUT.vtu  (or IN -o OUT.vtu)",
  "  adaptivert reduce data/ct-head-128.mha head.vtu --tets 20000\n"
  "  adaptivert reduce head.mha head.vtu --max-error 1% --metric rms\n"
  "  adaptivert reduce head.mha head.vtu --tets 1% --levels 0.01%,0.1%   (writes head_<n>.vtu too)\n"
  "  adaptivert reduce data/ct-head-128.mha head.vtu --tets 50000 --tf ct-skin-bone\n"
  "  adaptivert reduce data/ct-head-128.mha bone.vtu --region 300:3000 --tets 50000   (tets only in the bone)\n"
  "  adaptivert reduce labels.nii organs.vtu --labels --tets 100000   (one mesh, cell array 'label')\n",
  Declare, Run });
} // namespace
#endif
