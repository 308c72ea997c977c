#include "commands/RegionReduction.h"

#ifdef ART_HAVE_Reduction

#include "cli/NumberFormat.h"
#include "cli/Command.h"
#include "cli/Json.h"
#include "cli/LoadOptions.h"
#include "cli/ProgressBar.h"
#include "DataLoader.h"
#include "Error.h"
#include "FullResolutionMesh.h"
#include "MeshQuality.h"
#include "ReducerVTK.h"
#include "RegionReducer.h"
#include "RegionVTK.h"
#include "rendering/ReductionTargets.h"
#include "WholeBoxComparison.h"
#include "vtkImageDomainMesher.h"

#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace cli
{
namespace
{
using cli::Grouped;

// "LO:HI", either end may be left out (300: is 300 and above).
void ParseRegion(const std::string& s, double& lo, double& hi)
{
  const size_t c = s.find(':', s.empty() ? 0 : 1); // past a leading sign
  auto number = [&](const std::string& t, double open) {
    if (t.empty())
    {
      return open;
    }
    if (!IsDecimalNumber(t))
    {
      throw UsageError("--region expects LO:HI (numbers, e.g. 300:3000 or -500:), got '" + s + "'");
    }
    return std::strtod(t.c_str(), nullptr);
  };
  if (c == std::string::npos || (c == 0 && s.size() == 1))
  {
    throw UsageError("--region expects LO:HI (numbers, e.g. 300:3000 or -500:), got '" + s + "'");
  }
  lo = number(s.substr(0, c), -std::numeric_limits<double>::infinity());
  hi = number(s.substr(c + 1), std::numeric_limits<double>::infinity());
  if (!(lo <= hi))
  {
    throw UsageError("--region " + s + " is empty: its low end is above its high end");
  }
}

// A region mesh is conforming when no face has more than two tets and no tet is inverted; its
// boundary is the region's surface, not a convex hull.
void CheckConforming(const art::ReducedMesh& m, const std::string& out)
{
  const auto q = art::MeasureQuality(m.Points.data(), m.NumberOfVertices(), m.Tets.data(), m.NumberOfTets());
  if (q.Inverted > 0 || q.OverSharedFaces > 0 || q.Tets == 0)
  {
    throw art::Error("internal: the region's mesh failed its conformity check: " + q.Summary(), out);
  }
}

void PrintText(const Options& o, const std::string& in, const std::string& out, const art::VoxelVolume& v,
  const art::RegionOptions& ro, const art::RegionResult& r, const art::WholeBoxFigures* box)
{
  const auto& m = r.Mesh;
  const auto& k = r.Mask;
  std::printf("input        %s (%d x %d x %d = %s voxels, range %g .. %g)\n", in.c_str(), v.Dims[0], v.Dims[1],
    v.Dims[2], Grouped(v.NumberOfVoxels()).c_str(), v.Range[0], v.Range[1]);
  const char* absorbed = ro.Labels ? " taken into the label around them" : " dropped";
  if (ro.Labels)
  {
    std::string list;
    for (size_t i = 0; i < k.Labels.size() && i < 12; ++i)
    {
      list += (i ? ", " : "") + std::to_string(k.Labels[i]);
    }
    list += k.Labels.size() > 12 ? ", ..." : "";
    std::printf("labels       %zu (%s), background %lld: %s voxels in %s pieces\n", k.Labels.size(), list.c_str(),
      ro.Background, Grouped(k.Voxels).c_str(), Grouped(k.Pieces).c_str());
  }
  else
  {
    std::printf("region       %s: %s voxels (%.3g%% of the volume) in %s piece%s\n", o.Get("region").c_str(),
      Grouped(k.Voxels).c_str(), 100.0 * k.Voxels / v.NumberOfVoxels(), Grouped(k.Pieces).c_str(),
      k.Pieces == 1 ? "" : "s");
  }
  std::printf("islands      %s piece%s below %s voxels%s (%s voxels)\n", Grouped(k.IslandsDropped).c_str(),
    k.IslandsDropped == 1 ? "" : "s", Grouped(k.MinIslandVoxels).c_str(), absorbed, Grouped(k.IslandVoxels).c_str());
  std::printf("tets         %s, %s vertices, boundary on the %s (CGAL Mesh_3, %zu meshing%s)\n",
    Grouped(m.NumberOfTets()).c_str(), Grouped(m.NumberOfVertices()).c_str(),
    ro.Labels ? "labels' surfaces, interfaces shared" : "region's surface", r.Rounds.size(),
    r.Rounds.size() == 1 ? "" : "s");
  if (!m.Values.empty())
  {
    std::printf("error        RMS %.4g, max %.4g inside the region (%.2f%% of its voxels lie inside the mesh)\n", m.Rms,
      m.Max, 100.0 * r.CoveredVoxels / std::max<long long>(k.Voxels, 1));
  }
  if (box)
  {
    std::printf("whole box    %s tets for RMS %.4g inside the region%s: %.2f x this mesh (%.1f s)\n",
      Grouped(box->Tets).c_str(), m.Rms, box->Reached ? "" : " (not reached: more than that)",
      static_cast<double>(box->Tets) / std::max<long long>(m.NumberOfTets(), 1), box->Seconds);
  }
  const auto q = art::MeasureQuality(m.Points.data(), m.NumberOfVertices(), m.Tets.data(), m.NumberOfTets());
  std::printf("quality      min dihedral %.1f deg, radius ratio min %.3f mean %.3f, 0 inverted, conforming\n",
    q.MinDihedralDegrees, q.MinRadiusRatio, q.MeanRadiusRatio);
  std::printf("output       %s%s\n", out.c_str(), m.TargetReached ? "" : " (target not reached: the region's full resolution)");
  std::printf("time         %.2f s\n", m.BuildSeconds);
}

void PrintJson(const std::string& in, const std::string& out, const art::VoxelVolume& v, const art::RegionOptions& ro,
  const art::RegionResult& r, const art::WholeBoxFigures* box)
{
  const auto& m = r.Mesh;
  Json j;
  j.Set("input", in).Set("output", out).Set("voxels", v.NumberOfVoxels()).Set("tets", m.NumberOfTets())
    .Set("vertices", m.NumberOfVertices()).Set("region_voxels", r.Mask.Voxels).Set("covered_voxels", r.CoveredVoxels)
    .Set("region_pieces", r.Mask.Pieces).Set("islands_dropped", r.Mask.IslandsDropped)
    .Set("island_voxels", r.Mask.IslandVoxels).Set("min_island_voxels", r.Mask.MinIslandVoxels)
    .Set("meshings", static_cast<long long>(r.Rounds.size())).Set("build_seconds", m.BuildSeconds)
    .Set("target_reached", m.TargetReached);
  if (ro.Labels)
  {
    std::vector<double> labels(r.Mask.Labels.begin(), r.Mask.Labels.end());
    j.Set("labels", labels).Set("background", static_cast<long long>(ro.Background));
  }
  else
  {
    j.Set("region", std::vector<double>{ ro.Lo, ro.Hi });
  }
  if (!m.Values.empty())
  {
    j.Set("rms_error", m.Rms).Set("max_error", m.Max);
  }
  if (box)
  {
    j.Set("whole_box_tets", box->Tets).Set("whole_box_reached", box->Reached).Set("whole_box_seconds", box->Seconds);
  }
  std::vector<Json> rounds;
  for (const auto& rd : r.Rounds)
  {
    Json x;
    x.Set("tets", rd.Tets).Set("expected_tets", rd.ExpectedTets).Set("mesh_seconds", rd.MeshSeconds)
      .Set("fit_seconds", rd.FitSeconds);
    if (!m.Values.empty())
    {
      x.Set("rms_error", rd.Rms);
    }
    rounds.push_back(x);
  }
  j.Set("rounds", rounds);
  std::printf("%s\n", j.Str().c_str());
}
} // namespace

void DeclareRegionOptions(Options& o)
{
  o.Add("region", 0, "LO:HI",
    "mesh only the voxels whose value lies in [LO, HI] (e.g. 300:3000 for a CT's bone; 300: for 300 and above): the "
    "mesh's boundary follows the region's surface (CGAL Mesh_3)");
  o.Add("labels", 0, "", "the input is a label map: one conforming mesh of every label, cell array 'label', "
    "interfaces shared (CGAL Mesh_3; with --tets)");
  o.Add("background", 0, "N", "with --labels: the label left unmeshed", "0");
  o.Add("values", 0, "IMAGE",
    "with --labels: a volume of the same dimensions (an MRI beside its segmentation) whose values the label mesh "
    "carries, fitted in the least-squares sense inside the labels");
  o.Add("min-island", 0, "N",
    "with --region or --labels: connected pieces of fewer voxels are dropped (default: 27 or 0.01% of the region)");
  o.Add("no-whole-box", 0, "",
    "with --region: skip the whole-box reduction that says how many tets equal error inside the region needs");
}

bool WantsRegion(const Options& o)
{
  const bool region = o.Has("region"), labels = o.Flag("labels");
  if (!region && !labels)
  {
    for (const char* only : { "background", "min-island", "no-whole-box", "values" })
    {
      if (o.Has(only))
      {
        throw UsageError(std::string("--") + only + " goes with --region or --labels");
      }
    }
    return false;
  }
  if (region && labels)
  {
    throw UsageError("--region and --labels exclude each other: a label map is meshed by its labels");
  }
  if (labels && o.Has("max-error"))
  {
    throw UsageError("--labels meshes a label map to --tets N; --max-error bounds a fit it does not make");
  }
  if (region && o.Has("values"))
  {
    throw UsageError("--values goes with --labels (a region's values are the input's own)");
  }
  if (labels && o.Has("no-whole-box"))
  {
    throw UsageError("--no-whole-box goes with --region (a label map is not compared)");
  }
  for (const char* other : { "levels", "tf", "relocate", "clamp", "refine-fraction" })
  {
    if (o.Has(other))
    {
      throw UsageError(std::string("--") + other + " does not apply to --" + (labels ? "labels" : "region") +
        " (its meshes are made by CGAL, not refined from a box)");
    }
  }
  if (o.Has("refinement") && o.Get("refinement") != "bisection")
  {
    throw UsageError("--refinement does not apply to --" + std::string(labels ? "labels" : "region"));
  }
  if (o.Get("metric") != "rms")
  {
    throw UsageError("--max-error bounds the RMS inside a region (--metric rms)");
  }
  if (region)
  {
    double lo, hi;
    ParseRegion(o.Get("region"), lo, hi);
  }
  if (o.Has("min-island") && !(o.GetInt("min-island") >= 0))
  {
    throw UsageError("--min-island expects a count of voxels (0 or more)");
  }
  return true;
}

int RunRegionReduction(const Options& o, const std::string& in, const std::string& out, vtkImageData* image)
{
  vtkSmartPointer<vtkImageDomainMesher> mesher = vtkSmartPointer<vtkImageDomainMesher>::New();
  if (!mesher->IsAvailable())
  {
    throw art::Error(std::string("--") + (o.Has("region") ? "region" : "labels") +
        " needs CGAL's Mesh_3 (AdaptiveRT::Meshing), which is not in this build (ART_WITH_GPL_MESHING)",
      in);
  }
  const art::VoxelVolume volume = art::VolumeFromImage(image, in);
  art::RegionOptions ro;
  ro.Labels = o.Flag("labels");
  if (!ro.Labels)
  {
    ParseRegion(o.Get("region"), ro.Lo, ro.Hi);
    if (ro.Lo > volume.Range[1] || ro.Hi < volume.Range[0])
    {
      char span[96];
      std::snprintf(span, sizeof span, "%g .. %g", volume.Range[0], volume.Range[1]);
      throw art::Error("no voxel lies in the region " + o.Get("region") + " (the values span " + span + ")", in);
    }
    ro.Lo = std::max(ro.Lo, volume.Range[0] - 1.0);
    ro.Hi = std::min(ro.Hi, volume.Range[1] + 1.0);
  }
  art::VoxelVolume values;
  if (o.Has("values"))
  {
    const std::string file = o.Get("values");
    art::LoadOptions load = cli::LoadOptionsFrom(o);
    load.Array.clear(); // --array and the raw layout describe the label map, not the values
    load.Raw = {};
    auto vimg = art::LoadVolume(file, load);
    art::RequireOneComponent(vimg, file);
    values = art::VolumeFromImage(vimg, file);
    ro.Values = &values;
  }
  ro.Background = o.GetInt("background");
  ro.MinIslandVoxels = o.Has("min-island") ? o.GetInt("min-island") : -1;
  if (o.Has("tets"))
  {
    ro.TargetTets = ParseBudget(o.Get("tets"), volume.NumberOfVoxels(), "--tets");
    if (ro.TargetTets < 6)
    {
      throw UsageError("--tets must be at least 6");
    }
  }
  if (o.Has("max-error"))
  {
    bool relative = false;
    const double e = ParseMaxError(o.Get("max-error"), relative);
    ro.TargetError = relative ? e * (volume.Range[1] - volume.Range[0]) : e;
  }
  ro.SolverTolerance = o.GetDouble("tolerance");
  ProgressBar bar(o.Flag("quiet"));
  art::Progress progress(bar.Callback());
  const art::RegionResult r = art::ReduceRegion(
    volume, ro, [&mesher](const art::ImageDomainRequest& q) { return mesher->Mesh(q); }, &progress);
  CheckConforming(r.Mesh, out);
  art::WholeBoxFigures box;
  const bool compare = !ro.Labels && !o.Flag("no-whole-box");
  if (compare)
  {
    const long long cap = std::min<long long>(art::FullResolutionTetCount(volume), 64 * r.Mesh.NumberOfTets());
    box = art::WholeBoxForRegionError(volume, r.Mask.Inside, r.Mesh.Rms, r.Mesh.NumberOfTets(), cap, &progress);
  }
  bar.Finish();
  auto grid = art::RegionToUnstructuredGrid(r, ro, volume.DoubleValues, compare ? &box : nullptr);
  for (const char* name : { "IndexToWorld", "Frame" }) // the volume's placement goes with the mesh
  {
    if (vtkAbstractArray* a = image->GetFieldData() ? image->GetFieldData()->GetAbstractArray(name) : nullptr)
    {
      grid->GetFieldData()->AddArray(a);
    }
  }
  art::SaveMesh(grid, out);
  if (o.Flag("json"))
  {
    PrintJson(in, out, volume, ro, r, compare ? &box : nullptr);
  }
  else
  {
    PrintText(o, in, out, volume, ro, r, compare ? &box : nullptr);
  }
  return ExitOk;
}
} // namespace cli
#endif
