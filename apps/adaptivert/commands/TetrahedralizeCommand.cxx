// adaptivert tetrahedralize SURFACE OUT.vtu: the solid a closed surface bounds as a quality tet
// mesh (TetGen through AdaptiveRT::Meshing), to a tet budget or a largest tet volume; with
// --volume, the points carry the image's values (least-squares fit) and the tets where the fit
// misses the voxels most are refined. The surface is checked first: one that is open, not
// manifold or intersects itself is refused with the count of what is wrong.
#include "cli/NumberFormat.h"
#include "cli/Command.h"

#include "Error.h"

#ifdef ART_HAVE_Meshing
#include "cli/Json.h"
#include "cli/LoadOptions.h"
#include "cli/ProgressBar.h"
#include "DataLoader.h"
#include "MeshQuality.h"
#include "ReducerVTK.h"
#include "rendering/ReductionTargets.h"
#include "SurfaceTetrahedralizer.h"
#include "TriangleSurfaceVTK.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#endif

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace
{
void Declare(cli::Options& o)
{
  o.Add("output", 'o', "FILE", "the output .vtu (or give it after the surface)");
  o.Add("tets", 't', "N", "about N tets");
  o.Add("max-volume", 0, "V", "no tet larger than V (the surface's units cubed)");
  o.Add("volume", 0, "IMAGE",
    "the points carry this image's values (placed as the surface: the same coordinates), fitted to its voxels in the "
    "least-squares sense; with --tets the tets where the fit is worst are refined");
  o.Add("array", 0, "NAME", "with --volume: the image's point array to carry (default: its scalars)");
  o.Add("radius-edge", 0, "R", "TetGen's quality bound: largest circumradius over shortest edge", "1.414");
  o.Add("min-dihedral", 0, "DEG", "TetGen's quality bound: smallest dihedral angle in degrees", "10");
  cli::AddLoadOptions(o);
}

std::pair<std::string, std::string> InputAndOutput(const cli::Options& o)
{
  const auto& pos = o.Positional();
  if (pos.size() != (o.Has("output") ? 1u : 2u))
  {
    throw cli::UsageError(o.Has("output") && pos.size() == 2 ? "give the output once: after the surface or with -o"
                                                           : "needs a closed surface and an output .vtu");
  }
  const std::string out = o.Has("output") ? o.Get("output") : pos[1];
  std::string ext = std::filesystem::path(out).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext != ".vtu")
  {
    throw cli::UsageError("the output must be a .vtu file, got '" + out + "'");
  }
  if (!o.Has("tets") && !o.Has("max-volume"))
  {
    throw cli::UsageError("give --tets N or --max-volume V");
  }
  if (o.Has("tets") && o.Has("max-volume"))
  {
    throw cli::UsageError("--tets and --max-volume exclude each other: give one");
  }
  if (o.Has("array") && !o.Has("volume"))
  {
    throw cli::UsageError("--array goes with --volume IMAGE");
  }
  return { pos[0], out };
}

#ifdef ART_HAVE_Meshing
using cli::Grouped;

art::SurfaceMeshOptions MeshOptions(const cli::Options& o)
{
  art::SurfaceMeshOptions m;
  if (o.Has("tets"))
  {
    m.TargetTets = cli::ParseBudget(o.Get("tets"), 0, "--tets");
    if (m.TargetTets < 1)
    {
      throw cli::UsageError("--tets expects a count of at least 1");
    }
  }
  if (o.Has("max-volume"))
  {
    m.MaxVolume = o.GetDouble("max-volume");
    if (!(m.MaxVolume > 0) || !std::isfinite(m.MaxVolume))
    {
      throw cli::UsageError("--max-volume expects a positive volume, got '" + o.Get("max-volume") + "'");
    }
  }
  m.TetGen.RadiusEdge = o.GetDouble("radius-edge");
  m.TetGen.MinDihedral = o.GetDouble("min-dihedral");
  if (!(m.TetGen.RadiusEdge >= 1.1 && m.TetGen.RadiusEdge <= 10) || !(m.TetGen.MinDihedral >= 0 && m.TetGen.MinDihedral <= 20))
  {
    throw cli::UsageError("--radius-edge must be in [1.1, 10] and --min-dihedral in [0, 20] (TetGen's bounds)");
  }
  return m;
}

void Print(const cli::Options& o, const std::string& in, const std::string& out, const art::SurfaceMeshResult& r,
  const art::VoxelVolume* volume)
{
  const auto& m = r.Mesh;
  const auto q = art::MeasureQuality(m.Points.data(), m.NumberOfVertices(), m.Tets.data(), m.NumberOfTets());
  if (o.Flag("json"))
  {
    cli::Json j;
    j.Set("input", in).Set("output", out).Set("triangles", r.Surface.Triangles).Set("surface_volume", r.Surface.Volume)
      .Set("tets", m.NumberOfTets()).Set("vertices", m.NumberOfVertices()).Set("mesh_volume", r.MeshVolume)
      .Set("tetgen_runs", static_cast<long long>(r.Rounds.size())).Set("min_dihedral_degrees", q.MinDihedralDegrees)
      .Set("min_radius_ratio", q.MinRadiusRatio).Set("build_seconds", m.BuildSeconds);
    if (volume)
    {
      j.Set("volume", o.Get("volume")).Set("rms_error", m.Rms).Set("max_error", m.Max)
        .Set("covered_voxels", r.CoveredVoxels);
    }
    std::printf("%s\n", j.Str().c_str());
    return;
  }
  std::printf("input        %s (%s triangles, %s points: closed, manifold, no self-intersection; encloses %.6g)\n",
    in.c_str(), Grouped(r.Surface.Triangles).c_str(), Grouped(r.Surface.Points).c_str(), r.Surface.Volume);
  std::printf("tets         %s, %s vertices (TetGen -pq%g/%g, %zu run%s); volume %.6g (%.3f%% of the surface's)\n",
    Grouped(m.NumberOfTets()).c_str(), Grouped(m.NumberOfVertices()).c_str(), o.GetDouble("radius-edge"),
    o.GetDouble("min-dihedral"), r.Rounds.size(), r.Rounds.size() == 1 ? "" : "s", r.MeshVolume,
    100.0 * r.MeshVolume / std::max(r.Surface.Volume, 1e-300));
  if (volume)
  {
    std::printf("values       %s: RMS %.4g, max %.4g over the %s voxels inside the mesh\n", o.Get("volume").c_str(),
      m.Rms, m.Max, Grouped(r.CoveredVoxels).c_str());
  }
  std::printf("quality      min dihedral %.1f deg, radius ratio min %.3f mean %.3f, %lld inverted\n",
    q.MinDihedralDegrees, q.MinRadiusRatio, q.MeanRadiusRatio, q.Inverted);
  const bool over = m.TargetTets > 0 && m.NumberOfTets() > 1.1 * m.TargetTets;
  std::printf("output       %s%s\n", out.c_str(),
    over ? " (more tets than --tets: TetGen's quality bounds on this surface alone ask for that many)" : "");
  std::printf("time         %.2f s\n", m.BuildSeconds);
}
#endif

int Run(const cli::Options& o)
{
  const auto [in, out] = InputAndOutput(o);
#ifdef ART_HAVE_Meshing
  art::SurfaceMeshOptions mo = MeshOptions(o);
  if (art::KindOf(in) != art::DataKind::Surface)
  {
    throw art::Error(std::string("is a ") + art::KindName(art::KindOf(in)) +
        "; tetrahedralize takes a closed surface (.ply .obj .stl .vtp)",
      in);
  }
  auto poly = art::LoadSurface(in);
  std::unique_ptr<art::VoxelVolume> volume;
  if (o.Has("volume"))
  {
    art::LoadOptions lo = cli::LoadOptionsFrom(o);
    lo.Array = o.Get("array");
    auto image = art::LoadVolume(o.Get("volume"), lo);
    art::RequireOneComponent(image, o.Get("volume"));
    volume = std::make_unique<art::VoxelVolume>(art::VolumeFromImage(image, o.Get("volume")));
    mo.Volume = volume.get();
  }
  cli::ProgressBar bar(o.Flag("quiet"));
  art::Progress progress(bar.Callback());
  const art::SurfaceMeshResult r = art::TetrahedralizeSurface(art::TriangleSurfaceFromVTK(poly), mo, in, &progress);
  bar.Finish();
  auto grid = art::ToUnstructuredGrid(r.Mesh, volume && volume->DoubleValues);
  for (const auto& [name, v] : { std::pair<const char*, double>{ "surface_volume", r.Surface.Volume },
         { "mesh_volume", r.MeshVolume }, { "tetgen_runs", static_cast<double>(r.Rounds.size()) } })
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfTuples(1);
    a->SetValue(0, v);
    grid->GetFieldData()->AddArray(a);
  }
  art::SaveMesh(grid, out);
  Print(o, in, out, r, volume.get());
  return cli::ExitOk;
#else
  throw art::Error("tetrahedralize needs TetGen (AdaptiveRT::Meshing), which is not in this build "
                   "(ART_WITH_GPL_MESHING)",
    in);
#endif
}

cli::Registrar reg({ "tetrahedralize",
  "tet mesh of the solid a closed surface bounds (TetGen), optionally carrying a volume's values",
  "adaptivert tetrahedralize [options] SURFACE OUT.vtu  (or SURFACE -o OUT.vtu)",
  "  adaptivert tetrahedralize torus.ply torus.vtu --tets 20000\n"
  "  adaptivert tetrahedralize skin.vtp skin.vtu --volume ct.mha --tets 200000   (values fitted, refined where worst)\n"
  "  adaptivert tetrahedralize part.stl part.vtu --max-volume 0.5\n",
  Declare, Run });
} // namespace
