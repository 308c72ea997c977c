// The surface tracer behind `adaptivert render` for triangle scenes (.ply .obj .stl .vtp): the
// TriangleGrid ray tracing machine with point lights, shadows and transparent surfaces.
#ifdef ART_HAVE_TriangleGrid
#include "Accelerator.h"
#include "Camera.h"
#include "cli/Command.h"
#include "DataLoader.h"
#include "Error.h"
#include "ImageIO.h"
#include "cli/Json.h"
#include "ParallelTiles.h"
#include "cli/ProgressBar.h"
#include "rendering/Render.h"
#include "SurfaceColours.h"
#include "SurfaceTracer.h"

#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace
{
void Declare(cli::Options& o)
{
  o.Add("accelerator", 0, "NAME", "triangle scenes: recursive, octree, uniform or brute", "recursive");
  o.Add("threshold", 0, "N", "triangle scenes: voxel threshold (R: VOX_NTRG_THR, O: VX_THRESHOLD), 0 = default", "0");
  o.Add("subdivisions", 0, "N", "triangle scenes: recursive grid N_SUB_VOXELS, 0 = default", "0");
  o.Add("plane-weight", 0, "N", "triangle scenes: octree PLANE_WEIGHT, 0 = default", "0");
  o.Add("no-top-grid", 0, "", "triangle scenes: recursive grid without the top-level grid");
  o.Add("opacity", 0, "A", "triangle scenes: surface opacity; < 1 shows every surface and dims light through them", "1");
  o.Add("lights", 0, "X,Y,Z[;..]", "triangle scenes: point lights (default: a headlight and a key light)");
  o.Add("no-shadows", 0, "", "triangle scenes: no shadow rays");
  o.Add("flat", 0, "", "triangle scenes: flat shading (no vertex normals)");
  o.Add("color", 0, "R,G,B", "triangle scenes: surface colour when the scene has none", "0.85,0.82,0.75");
  o.Add("camera-position", 0, "X,Y,Z", "put the camera here (e.g. inside a level) instead of framing the scene");
  o.Add("focal-point", 0, "X,Y,Z", "with --camera-position: look at this point (default: the scene's centre)");
  o.Add("view-angle", 0, "DEG", "vertical view angle of the perspective camera", "30");
}

art::Vec3 ParseVec(const std::string& s, const char* what)
{
  std::istringstream in(s);
  art::Vec3 v;
  char c1 = 0, c2 = 0;
  if (!(in >> v.x >> c1 >> v.y >> c2 >> v.z) || c1 != ',' || c2 != ',' || !art::IsFinite(v))
  {
    throw cli::UsageError(std::string(what) + " expects X,Y,Z, got '" + s + "'");
  }
  return v;
}

// The scene's triangles, its colours on the points. A scene far from the origin is traced about
// its centre (TriangleStore::OriginFor): the camera and lights given on the command line move
// with it, by `shift`.
struct SurfaceScene
{
  vtkSmartPointer<vtkPolyData> pd;
  std::shared_ptr<art::TriangleStore> store;
  art::Vec3 shift;
};

SurfaceScene LoadScene(const std::string& input)
{
  SurfaceScene sc;
  // Face colours move onto corners of each face's own (SurfaceColours.h).
  sc.pd = art::WithColoursOnPoints(art::LoadSurface(input));
  double pb[6];
  sc.pd->GetBounds(pb);
  sc.shift = art::TriangleStore::OriginFor(art::Box3::FromBounds(pb));
  sc.store = std::make_shared<art::TriangleStore>(art::TriangleStore::FromPolyData(sc.pd, sc.shift));
  if (sc.store->Size() == 0)
  {
    // LoadSurface found polygons, so every one was dropped as degenerate: say so.
    throw art::Error("has no triangles to render: all " +
        std::to_string(sc.pd->GetNumberOfPolys() + sc.pd->GetNumberOfStrips()) +
        " polygons have zero area or non-finite points (float coordinates far from the origin lose small detail)",
      input);
  }
  return sc;
}

std::unique_ptr<art::Accelerator> BuildAccelerator(const cli::Options& o, const SurfaceScene& sc)
{
  art::AcceleratorOptions ao;
  try
  {
    ao.kind = art::AcceleratorKindFromName(o.Get("accelerator"));
  }
  catch (const art::Error& e)
  {
    throw cli::UsageError(e.what()); // a command-line mistake: exit 2
  }
  ao.voxelThreshold = static_cast<int>(o.GetInt("threshold"));
  ao.subdivisions = static_cast<int>(o.GetInt("subdivisions"));
  ao.planeWeight = static_cast<int>(o.GetInt("plane-weight"));
  ao.topLevelGrid = !o.Flag("no-top-grid");
  if (ao.voxelThreshold < 0 || ao.subdivisions < 0 || ao.subdivisions > 16 || ao.planeWeight < 0)
  {
    throw cli::UsageError("--threshold, --subdivisions (<= 16) and --plane-weight expect counts >= 0");
  }
  return art::MakeAccelerator(sc.store, ao);
}

// The scene framed as any render frames it, or placed with --camera-position / --focal-point
// (z up, as game levels and terrains have it).
void SetupSurfaceCamera(const cli::Options& o, const art::Box3& bounds, const art::Vec3& shift, vtkCamera* vcam)
{
  const double angle = o.GetDouble("view-angle");
  if (!(angle > 0 && angle < 180))
  {
    throw cli::UsageError("--view-angle expects degrees in (0, 180)");
  }
  // The angle is set before framing, which zooms by narrowing it (setting it after undid --zoom).
  vcam->SetViewAngle(angle);
  if (!o.Has("camera-position"))
  {
    // A flat, wide scene from above at an angle, which shows its layout.
    cli::SetupCamera(o, bounds, bounds, vcam, art::Camera::LayoutView(bounds) ? art::Camera::LayoutElevation : 0.0);
    return;
  }
  const double zoom = cli::Zoom(o), azimuth = o.GetDouble("azimuth"), elevation = o.GetDouble("elevation");
  if (!std::isfinite(azimuth) || !std::isfinite(elevation))
  {
    throw cli::UsageError("--azimuth and --elevation expect finite angles");
  }
  vcam->SetParallelProjection(o.Flag("parallel"));
  vcam->SetParallelScale(std::max(0.5 * bounds.Diagonal(), 1e-12));
  const art::Vec3 p = ParseVec(o.Get("camera-position"), "--camera-position") - shift;
  const art::Vec3 f = o.Has("focal-point") ? ParseVec(o.Get("focal-point"), "--focal-point") - shift : bounds.Center();
  if (p == f)
  {
    throw cli::UsageError("--camera-position and --focal-point must differ");
  }
  vcam->SetPosition(p.x, p.y, p.z);
  vcam->SetFocalPoint(f.x, f.y, f.z);
  // z is up, except when looking straight along z (a floor plan from above): a view-up parallel
  // to the view direction leaves no 'right', and every ray came out NaN (one flat colour).
  const art::Vec3 dir = art::Normalize(f - p);
  const bool alongZ = std::abs(dir.z) > 0.999;
  vcam->SetViewUp(0, alongZ ? (dir.z < 0 ? 1 : -1) : 0, alongZ ? 0 : 1);
  vcam->OrthogonalizeViewUp();
  cli::ApplyViewUp(o, vcam);
  vcam->Azimuth(azimuth);
  vcam->Elevation(elevation);
  vcam->OrthogonalizeViewUp();
  vcam->Zoom(zoom);
  vcam->Roll(cli::Roll(o));
}

art::SurfaceTracerSettings TracerSettings(const cli::Options& o, vtkCamera* vcam, const art::Vec3& shift)
{
  art::SurfaceTracerSettings s;
  s.opacity = o.GetDouble("opacity");
  if (!(s.opacity > 0 && s.opacity <= 1))
  {
    throw cli::UsageError("--opacity expects a value in (0, 1]");
  }
  s.shadows = !o.Flag("no-shadows");
  s.smooth = !o.Flag("flat");
  const art::Vec3 col = ParseVec(o.Get("color"), "--color");
  s.color = { { float(col.x), float(col.y), float(col.z) } };
  if (!o.Has("lights"))
  {
    // A headlight, and a key light above and to the left of the camera, which casts shadows.
    s.lights = art::HeadAndKeyLights(
      art::Vec3(vcam->GetPosition()), art::Vec3(vcam->GetFocalPoint()), art::Vec3(vcam->GetViewUp()));
    return s;
  }
  std::stringstream ss(o.Get("lights"));
  std::string item;
  while (std::getline(ss, item, ';'))
  {
    s.lights.push_back({ ParseVec(item, "--lights") - shift, 0.0 });
  }
  for (auto& l : s.lights)
  {
    l.intensity = 0.85 / double(s.lights.size());
  }
  return s;
}

long long CoveredPixels(const art::Image& img)
{
  long long covered = 0;
  for (std::size_t i = 3; i < img.Pixels().size(); i += 4)
  {
    covered += img.Pixels()[i] > 0.f;
  }
  return covered;
}

// An image of background only exits 0 like any other: say why when we can. A flat scene (a
// floor plan, a terrain tile in z = 0) is seen face on by default (Camera::DefaultView), edge
// on when --azimuth or --elevation turn it so.
std::string NothingInViewNote(const art::Box3& bounds, const art::Camera& cam)
{
  // Flat along an axis that the view direction is square to: every ray runs beside the plane.
  const art::Vec3 e = bounds.hi - bounds.lo, f = Normalize(cam.Forward());
  const double ext[3] = { e.x, e.y, e.z }, dir[3] = { f.x, f.y, f.z };
  int flat = -1;
  for (int a = 0; a < 3; ++a)
  {
    flat = (ext[a] <= 1e-6 * Length(e) && std::abs(dir[a]) < 1e-6) ? a : flat;
  }
  return flat >= 0 ? std::string("no surface is in view: the scene is flat in ") + "xyz"[flat] +
      " and seen edge-on (the default view, without --azimuth and --elevation, looks at it face on)"
                   : std::string("no surface is in view (the image is background only)");
}

struct TraceResult
{
  art::Counters c;
  double buildSeconds = 0, seconds = 0, mb = 0;
  long long covered = 0;
  std::string note, accelerator;
};

void PrintResult(const cli::Options& o, const std::string& input, const cli::View& view, const SurfaceScene& sc,
  const art::SurfaceTracerSettings& s, const TraceResult& r)
{
  const double mrays = double(r.c.rays) / std::max(r.seconds, 1e-9) / 1e6;
  if (o.Flag("json"))
  {
    cli::Json j;
    j.Set("input", input).Set("output", view.output).Set("width", view.width).Set("height", view.height);
    j.Set("accelerator", r.accelerator).Set("triangles", static_cast<long long>(sc.store->Size()));
    j.Set("build_seconds", r.buildSeconds).Set("render_seconds", r.seconds).Set("rays", static_cast<long long>(r.c.rays));
    j.Set("mrays_per_second", mrays).Set("memory_mb", r.mb).Set("threads", art::GetThreadCount());
    j.Set("voxels_per_ray", r.c.PerRay(r.c.voxelsVisited)).Set("triangles_per_ray", r.c.PerRay(r.c.trianglesTested));
    j.Set("lights", static_cast<long long>(s.lights.size())).Set("opacity", s.opacity);
    j.Set("covered_pixels", r.covered);
    if (!r.note.empty())
    {
      j.Set("note", r.note);
    }
    std::printf("%s\n", j.Str().c_str());
    return;
  }
  std::printf("input        %s: %zu triangles\n", input.c_str(), sc.store->Size());
  std::printf("accelerator  %s: built in %.1f ms, %.1f MB (%.0f bytes/triangle with the store)\n",
    r.accelerator.c_str(), r.buildSeconds * 1e3, r.mb, r.mb * 1e6 / double(sc.store->Size()));
  std::printf("render       %d x %d, %zu lights%s, opacity %g: %.3f s, %llu rays (%.2f Mrays/s on %d threads)\n",
    view.width, view.height, s.lights.size(), s.shadows ? " with shadows" : "", s.opacity, r.seconds,
    static_cast<unsigned long long>(r.c.rays), mrays, art::GetThreadCount());
  std::printf("work         %.1f voxels visited, %.1f triangles tested per ray\n", r.c.PerRay(r.c.voxelsVisited),
    r.c.PerRay(r.c.trianglesTested));
  if (!r.note.empty())
  {
    std::printf("note         %s\n", r.note.c_str());
  }
  std::printf("output       %s\n", view.output.c_str());
}

int Run(const cli::Options& o, const std::string& input)
{
  const cli::View view = cli::ViewFromOptions(o);
  cli::ProgressBar bar(o.Flag("quiet"));
  art::Progress progress(bar.Callback());
  TraceResult r;

  auto t0 = std::chrono::steady_clock::now();
  const SurfaceScene sc = LoadScene(input);
  const auto acc = BuildAccelerator(o, sc);
  r.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.accelerator = acc->Name();
  r.mb = double(acc->MemoryBytes() + sc.store->MemoryBytes()) / 1e6;

  const art::Box3 bounds = sc.store->Bounds();
  vtkNew<vtkCamera> vcam;
  SetupSurfaceCamera(o, bounds, sc.shift, vcam);
  const art::Camera cam = art::Camera::FromVTK(vcam, view.width, view.height);
  const art::SurfaceTracerSettings s = TracerSettings(o, vcam, sc.shift);

  std::vector<std::array<float, 3>> colors = art::PointColours(sc.pd);
  art::SurfaceTracer tracer(*acc, s);
  if (!colors.empty())
  {
    tracer.SetPointColors(std::move(colors));
  }
  progress.Begin("tracing", double(view.width) * view.height);
  t0 = std::chrono::steady_clock::now();
  art::Image img = tracer.Render(cam, &progress, &r.c);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  progress.End();
  bar.Finish();
  r.covered = CoveredPixels(img);
  if (r.covered == 0)
  {
    r.note = NothingInViewNote(bounds, cam);
  }
  img.CompositeOver({ view.background[0], view.background[1], view.background[2] });
  art::WriteImage(img, view.output);
  PrintResult(o, input, view, sc, s, r);
  return cli::ExitOk;
}

cli::RendererRegistrar reg({ "surface", { art::DataKind::Surface }, Declare, Run });
} // namespace
#endif // ART_HAVE_TriangleGrid
