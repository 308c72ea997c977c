// adaptivert bench tets: our version of the seed paper's Table 1. The CT head reduced to a series
// of tet budgets and at full resolution, rendered at 500 x 500 by our cell-by-cell caster (exact
// rule with and without early termination, the paper's trapezoid rule), side by side in the same
// run with VTK's vtkUnstructuredGridVolumeRayCastMapper (Bunyk) on the same meshes and
// vtkFixedPointVolumeRayCastMapper on the voxels; every image scored (PSNR, SSIM, RMSE) against
// the full-resolution voxel reference. The VTK mappers need a display (run under xvfb-run -a).
#include "benchmarks/Bench.h"
#include "benchmarks/BenchUtil.h"
#include "Camera.h"
#include "cli/Command.h"
#include "DataLoader.h"
#include "Error.h"
#include "ImageIO.h"
#include "ImageMetrics.h"
#include "cli/Json.h"
#include "ParallelTiles.h"
#include "rendering/ReducedTets.h"
#include "TetMesh.h"
#include "TetRayCaster.h"
#include "TransferFunction.h"
#include "vtkTetRayCastMapper.h"
#include "VoxelReferenceCaster.h"
#ifdef ART_HAVE_Reduction
#include "ReducerVTK.h"
#include "TetReducer.h"
#include "cli/ResourcePath.h"
#endif

#include <vtkCamera.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFixedPointVolumeRayCastMapper.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkUnstructuredGridVolumeRayCastMapper.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

namespace
{
struct Row
{
  std::string method, mesh, series; // series: the reduction's refinement, "full" or "voxels"
  long long tets = 0, vertices = 0;
  cli::BenchStats seconds;
  art::ImageMetricsResult err;
  double tetsPerRay = 0, nsPerTet = 0;
};

art::Image OverBlack(art::Image img)
{
  img.CompositeOver({ 0.f, 0.f, 0.f });
  return img;
}

vtkSmartPointer<vtkUnstructuredGrid> ToGrid(const art::TetMesh& m)
{
  auto ug = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> s;
  s->SetName("scalars");
  for (std::size_t i = 0; i < m.NumberOfPoints(); ++i)
  {
    const auto& p = m.PointsArray()[i];
    pts->InsertNextPoint(p.x, p.y, p.z);
    s->InsertNextValue(m.Scalars()[i]);
  }
  ug->SetPoints(pts);
  ug->GetPointData()->SetScalars(s);
  ug->Allocate(static_cast<vtkIdType>(m.NumberOfTets()));
  for (std::size_t t = 0; t < m.NumberOfTets(); ++t)
  {
    const auto& v = m.Tet(t);
    vtkIdType ids[4] = { v[0], v[1], v[2], v[3] };
    ug->InsertNextCell(VTK_TETRA, 4, ids);
  }
  return ug;
}

// A VTK volume mapper in its own offscreen window with the shared camera: timed a frame at a
// time (its cached image dropped first), then read back.
class VTKWindow
{
public:
  VTKWindow(vtkAbstractVolumeMapper* mapper, vtkVolumeProperty* prop, vtkCamera* cam, int w, int h)
    : W(w), H(h)
  {
    Vol->SetMapper(mapper);
    Vol->SetProperty(prop);
    Ren->SetBackground(0, 0, 0);
    Ren->AddVolume(Vol);
    Ren->SetActiveCamera(cam);
    Win->SetOffScreenRendering(1);
    Win->SetSize(w, h);
    Win->AddRenderer(Ren);
  }
  double Frame()
  {
    Vol->Modified(); // no cached image
    const auto t0 = std::chrono::steady_clock::now();
    Win->Render();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  art::Image Read()
  {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(Win);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    vtkDataArray* px = grab->GetOutput()->GetPointData()->GetScalars();
    art::Image img(W, H);
    for (int y = 0; y < H; ++y)
    {
      for (int x = 0; x < W; ++x)
      {
        const vtkIdType i = static_cast<vtkIdType>(H - 1 - y) * W + x;
        img.Set(x, y, { float(px->GetComponent(i, 0) / 255.0), float(px->GetComponent(i, 1) / 255.0),
                        float(px->GetComponent(i, 2) / 255.0), 1.f });
      }
    }
    return img;
  }

private:
  int W, H;
  vtkNew<vtkVolume> Vol;
  vtkNew<vtkRenderer> Ren;
  vtkNew<vtkRenderWindow> Win;
};

// --tets-series, checked before any work; --tets-no-relocate turns relocated into bisection.
std::vector<std::string> SeriesNames(const cli::Options& o)
{
  std::vector<std::string> out;
  std::stringstream ss(o.Get("tets-series"));
  std::string s;
  while (std::getline(ss, s, ','))
  {
    if (s == "relocated" && o.Flag("tets-no-relocate"))
    {
      s = "bisection";
    }
    if (s != "relocated" && s != "bisection" && s != "anisotropic")
    {
      throw cli::UsageError("--tets-series takes relocated, bisection and anisotropic, got '" + s + "'");
    }
    if (std::find(out.begin(), out.end(), s) == out.end())
    {
      out.push_back(s);
    }
  }
  return out;
}

void Declare(cli::Options& o)
{
  o.Add("tets-input", 0, "FILE", "volume for `bench tets`", cli::DataDir() + "/ct-head-128.mha");
  o.Add("tets-levels", 0, "N,N..", "tet budgets of the reduction series", "10000,25000,50000,100000,250000");
  o.Add("tets-size", 0, "WxH", "image size for `bench tets`", "500x500");
  o.Add("tets-tf", 0, "NAME|FILE", "transfer function for `bench tets`", "ct-skin-bone");
  o.Add("tets-plain-reduction", 0, "", "reduce in plain L2, not weighted by the transfer function's opacity");
  o.Add("tets-series", 0, "LIST",
    "reduction series rendered side by side: relocated (render's lattice refinement), bisection (no relocation), "
    "anisotropic (MMG3D)", "relocated,anisotropic");
  o.Add("tets-no-relocate", 0, "", "the relocated series without relocation (as --tets-series bisection)");
  o.Add("tets-bunyk-max", 0, "N", "largest mesh (tets) given to VTK's Bunyk mapper", "1000000");
  o.Add("tets-no-vtk", 0, "", "skip VTK's mappers (they need a display)");
}

// Per series, the smallest mesh whose headline render reaches FixedPoint's PSNR, and its time
// against FixedPoint's.
void FixedPointMatch(const std::vector<Row>& rows, long long voxels, std::ostringstream& md)
{
  const auto fp = std::find_if(rows.begin(), rows.end(), [](const Row& r) { return r.series == "voxels"; });
  if (fp == rows.end())
  {
    return;
  }
  char line[512];
  std::vector<std::string> done;
  for (const Row& r : rows)
  {
    if (r.series == "voxels" || r.series == "full" || std::find(done.begin(), done.end(), r.series) != done.end())
    {
      continue;
    }
    done.push_back(r.series);
    const Row* best = nullptr;
    for (const Row& q : rows)
    {
      if (q.series == r.series && q.method == "ours exact, ERT 0.99" && q.err.psnr >= fp->err.psnr &&
        (!best || q.vertices < best->vertices))
      {
        best = &q;
      }
    }
    if (best)
    {
      std::snprintf(line, sizeof line,
        "- %s: the smallest mesh at FixedPoint's PSNR (%.2f dB) is %s (%.2f%% of the vertices): %.2f dB in %.3f s, "
        "%.2fx FixedPoint's time (%.3f s)\n",
        r.series.c_str(), fp->err.psnr, best->mesh.c_str(), 100.0 * best->vertices / voxels, best->err.psnr,
        best->seconds.median, best->seconds.median / fp->seconds.median, fp->seconds.median);
    }
    else
    {
      std::snprintf(line, sizeof line, "- %s: no mesh of the series reaches FixedPoint's PSNR (%.2f dB)\n",
        r.series.c_str(), fp->err.psnr);
    }
    md << line;
  }
}

int Run(const cli::Options& o)
{
  const std::string in = o.Get("tets-input");
  const std::vector<std::string> seriesNames = SeriesNames(o); // a usage error before any work
  const std::string dir = o.Get("results");
  const int runs = static_cast<int>(std::max(1LL, o.GetInt("runs")));
  int W, H;
  o.GetSize("tets-size", W, H);
  std::filesystem::create_directories(dir);
  const bool vtk = !o.Flag("tets-no-vtk") && std::getenv("DISPLAY");
  if (!o.Flag("tets-no-vtk") && !vtk)
  {
    std::fprintf(stderr, "bench tets: no DISPLAY, VTK's mappers skipped (run under xvfb-run -a)\n");
  }

  auto volume = art::LoadVolume(in);
  double range[2], b[6], spacing[3];
  volume->GetPointData()->GetScalars()->GetRange(range);
  volume->GetBounds(b);
  volume->GetSpacing(spacing);
  int dims[3];
  volume->GetDimensions(dims);
  const long long voxels = static_cast<long long>(dims[0]) * dims[1] * dims[2];
  const std::string tfName = o.Get("tets-tf");
  const art::TransferFunction tf = std::filesystem::exists(tfName) ? art::TransferFunction::FromFile(tfName)
    : art::TransferFunction::PresetFor(tfName, volume, range[0], range[1]);
  vtkNew<vtkCamera> cam;
  cam->SetPosition(0, -1, 0);
  cam->SetFocalPoint(0, 0, 0);
  cam->SetViewUp(0, 0, 1);
  art::Camera::Frame(cam, art::Box3::FromBounds(b), 30, 10, 1.0);
  const art::Camera camera = art::Camera::FromVTK(cam, W, H);
  vtkNew<vtkVolumeProperty> prop;
  tf.ToVTK(prop);

  // The reference: voxels, trilinear, 2 samples per voxel, exact steps, no early termination.
  std::fprintf(stderr, "reference (voxel caster) ...\n");
  art::Image refRaw;
  const auto refCaster = art::VoxelReferenceCaster::FromVTK(volume, tf, in);
  const art::RenderStats refStats = refCaster.Render(camera, refRaw);
  const art::Image ref = OverBlack(refRaw);
  art::WriteImage(ref, dir + "/tets-reference.png");

  // The meshes: each reduction series (one run of its levels) and full resolution.
  struct MeshEntry
  {
    std::string name, series;
    std::unique_ptr<art::TetMesh> mesh;
    double rms = -1;
  };
  std::vector<MeshEntry> meshes;
#ifdef ART_HAVE_Reduction
  {
    std::vector<long long> levels;
    std::stringstream ss(o.Get("tets-levels"));
    std::string item;
    while (std::getline(ss, item, ','))
    {
      levels.push_back(std::stoll(item));
    }
    std::sort(levels.begin(), levels.end());
    const art::VoxelVolume voxelVolume = art::VolumeFromImage(volume, in);
    for (const std::string& series : seriesNames)
    {
      if (levels.empty())
      {
        break;
      }
      std::fprintf(stderr, "reducing to %zu budgets (%s) ...\n", levels.size(), series.c_str());
      art::ReducerOptions ro;
      ro.TargetTets = levels.back();
      ro.Levels = levels;
      ro.RelocateVertices = series == "relocated"; // as render reduces
      if (series == "anisotropic")
      {
        ro.Refine = art::ReducerOptions::Refinement::Anisotropic;
      }
      if (!o.Flag("tets-plain-reduction"))
      {
        ro.ScalarOpacity = tf.OpacityPoints();
      }
      const std::string prefix = series == "anisotropic" ? "anisotropic " : "reduced ";
      for (const auto& r : art::TetReducer(ro).Run(voxelVolume))
      {
        meshes.push_back({ prefix + std::to_string(r.NumberOfTets()), series,
          std::make_unique<art::TetMesh>(cli::ToTetMesh(r)), r.Rms });
      }
    }
  }
#endif
  std::fprintf(stderr, "full-resolution tets ...\n");
  meshes.push_back({ "full resolution", "full", std::make_unique<art::TetMesh>(art::TetMesh::FromImage(volume, in)), 0.0 });

  std::vector<Row> rows;
  auto report = [&](const Row& r) {
    std::fprintf(stderr, "  %-22s %-18s %9lld tets  %8.3f s [%.3f-%.3f]  PSNR %6.2f dB  SSIM %.4f\n",
      r.method.c_str(), r.mesh.c_str(), r.tets, r.seconds.median, r.seconds.lo, r.seconds.hi, r.err.psnr, r.err.ssim);
    rows.push_back(r);
  };
  // Per mesh, every method is timed in turn, a frame each per round (TimeInterleaved): this
  // machine's speed drifts, and runs of one method after another would put the drift into the
  // ratios.
  for (const auto& me : meshes)
  {
    const art::TetMesh& m = *me.mesh;
    const std::string file = [&] {
      std::string f = me.name;
      std::replace(f.begin(), f.end(), ' ', '-');
      return f;
    }();
    struct Method
    {
      Row row;
      std::function<double()> frame;
      std::function<void(Row&)> finish; // error figures (and images) once timed
    };
    std::vector<Method> methods;
    auto row = [&](const char* name) {
      return Row{ name, me.name, me.series, static_cast<long long>(m.NumberOfTets()), static_cast<long long>(m.NumberOfPoints()) };
    };
    struct Variant
    {
      const char* name;
      art::RenderSettings::Rule rule;
      double ert;
      bool skip = true;
    };
    struct Ours
    {
      std::unique_ptr<art::TetRayCaster> caster;
      art::Image img;
      art::RenderStats st;
    };
    std::vector<std::unique_ptr<Ours>> ours;
    for (const Variant& v : { Variant{ "ours exact, ERT 0.99", art::RenderSettings::Rule::Exact, 0.99 },
           Variant{ "ours exact, no ERT", art::RenderSettings::Rule::Exact, 2.0 },
           Variant{ "ours trapezoid, ERT 0.99", art::RenderSettings::Rule::Trapezoid, 0.99 },
           Variant{ "ours exact, ERT 0.99, every tet", art::RenderSettings::Rule::Exact, 0.99, false } })
    {
      art::RenderSettings s;
      s.tf = tf;
      s.rule = v.rule;
      s.earlyTermination = v.ert;
      s.skipEmpty = v.skip; // "every tet": without empty-space skipping
      ours.push_back(std::make_unique<Ours>());
      Ours* o = ours.back().get();
      o->caster = std::make_unique<art::TetRayCaster>(m, s);
      const bool keep = v.ert < 1 && v.rule == art::RenderSettings::Rule::Exact && v.skip;
      methods.push_back({ row(v.name),
        [&camera, o] {
          o->st = o->caster->Render(camera, o->img);
          return o->st.seconds;
        },
        [&, o, keep](Row& r) {
          r.err = art::CompareImages(OverBlack(o->img), ref);
          r.tetsPerRay = o->st.counters.PerRay(o->st.counters.tetsCrossed);
          r.nsPerTet = o->st.counters.tetsCrossed
            ? r.seconds.median * 1e9 * art::GetThreadCount() / o->st.counters.tetsCrossed : 0;
          if (keep)
          {
            art::WriteImage(OverBlack(o->img), dir + "/tets-ours-" + file + ".png");
          }
        } });
    }
    vtkSmartPointer<vtkUnstructuredGrid> grid;
    vtkNew<vtkUnstructuredGridVolumeRayCastMapper> bunyk;
    vtkNew<vtkTetRayCastMapper> mapper;
    std::unique_ptr<VTKWindow> bunykWin, mapperWin;
    if (vtk && static_cast<long long>(m.NumberOfTets()) <= o.GetInt("tets-bunyk-max"))
    {
      grid = ToGrid(m);
      bunyk->SetInputData(grid);
      bunyk->SetAutoAdjustSampleDistances(0);
      bunyk->SetImageSampleDistance(1.0f);
      bunykWin = std::make_unique<VTKWindow>(bunyk, prop, cam, W, H);
      methods.push_back({ row("VTK Bunyk (UG ray cast)"), [&] { return bunykWin->Frame(); },
        [&](Row& r) {
          const art::Image img = bunykWin->Read();
          r.err = art::CompareImages(img, ref);
          art::WriteImage(img, dir + "/tets-bunyk-" + file + ".png");
        } });
      // Ours the same way, mapper against mapper: window draw and read-back included.
      mapper->SetInputData(grid);
      mapper->SetAutoAdjustSampleDistances(0); // one ray a pixel, as Bunyk's
      mapperWin = std::make_unique<VTKWindow>(mapper, prop, cam, W, H);
      methods.push_back({ row("ours mapper in a window"), [&] { return mapperWin->Frame(); },
        [&](Row& r) { r.err = art::CompareImages(mapperWin->Read(), ref); } });
    }
    std::vector<std::function<double()>> frames;
    for (const Method& method : methods)
    {
      frames.push_back(method.frame);
    }
    const std::vector<cli::BenchStats> times = cli::TimeInterleaved(runs, frames);
    for (std::size_t i = 0; i < methods.size(); ++i)
    {
      methods[i].row.seconds = times[i];
      methods[i].finish(methods[i].row);
      report(methods[i].row);
    }
  }
  if (vtk)
  {
    vtkNew<vtkFixedPointVolumeRayCastMapper> fp;
    fp->SetInputData(volume);
    fp->SetAutoAdjustSampleDistances(0);
    fp->SetImageSampleDistance(1.0f);
    fp->SetSampleDistance(0.5 * std::min(spacing[0], std::min(spacing[1], spacing[2])));
    VTKWindow win(fp, prop, cam, W, H);
    Row r{ "VTK FixedPoint (voxels)", "voxels", "voxels", 0, voxels };
    r.seconds = cli::TimeRuns(runs, [&] { return win.Frame(); });
    const art::Image img = win.Read();
    r.err = art::CompareImages(img, ref);
    report(r);
    art::WriteImage(img, dir + "/tets-fixedpoint.png");
  }

  // JSON, markdown, chart.
  const cli::RunInfo run = cli::ThisRun();
  const std::string &src = run.source, &commit = run.commit, &cpu = run.cpu, &date = run.date;
  std::vector<cli::Json> jr;
  for (const Row& r : rows)
  {
    cli::Json j;
    j.Set("method", r.method).Set("mesh", r.mesh).Set("series", r.series).Set("tets", r.tets).Set("vertices", r.vertices)
      .Set("seconds", r.seconds.median).Set("seconds_min", r.seconds.lo).Set("seconds_max", r.seconds.hi)
      .Set("psnr", r.err.psnr).Set("ssim", r.err.ssim).Set("rmse", r.err.rmse)
      .Set("tets_per_ray", r.tetsPerRay).Set("ns_per_tet_crossed_per_thread", r.nsPerTet);
    jr.push_back(j);
  }
  cli::Json js;
  js.Set("benchmark", "tets").Set("input", in).Set("voxels", voxels).Set("width", W).Set("height", H)
    .Set("transfer_function", tfName).Set("machine", cpu)
    .Set("hardware_threads", static_cast<long long>(std::thread::hardware_concurrency()))
    .Set("threads", art::GetThreadCount()).Set("date", date).Set("commit", commit).Set("runs", runs)
    .Set("reference_seconds", refStats.seconds).Set("rows", jr);
  const std::string stem = dir + "/tets";
  std::ofstream(stem + ".json") << js.Str() << "\n";

  // Markdown with the ratios the issue asks for.
  std::ostringstream md;
  md << "# Tet ray casting: the CT head reduction series (" << W << " x " << H << ")\n\n"
     << in << " (" << dims[0] << " x " << dims[1] << " x " << dims[2] << " voxels), transfer function " << tfName
     << (o.Flag("tets-plain-reduction") ? " (plain L2 reduction" : " (reduction weighted by its opacity")
     << "; series: " << o.Get("tets-series") << (o.Flag("tets-no-relocate") ? ", no relocation)" : ")")
     << ", reference: voxel ray caster (trilinear, 2 samples/voxel, exact steps, no ERT; " << refStats.seconds
     << " s). " << cpu << ", " << art::GetThreadCount() << " threads, commit " << commit << ", " << date
     << ". Times: median of " << runs << " runs after a warm-up [min-max]; a mesh's methods are timed in turn, one frame each per round.\n\n"
     << "| method | mesh | tets | vertices (% of voxels) | time s [min-max] | PSNR dB | SSIM | RMSE | tets/ray | ns/tet crossed/thread |\n"
     << "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  char line[512];
  for (const Row& r : rows)
  {
    std::snprintf(line, sizeof line, "| %s | %s | %lld | %lld (%.2f%%) | %.3f [%.3f-%.3f] | %.2f | %.4f | %.5f | %.1f | %.0f |\n",
      r.method.c_str(), r.mesh.c_str(), r.tets, r.vertices, 100.0 * r.vertices / voxels, r.seconds.median,
      r.seconds.lo, r.seconds.hi, r.err.psnr, r.err.ssim, r.err.rmse, r.tetsPerRay, r.nsPerTet);
    md << line;
  }
  md << "\n## Ratios\n\n";
  const Row* fullOurs = nullptr;
  for (const Row& r : rows)
  {
    if (r.mesh == "full resolution" && r.method == "ours exact, ERT 0.99")
    {
      fullOurs = &r;
    }
  }
  for (const Row& r : rows)
  {
    if (r.method.rfind("VTK Bunyk", 0) == 0)
    {
      for (const Row& q : rows)
      {
        if (q.mesh == r.mesh && q.method == "ours exact, ERT 0.99")
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
    if (fullOurs && r.method == "ours exact, ERT 0.99" && r.mesh != "full resolution")
    {
      std::snprintf(line, sizeof line,
        "- %s (%.2f%% of the vertices): %.2fx faster than our full-resolution render, %.0f%% of its time, PSNR %.2f dB\n",
        r.mesh.c_str(), 100.0 * r.vertices / voxels, fullOurs->seconds.median / r.seconds.median,
        100.0 * r.seconds.median / fullOurs->seconds.median, r.err.psnr);
      md << line;
    }
  }
  FixedPointMatch(rows, voxels, md);
  std::ofstream(stem + ".md") << md.str();
  std::printf("%s", md.str().c_str());

  cli::FinishResults(src + "/tests/benchmarks/tets_chart.py", stem);
  return cli::ExitOk;
}

cli::BenchRegistrar reg({ "tets",
  "the CT head reduction series cast cell by cell vs VTK's Bunyk and FixedPoint mappers (time vs PSNR)", Declare,
  Run });
} // namespace
