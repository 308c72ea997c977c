// The tet caster behind `adaptivert render` for volumes and tet meshes. A volume becomes tets
// (reduced with --tets / --max-error when the Reduction module is built, else full resolution),
// is cast cell by cell, and is compared with the full-resolution voxel reference render.
#include "AtomicFile.h"
#include "Camera.h"
#include "cli/Command.h"
#include "DataLoader.h"
#include "Error.h"
#include "ImageIO.h"
#include "ImageMetrics.h"
#include "cli/Json.h"
#include "cli/LoadOptions.h"
#include "rendering/DefaultFrame.h"
#include "rendering/LabelColours.h"
#include "rendering/MeshCache.h"
#include "ParallelTiles.h"
#include "cli/ProgressBar.h"
#include "rendering/ReducedTets.h"
#include "rendering/ReductionTargets.h"
#include "rendering/Render.h"
#include "rendering/TransferFunctionChoice.h"
#include "TetMesh.h"
#include "TetRayCaster.h"
#include "TransferFunction.h"
#include "VisibleBounds.h"
#include "VoxelReferenceCaster.h"

#ifdef ART_HAVE_Reduction
#include "MmgRemesher.h"
#include "ReducerVTK.h"
#include "TetReducer.h"
#endif

#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <iomanip>
#include <sstream>
#include <vector>

namespace
{
double Seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void Declare(cli::Options& o)
{
  o.Add("array", 0, "NAME", "point (or cell) array to render (default: the active scalars, else the first one-component array); NAME:magnitude or "
    "NAME:N for a vector's magnitude or component N");
  o.Add("tf", 0, "NAME|FILE",
    "transfer function: a preset (auto = ct-skin-bone on CT in Hounsfield units, else from the data: background "
    "clear, a grey ramp over its 1st-99.5th percentiles, labels in distinct colours; under --mip a window; ct-skin-bone, "
    "ct-bone, grey-ramp, constant, labels: one colour per integer, the default for a label mesh) or a file of 'scalar r g b opacity' lines, or a ParaView preset exported as .json",
    "auto");
  o.Add("label-colours", 0, "MODE", cli::LabelColouringHelp(), "values");
  o.Add("unit-distance", 0, "U",
    "world distance over which the transfer function's opacity applies (default: 1 for CT in Hounsfield "
    "units with voxels of 0.1-10 mm; else the data's mean sample spacing, so any unit renders alike)");
  o.Add("iso", 0, "V[,V..]", "iso-surfaces at these scalar values (shaded, combined with the volume)");
  o.Add("iso-opacity", 0, "A", "opacity of every iso-surface", "1");
  o.Add("clip", 0, "X,Y,Z,NX,NY,NZ[;..]",
    "cut the volume by planes, each through a point with a normal, keeping the side the normal points "
    "to (';' between planes; the error figures clip the reference alike)");
  o.Add("ert", 0, "A", "early ray termination at this opacity (1 = off)", "0.99");
  o.Add("integrator", 0, "RULE", "segment rule: exact or trapezoid (the paper's)", "exact");
  o.Add("mip", 0, "", "maximum-intensity projection instead of emission-absorption");
  o.Add("shade", 0, "", "light the volume by its gradient, as vtkVolumeProperty::ShadeOn does (a headlight; "
    "ambient 0.1, diffuse 0.7, specular 0.2, power 10); the voxel reference does not shade, so its error "
    "figures are left out (--error exact compares with the mesh's own exact render)");
  o.Add("tets", 0, "N", "reduce a volume to about N adaptive tets first (or N% of the voxel count); without "
    "--tets or --max-error a volume is cast through its full-resolution tets (5 per voxel cell)");
  o.Add("max-error", 0, "E",
    "reduce a volume until the RMS error (opacity-weighted unless --plain-reduction) is at most E data units "
    "(E% of the scalar range)");
  o.Add("refinement", 0, "bisection|edge|anisotropic",
    "how a volume is reduced: bisection (newest-vertex, near-regular tets), edge (split the edges that remove the "
    "most error: thin tets along sharp surfaces, sharper images per tet, slower) or anisotropic (MMG3D remeshes to "
    "the voxels' Hessian metric: tets long along surfaces and thin across them; 0.4-7 dB sharper images than "
    "relocated bisection at the same tets on the CTs and the MNI brain measured, 1-3x its reduction time). Without "
    "MMG the default falls back to bisection, with a note",
    "anisotropic");
  o.Add("relocate", 0, "",
    "after reducing, move the vertices toward the surfaces they fit (the default without --iso; bisection: 2-6 dB "
    "sharper images of the CT at the same tets, 4-5x the reduction's time; anisotropic: by default when the tets "
    "hold 20 voxels or more each, 7-9 dB sharper on the MNI brain; given, on every mesh)");
  o.Add("no-relocate", 0, "", "keep the reduction's vertices where the refinement put them (faster to reduce)");
  o.Add("plain-reduction", 0, "",
    "reduce in plain L2, not weighted by the transfer function's opacity (a few times faster on large volumes)");
  o.Add("save-mesh", 0, "OUT.vtu",
    "also write the reduced mesh that is rendered, as `adaptivert reduce` writes it (with --tets or --max-error)");
  o.Add("mesh-cache", 0, "DIR",
    "keep each reduced mesh in DIR and reuse it when the same voxels are reduced with the same settings "
    "(batch does this for its frames)");
  o.Add("reference", 0, "", "render the full-resolution voxel reference instead");
  o.Add("no-error", 0, "", "skip the reference render and the error figures");
  o.Add("error", 0, "REF",
    "the error figures against REF: an image file, a volume (its voxel reference, same view and transfer "
    "function), or 'exact' (this mesh with the exact rule and no early termination); a volume's default is "
    "its own voxel reference, a mesh has none");
  cli::AddLoadOptions(o);
}

// Options that contradict each other were taken without a word (--relocate --no-relocate
// relocated; --reference --tets 500 rendered the reference and reduced nothing).
void RefuseContradictions(const cli::Options& o)
{
  cli::LabelColouring mode = cli::LabelColouring::Values;
  if (!cli::ParseLabelColouring(o.Get("label-colours"), mode))
  {
    throw cli::UsageError("--label-colours expects values, flat or off, got '" + o.Get("label-colours") + "'");
  }
  if (o.Flag("relocate") && o.Flag("no-relocate"))
  {
    throw cli::UsageError("--relocate and --no-relocate contradict each other: give one");
  }
  if (o.Flag("reference"))
  {
    for (const char* reducing :
      { "tets", "max-error", "refinement", "relocate", "no-relocate", "plain-reduction", "mesh-cache", "save-mesh" })
    {
      if (o.Has(reducing))
      {
        throw cli::UsageError(std::string("--reference renders the full-resolution voxels; --") + reducing +
          " (which reduces them first) does not apply to it");
      }
    }
    if (o.Flag("shade"))
    {
      throw cli::UsageError("--shade: the voxel reference does not shade; render the volume's tets instead");
    }
  }
}

// --unit-distance, when given, restates f's opacities per that distance.
art::TransferFunction WithUnitDistance(const cli::Options& o, const art::TransferFunction& f)
{
  if (!o.Has("unit-distance"))
  {
    return f;
  }
  const double u = o.GetDouble("unit-distance");
  if (!(u > 0) || !std::isfinite(u))
  {
    throw cli::UsageError("--unit-distance expects a positive length, got '" + o.Get("unit-distance") + "'");
  }
  return art::TransferFunction(f.Nodes(), u);
}

// A preset's opacities are per unit distance: 1 mm on CT in HU of mm voxels, else the data's sample spacing;
// --unit-distance overrides that and a file's own unit-distance line.
// `mesh`: the tet mesh built from `data` (its used, merged points), for a preset's unit distance.
art::TransferFunction MakeTF(const cli::Options& o, vtkDataSet* data, double lo, double hi, const art::TetMesh* mesh = nullptr,
  bool labels = false)
{
  const std::string tf = labels && o.Get("tf") == "auto" ? "labels" : o.Get("tf");
  art::TransferFunction f;
  if (art::TransferFunction::NamesFile(tf))
  {
    f = art::TransferFunction::FromFile(tf);
  }
  else if (tf == "auto" && o.Flag("mip"))
  {
    f = art::TransferFunction::MaximumIntensityFor(data, lo, hi, mesh);
  }
  else
  {
    f = art::TransferFunction::PresetFor(tf, data, lo, hi, mesh);
  }
  return WithUnitDistance(o, f);
}

// --clip's planes "x,y,z,nx,ny,nz;..." as (a, b, c, d) = (n, -n.p): a x + b y + c z + d >= 0 kept.
std::vector<std::array<double, 4>> ParsePlanes(const std::string& text)
{
  std::vector<std::array<double, 4>> planes;
  std::stringstream all(text);
  std::string one;
  while (std::getline(all, one, ';'))
  {
    std::stringstream ss(one);
    std::string item;
    std::vector<double> v;
    while (std::getline(ss, item, ','))
    {
      char* end = nullptr;
      const double x = std::strtod(item.c_str(), &end);
      v.push_back(!item.empty() && *end == '\0' && std::isfinite(x) ? x : std::nan(""));
    }
    if (v.size() != 6 || std::any_of(v.begin(), v.end(), [](double x) { return std::isnan(x); }) ||
      !(v[3] * v[3] + v[4] * v[4] + v[5] * v[5] > 0))
    {
      throw cli::UsageError("--clip expects X,Y,Z,NX,NY,NZ (a point and a non-zero normal) per plane, "
                            "planes separated by ';', got '" + text + "'");
    }
    planes.push_back({ v[3], v[4], v[5], -(v[0] * v[3] + v[1] * v[4] + v[2] * v[5]) });
  }
  if (planes.empty())
  {
    throw cli::UsageError("--clip expects X,Y,Z,NX,NY,NZ per plane, got '" + text + "'");
  }
  return planes;
}

art::RenderSettings MakeSettings(const cli::Options& o, art::TransferFunction tf)
{
  art::RenderSettings s;
  s.tf = std::move(tf);
  s.earlyTermination = o.GetDouble("ert");
  if (!(s.earlyTermination > 0 && s.earlyTermination <= 1))
  {
    throw cli::UsageError("--ert expects an opacity in (0, 1], got '" + o.Get("ert") + "'");
  }
  const std::string rule = o.Get("integrator");
  if (rule == "trapezoid")
  {
    s.rule = art::RenderSettings::Rule::Trapezoid;
  }
  else if (rule != "exact")
  {
    throw cli::UsageError("--integrator expects exact or trapezoid, got '" + rule + "'");
  }
  if (o.Flag("mip"))
  {
    s.mode = art::RenderSettings::Mode::MaxIntensity;
  }
  s.shading.on = o.Flag("shade");
  if (o.Has("iso"))
  {
    std::stringstream ss(o.Get("iso"));
    std::string item;
    const double a = o.GetDouble("iso-opacity");
    static const double colours[4][3] = { { 1, 0.85, 0.7 }, { 0.6, 0.8, 1 }, { 1, 0.5, 0.4 }, { 0.6, 1, 0.6 } };
    while (std::getline(ss, item, ','))
    {
      char* end = nullptr;
      const double v = std::strtod(item.c_str(), &end);
      if (item.empty() || *end != '\0' || !std::isfinite(v))
      {
        throw cli::UsageError("--iso expects numbers separated by commas, got '" + o.Get("iso") + "'");
      }
      const auto& c = colours[s.isos.size() % 4];
      s.isos.push_back({ v, { { c[0], c[1], c[2] } }, a });
    }
  }
  if (o.Has("clip"))
  {
    s.clipPlanes = ParsePlanes(o.Get("clip"));
  }
  return s;
}

// What `render` casts: a volume's tets (full resolution or reduced) or a mesh's, its transfer
// function and the notes gathered on the way.
struct Scene
{
  vtkSmartPointer<vtkImageData> volume; ///< null for a mesh input
  vtkSmartPointer<vtkUnstructuredGrid> grid; ///< a mesh input as read (its field data)
  art::TetMesh mesh;
  std::string meshLabel, note;
  double range[2] = { 0, 1 };
  art::RenderSettings settings;
  double buildSeconds = 0;
};

void AddNote(std::string& note, const std::string& text)
{
  note += (note.empty() ? "" : "; ") + text;
}

#ifdef ART_HAVE_Reduction
// The reduction `render` makes of a volume for its settings: weighted by what the transfer
// function shows, vertices relocated unless there are iso-surfaces, clamped under MIP.
art::ReducerOptions ReductionFor(const cli::Options& o, const art::RenderSettings& settings, const int dims[3])
{
  const long long voxels = static_cast<long long>(dims[0]) * dims[1] * dims[2];
  art::ReducerOptions ro;
  ro.Refine = cli::ParseRefinement(o.Get("refinement"), "--refinement");
  if (!o.Has("refinement") && ro.Refine == art::ReducerOptions::Refinement::Anisotropic &&
    (o.Has("tets") || o.Has("max-error")))
  {
    // The default falls back to bisection where MMG cannot run, and on slabs a few voxels
    // thin, where MMG took 30-60 s for what bisection makes in 0.1 s.
    std::string why;
    const int thinnest = std::min({ dims[0], dims[1], dims[2] });
    if (!art::MmgRemesher::Available(&why))
    {
      why = "anisotropic refinement needs MMG (" + why + ")";
    }
    else if (thinnest < 8)
    {
      why = "the volume is " + std::to_string(thinnest) + " voxels thin; --refinement anisotropic remeshes it anyway, slowly";
    }
    if (!why.empty())
    {
      std::fprintf(stderr, "adaptivert: note: reducing with bisection: %s\n", why.c_str());
      ro.Refine = art::ReducerOptions::Refinement::Bisection;
    }
  }
  if (o.Has("tets"))
  {
    ro.TargetTets = cli::ParseBudget(o.Get("tets"), voxels, "--tets");
    if (ro.TargetTets < 6)
    {
      throw cli::UsageError("--tets expects a count of at least 6");
    }
  }
  if (o.Has("max-error"))
  {
    ro.TargetError = cli::ParseMaxError(o.Get("max-error"), ro.ErrorRelative);
  }
  if (!o.Flag("plain-reduction") && settings.mode == art::RenderSettings::Mode::Composite)
  {
    ro.ScalarOpacity = settings.tf.OpacityPoints(); // model what this transfer function shows
    for (const auto& iso : settings.isos) // and where its iso-surfaces lie
    {
      ro.IsoValues.push_back(iso.value);
    }
  }
  // Not by default under iso-surfaces: on the CT's head rest (thin struts) the relocated fit
  // crosses an iso-value in blobs where the voxels have thin lines (a worse picture than the
  // lattice's).
  ro.RelocateVertices = o.Flag("relocate") || (!o.Flag("no-relocate") && settings.isos.empty());
  if (o.Flag("relocate"))
  {
    ro.RelocateVoxelsPerTet = 0; // asked for: every mesh, however fine
  }
  // Maximum intensity shows the fit's overshoot at sharp edges as bright facets.
  ro.ClampToVoxels = settings.mode == art::RenderSettings::Mode::MaxIntensity;
  return ro;
}

// Reduces the scene's volume (or takes the mesh from --mesh-cache) and labels it.
void ReduceVolume(const cli::Options& o, const std::string& input, Scene& sc, art::Progress& progress, cli::Json& j)
{
  art::ReducerOptions ro = ReductionFor(o, sc.settings, sc.volume->GetDimensions());
  const art::VoxelVolume vv = art::VolumeFromImage(sc.volume, input);
  if (ro.TargetTets > 0)
  {
    const std::string capped = cli::CapToFullResolution(ro.TargetTets, vv, "--tets");
    if (!capped.empty()) // the budget asks for the voxels themselves
    {
      AddNote(sc.note, capped);
      sc.mesh = art::TetMesh::FromImage(sc.volume, input);
      sc.meshLabel = "full-resolution tets (5 per voxel cell)";
      return;
    }
  }
  art::ReducedMesh r;
  std::optional<cli::MeshCache> cache;
  bool cached = false;
  if (o.Has("mesh-cache"))
  {
    cache.emplace(o.Get("mesh-cache"), vv, ro);
    cached = cache->Load(r);
    j.Set("mesh_cache", cache->File()).Set("mesh_cache_hit", cached);
  }
  if (!cached)
  {
    auto levels = art::TetReducer(ro).Run(vv, &progress);
    if (levels.empty())
    {
      throw art::Error("the reducer produced no mesh", input);
    }
    r = std::move(levels.back());
    try
    {
      if (cache)
      {
        cache->Store(r);
      }
    }
    catch (const art::Error& e) // the image is still worth making
    {
      AddNote(sc.note, std::string("the mesh cache was not written: ") + e.what());
    }
  }
  sc.mesh = cli::ToTetMesh(r);
  if (o.Has("save-mesh"))
  {
    auto grid = art::ToUnstructuredGrid(r, vv.DoubleValues);
    if (auto frame = cli::SourceVisibleBounds(sc.volume))
    {
      grid->GetFieldData()->AddArray(frame);
    }
    art::SaveMesh(grid, o.Get("save-mesh"));
    j.Set("saved_mesh", o.Get("save-mesh"));
  }
  std::ostringstream ss;
  ss << std::setprecision(4) // errors to four digits (87.34 HU); counts are integers
     << "adaptive tets (" << (r.Weighted ? "opacity-weighted " : "") << "least-squares reduction"
     << (ro.Refine == art::ReducerOptions::Refinement::Anisotropic ? ", anisotropic (MMG3D)" : "")
     << (r.Relocated ? ", vertices relocated" : "")
     << (ro.ClampToVoxels ? ", clamped to the voxel range" : "") << ", RMS error " << r.Rms << ", max " << r.Max;
  if (r.Weighted)
  {
    ss << "; weighted RMS " << r.WeightedRms << ", max " << r.WeightedMax;
  }
  ss << (r.TargetReached ? ")" : "; " + cli::UnreachedReason(r, vv, ro.TargetTets == 0) + ")")
     << (cached ? ", from the mesh cache" : "");
  sc.meshLabel = ss.str();
  j.Set("reduced_rms", r.Rms).Set("reduced_max", r.Max).Set("reduced_weighted", r.Weighted);
  if (r.Weighted)
  {
    j.Set("reduced_weighted_rms", r.WeightedRms).Set("reduced_weighted_max", r.WeightedMax);
  }
}
#endif

// --save-mesh names a .vtu that can be written, and a reduction to write: said before loading.
void CheckSaveMesh(const cli::Options& o)
{
  const std::string path = o.Get("save-mesh");
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (ext != ".vtu")
  {
    throw cli::UsageError("--save-mesh writes a .vtu, got '" + path + "'");
  }
  if (!o.Has("tets") && !o.Has("max-error"))
  {
    throw cli::UsageError("--save-mesh writes the reduced mesh: give --tets N or --max-error E");
  }
  if (o.Has("output") && std::filesystem::weakly_canonical(path) == std::filesystem::weakly_canonical(o.Get("output")))
  {
    throw cli::UsageError("--save-mesh and -o name the same file");
  }
  art::AtomicFile trial(path); // its folder exists and is writable
}

// A volume input: its scalars and transfer function; its tets come after the camera is set up
// (MakeVolumeTets), so a view that cannot be set up is said before a long reduction.
void LoadVolumeScene(const cli::Options& o, const std::string& input, Scene& sc)
{
  sc.volume = art::LoadVolume(input, cli::LoadOptionsFrom(o)); // it has scalars
  art::RequireOneComponent(sc.volume, input);
  sc.volume->GetPointData()->GetScalars()->GetRange(sc.range);
  if (!std::isfinite(sc.range[0]) || !std::isfinite(sc.range[1]))
  {
    throw art::Error("the scalars hold infinite values (range " + std::to_string(sc.range[0]) + " .. " +
        std::to_string(sc.range[1]) + ")",
      input);
  }
  sc.settings = MakeSettings(o, MakeTF(o, sc.volume, sc.range[0], sc.range[1]));
}

// The volume's tets (unless --reference): reduced with --tets / --max-error, else full resolution.
void MakeVolumeTets(const cli::Options& o, const std::string& input, Scene& sc, art::Progress& progress, cli::Json& j)
{
  if (o.Flag("reference"))
  {
    return;
  }
  if (o.Has("tets") || o.Has("max-error"))
  {
#ifdef ART_HAVE_Reduction
    ReduceVolume(o, input, sc, progress, j);
#else
    (void)progress;
    (void)j;
    throw art::Error("--tets and --max-error need the Reduction module, which is not in this build", input);
#endif
  }
  else
  {
    sc.mesh = art::TetMesh::FromImage(sc.volume, input);
    sc.meshLabel = "full-resolution tets (5 per voxel cell)";
  }
}

// A tet mesh input (other cells tetrahedralised, with a note).
void LoadMeshScene(const cli::Options& o, const std::string& input, Scene& sc)
{
  auto grid = art::LoadMesh(input);
  std::string array = art::AddComponentArray(grid, o.Get("array"), input); // NAME:magnitude, NAME:N
  // A label mesh: each tet in its label's colour (a categorical table unless --tf says otherwise),
  // and the values inside each label when it has them (--label-colours).
  cli::LabelColouring mode = cli::LabelColouring::Values;
  cli::ParseLabelColouring(o.Get("label-colours"), mode); // RefuseContradictions checked the word
  const auto labels = cli::LabelMeshFor(grid, array, mode, !o.Flag("mip") && !o.Has("iso"));
  const bool values = labels && labels->HasValues();
  if (labels)
  {
    sc.grid = labels->Grid();
    array = values ? "label_values" : "label";
  }
  else
  {
    sc.grid = grid;
  }
  sc.mesh = art::TetMesh::FromVTK(sc.grid, array, &sc.note, input);
  sc.meshLabel = values ? "label mesh with values" : labels ? "label mesh" : "tet mesh";
  sc.range[0] = sc.mesh.ScalarRange(0), sc.range[1] = sc.mesh.ScalarRange(1);
  sc.settings = MakeSettings(o, values ? WithUnitDistance(o, cli::LabelValuesFunction(*labels, grid, o.Get("tf")))
                                       : MakeTF(o, sc.grid, sc.range[0], sc.range[1], &sc.mesh, labels.has_value()));
}

// A transfer function made for other data (another modality or units) draws nothing: say so
// rather than write a blank image without a word.
void NoteTransparentTF(Scene& sc)
{
  if (!sc.settings.isos.empty() || !sc.settings.tf.Transparent(sc.range[0], sc.range[1]))
  {
    return;
  }
  const auto& n = sc.settings.tf.Nodes();
  std::ostringstream ss;
  ss << "the transfer function is transparent over the data's range " << sc.range[0] << " .. " << sc.range[1]
     << " (its control points span " << n.front().s << " .. " << n.back().s << "): the image shows nothing";
  AddNote(sc.note, ss.str());
}

struct Frame
{
  art::Image img, ref;
  art::RenderStats st, rst;
  bool haveRef = false;
  std::string refLabel;
  art::ImageMetricsResult m;
};

// Casts the scene and, unless --no-error, its reference: --error's (an image, a volume's voxels,
// or the exact rule on the mesh), else a volume's own voxels. A mesh has no reference unless
// asked for one: its own exact render would score how it is drawn, not what it models.
Frame CastWithReference(const cli::Options& o, const std::string& input, Scene& sc, const art::Camera& cam,
  const std::array<float, 3>& background, art::Progress& progress)
{
  Frame f;
  if (o.Flag("reference"))
  {
    if (!sc.volume)
    {
      throw art::Error("--reference needs a voxel volume", input);
    }
    f.st = art::VoxelReferenceCaster::FromVTK(sc.volume, sc.settings, input).Render(cam, f.img, &progress);
    return f;
  }
  f.st = art::TetRayCaster(sc.mesh, sc.settings).Render(cam, f.img, &progress);
  if (o.Flag("no-error"))
  {
    return f;
  }
  std::string ref = o.Has("error") ? o.Get("error") : sc.volume ? std::string() : std::string("none");
  if (sc.settings.shading.on && ref != "exact" && !art::IsImageExtension(ref) && ref != "none")
  {
    // Against unlit voxels every lit pixel would count as error.
    AddNote(sc.note, "no error figures: the voxel reference does not shade (--error exact compares with the "
                     "mesh's own exact render)");
    ref = "none";
  }
  if (ref.empty() && sc.volume)
  {
    f.rst = art::VoxelReferenceCaster::FromVTK(sc.volume, sc.settings, input).Render(cam, f.ref, &progress);
    f.refLabel = "voxel ray caster";
  }
  else if (ref == "exact")
  {
    art::RenderSettings exact = sc.settings; // the mesh's own reference: exact rule, no ERT
    exact.rule = art::RenderSettings::Rule::Exact;
    exact.earlyTermination = 2.0;
    f.rst = art::TetRayCaster(sc.mesh, exact).Render(cam, f.ref, &progress);
    f.refLabel = "exact rule on the mesh";
  }
  else if (ref != "none" && art::IsImageExtension(ref))
  {
    f.ref = art::ReadImage(ref);
    art::RequireFinite(f.ref, ref);
    if (f.ref.Width() != f.img.Width() || f.ref.Height() != f.img.Height())
    {
      throw art::Error("is " + std::to_string(f.ref.Width()) + "x" + std::to_string(f.ref.Height()) +
          ", the render " + std::to_string(f.img.Width()) + "x" + std::to_string(f.img.Height()) +
          ": give --size to match the reference image",
        ref);
    }
    f.refLabel = "image " + ref;
  }
  else if (ref != "none")
  {
    art::LoadOptions placed; // the reference volume in the frame the mesh was reduced in
    placed.Array = o.Get("array");
    placed.Placement = cli::LoadOptionsFrom(o).Placement;
    auto volume = art::LoadVolume(ref, placed);
    art::RequireOneComponent(volume, ref);
    f.rst = art::VoxelReferenceCaster::FromVTK(volume, sc.settings, ref).Render(cam, f.ref, &progress);
    f.refLabel = "voxel ray caster on " + ref;
  }
  f.haveRef = ref != "none";
  if (f.haveRef)
  {
    f.m = art::CompareOnBackground(f.img, f.ref, background); // as the images are written
  }
  return f;
}

// Images whose error figures would look perfect for the wrong reason: nothing hit, or opacity
// built up over too long a unit distance (data in other units than the transfer function's).
void NoteEmptyImage(const cli::Options& o, Scene& sc, const Frame& f)
{
  if (!o.Flag("reference") && f.st.counters.hits == 0)
  {
    AddNote(sc.note, "no ray meets the data (the camera sees none of it, or the clipping planes cut it all): the "
                     "image is background only");
  }
  if (sc.settings.mode != art::RenderSettings::Mode::Composite || !sc.settings.isos.empty() ||
    f.st.counters.hits == 0 || sc.settings.tf.Transparent(sc.range[0], sc.range[1]))
  {
    return;
  }
  float top = 0.f;
  for (int y = 0; y < f.img.Height(); ++y)
  {
    for (int x = 0; x < f.img.Width(); ++x)
    {
      top = std::max(top, f.img.Pixel(x, y)[3]);
    }
  }
  if (top < 0.02f)
  {
    std::ostringstream ss;
    ss << "the image is all but clear (opacity at most " << top << "): the transfer function's opacity applies per "
       << sc.settings.tf.UnitDistance() << " world units; a smaller --unit-distance shows more";
    AddNote(sc.note, ss.str());
  }
}

void PrintJson(const cli::Options& o, const cli::View& view, const Scene& sc, const Frame& f, cli::Json& j)
{
  const auto& c = f.st.counters;
  const double mrays = c.rays / std::max(f.st.seconds, 1e-9) / 1e6;
  const double nsPerTet = c.tetsCrossed ? f.st.seconds * 1e9 / double(c.tetsCrossed) * art::GetThreadCount() : 0;
  j.Set("output", view.output).Set("width", view.width).Set("height", view.height);
  if (!sc.note.empty())
  {
    j.Set("note", sc.note);
  }
  j.Set("mesh", o.Flag("reference") ? std::string("voxel reference") : sc.meshLabel);
  j.Set("tets", static_cast<long long>(sc.mesh.NumberOfTets()))
    .Set("vertices", static_cast<long long>(sc.mesh.NumberOfPoints()));
  j.Set("build_seconds", sc.buildSeconds).Set("render_seconds", f.st.seconds).Set("mrays_per_second", mrays);
  j.Set("tets_crossed", static_cast<long long>(c.tetsCrossed)).Set("tets_per_ray", c.PerRay(c.tetsCrossed));
  j.Set("ns_per_tet_crossed_per_thread", nsPerTet).Set("entry_searches", static_cast<long long>(c.entrySearches))
    .Set("fallback_exits", static_cast<long long>(f.st.nudges));
  if (f.haveRef)
  {
    j.Set("reference_seconds", f.rst.seconds).Set("psnr_db", f.m.psnr).Set("ssim", f.m.ssim).Set("rmse", f.m.rmse);
    j.Set("object_psnr_db", f.m.objectPsnr).Set("object_ssim", f.m.objectSsim).Set("object_rmse", f.m.objectRmse)
      .Set("object_pixels", f.m.objectPixels);
  }
  std::printf("%s\n", j.Str().c_str());
}

void PrintText(const cli::Options& o, const std::string& input, const cli::View& view, const Scene& sc, const Frame& f)
{
  const auto& c = f.st.counters;
  const double mrays = c.rays / std::max(f.st.seconds, 1e-9) / 1e6;
  const double nsPerTet = c.tetsCrossed ? f.st.seconds * 1e9 / double(c.tetsCrossed) * art::GetThreadCount() : 0;
  std::printf("input        %s\n", input.c_str());
  if (!sc.note.empty())
  {
    std::printf("note         %s\n", sc.note.c_str());
  }
  if (o.Flag("reference"))
  {
    std::printf("render       voxel reference (trilinear, 2 samples/voxel, exact steps, no ERT), %d x %d: %.3f s\n",
      view.width, view.height, f.st.seconds);
  }
  else
  {
    const std::size_t tets = sc.mesh.NumberOfTets(), verts = sc.mesh.NumberOfPoints();
    std::printf("mesh         %s: %zu tet%s, %zu vert%s (%.2f s)\n", sc.meshLabel.c_str(), tets, tets == 1 ? "" : "s",
      verts, verts == 1 ? "ex" : "ices", sc.buildSeconds);
    std::printf("render       %d x %d, %s rule, ERT %g: %.3f s (%.2f Mrays/s), %.1f tets/ray, %.0f ns/tet "
                "crossed per thread\n",
      view.width, view.height, sc.settings.rule == art::RenderSettings::Rule::Exact ? "exact" : "trapezoid",
      sc.settings.earlyTermination, f.st.seconds, mrays, c.PerRay(c.tetsCrossed), nsPerTet);
  }
  if (f.haveRef)
  {
    std::printf("reference    %s: %.3f s\n", f.refLabel.c_str(), f.rst.seconds);
    std::printf("error        PSNR %.2f dB, SSIM %.4f, RMSE %.5f (RGB over the background, against the reference)\n",
      f.m.psnr, f.m.ssim, f.m.rmse);
    std::printf("             object: PSNR %.2f dB, SSIM %.4f, RMSE %.5f (the %lld pixels either image covers)\n",
      f.m.objectPsnr, f.m.objectSsim, f.m.objectRmse, f.m.objectPixels);
  }
  std::printf("output       %s\n", view.output.c_str());
}

int Run(const cli::Options& o, const std::string& input)
{
  const cli::View view = cli::ViewFromOptions(o);
  RefuseContradictions(o);
  cli::ProgressBar bar(o.Flag("quiet"));
  art::Progress progress(bar.Callback());
  cli::Json j;
  j.Set("input", input);

  cli::CheckTransferFunctionName(o.Get("tf"));
  if (o.Has("save-mesh"))
  {
    CheckSaveMesh(o);
  }
  if (o.Has("error") && (o.Flag("no-error") || o.Flag("reference")))
  {
    throw cli::UsageError(std::string("--error and ") + (o.Flag("no-error") ? "--no-error" : "--reference") +
      " exclude each other");
  }
  Scene sc;
  const auto t0 = std::chrono::steady_clock::now();
  art::Box3 bounds;
  if (art::KindOf(input, cli::LoadOptionsFrom(o)) == art::DataKind::Volume)
  {
    LoadVolumeScene(o, input, sc);
    double b[6];
    sc.volume->GetBounds(b);
    bounds = art::Box3::FromBounds(b);
  }
  else
  {
    LoadMeshScene(o, input, sc);
    bounds = sc.mesh.Bounds();
  }
  const art::Box3 object = cli::ObjectBounds(sc.volume, sc.grid, &sc.mesh, sc.settings, o.Get("tf"));
  vtkNew<vtkCamera> vcam;
  cli::SetupCamera(o, object, bounds, vcam);
  j.Set("camera", cli::CameraJson(vcam));
  const art::Camera cam = art::Camera::FromVTK(vcam, view.width, view.height);
  if (sc.volume)
  {
    MakeVolumeTets(o, input, sc, progress, j);
  }
  sc.buildSeconds = Seconds(t0);
  NoteTransparentTF(sc);

  const std::array<float, 3> background = { view.background[0], view.background[1], view.background[2] };
  Frame f = CastWithReference(o, input, sc, cam, background, progress);
  bar.Finish();
  NoteEmptyImage(o, sc, f);
  f.img.CompositeOver(background);
  art::WriteImage(f.img, view.output);

  if (o.Flag("json"))
  {
    PrintJson(o, view, sc, f, j);
  }
  else
  {
    PrintText(o, input, view, sc, f);
  }
  return cli::ExitOk;
}

cli::RendererRegistrar reg({ "tets", { art::DataKind::Volume, art::DataKind::Mesh }, Declare, Run });
} // namespace
