// adaptivert bench tets: our version of the seed paper's Table 1. The CT head reduced to a series
// of tet budgets and at full resolution, rendered at 500 x 500 by our cell-by-cell caster (exact
// rule with and without early termination, the paper's trapezoid rule), side by side in the same
// run with VTK's vtkUnstructuredGridVolumeRayCastMapper (Bunyk) on the same meshes and
// vtkFixedPointVolumeRayCastMapper on the voxels; every image scored (PSNR, SSIM, RMSE) against
// the full-resolution voxel reference. The VTK mappers need a display (run under xvfb-run -a).
// Any volume (resampled by a factor, labelled so) and any mesh series read from files (other
// reducers' output) can be given; the scaling figure is the smallest mesh at FixedPoint's PSNR.
#include "benchmarks/Bench.h"
#include "benchmarks/BenchUtil.h"
#include "benchmarks/TetBenchmark.h"
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
#include <vtkImageResample.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
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
using Row = cli::TetBenchRow;

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
  /// Places the volume by a matrix (its data then in index-aligned coordinates).
  void Place(vtkMatrix4x4* m) { Vol->SetUserMatrix(m); }
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

void Declare(cli::Options& o)
{
  o.Add("tets-input", 0, "FILE", "volume for `bench tets`", cli::DataDir() + "/ct-head-128.mha");
  o.Add("tets-resample", 0, "F", "resample the volume by F along each axis first (trilinear; labelled so)", "1");
  o.Add("tets-levels", 0, "N,N..", "tet budgets of the reduction series (empty: none)", "10000,25000,50000,100000,250000");
  o.Add("tets-series", 0, "LIST",
    "reduction series rendered side by side: relocated (relocated bisection), bisection (no relocation), "
    "anisotropic (MMG3D, relocated as render's default reduces)", "relocated,anisotropic");
  o.Add("tets-meshes", 0, "FILE,FILE..", "a mesh series read from files (another reducer's meshes of the volume)");
  o.Add("tets-meshes-name", 0, "NAME", "name of the --tets-meshes series", "meshes");
  o.Add("tets-no-full", 0, "", "leave out the full-resolution tets (too large past ~50M tets)");
  o.Add("tets-main-only", 0, "", "time only `ours exact, ERT 0.99` of our variants (and VTK's mappers)");
  o.Add("tets-size", 0, "WxH", "image size for `bench tets`", "500x500");
  o.Add("tets-tf", 0, "NAME|FILE", "transfer function for `bench tets`", "ct-skin-bone");
  o.Add("tets-plain-reduction", 0, "", "reduce in plain L2, not weighted by the transfer function's opacity");
  o.Add("tets-no-relocate", 0, "", "the relocated series without relocation (as --tets-series bisection)");
  o.Add("tets-bunyk-max", 0, "N", "largest mesh (tets) given to VTK's Bunyk mapper", "1000000");
  o.Add("tets-no-vtk", 0, "", "skip VTK's mappers (they need a display)");
}

std::vector<std::string> SplitList(const std::string& s)
{
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
  {
    if (!item.empty())
    {
      out.push_back(item);
    }
  }
  return out;
}

// The volume, resampled when asked (a larger size class of the same data, labelled so).
vtkSmartPointer<vtkImageData> LoadBenchVolume(const std::string& in, double factor, cli::TetBenchSetup& setup)
{
  vtkSmartPointer<vtkImageData> volume = art::LoadVolume(in);
  setup.input = in, setup.resample = factor;
  setup.inputLabel = std::filesystem::path(in).filename().string();
  if (factor != 1.0)
  {
    if (!(factor > 0.0 && factor <= 8.0))
    {
      throw art::Error("--tets-resample must lie in (0, 8]", in);
    }
    vtkNew<vtkImageResample> resample;
    resample->SetInputData(volume);
    resample->SetInterpolationModeToLinear();
    for (int k = 0; k < 3; ++k)
    {
      resample->SetAxisMagnificationFactor(k, factor);
    }
    resample->Update();
    volume = resample->GetOutput();
    char label[64];
    std::snprintf(label, sizeof label, " resampled x%g", factor);
    setup.inputLabel += label;
  }
  volume->GetDimensions(setup.dims);
  setup.voxels = static_cast<long long>(setup.dims[0]) * setup.dims[1] * setup.dims[2];
  return volume;
}

struct MeshEntry
{
  std::string name, series;
  std::unique_ptr<art::TetMesh> mesh;
};

// --tets-series, checked before any work; --tets-no-relocate turns relocated into bisection.
std::vector<std::string> SeriesNames(const cli::Options& o)
{
  std::vector<std::string> out;
  for (std::string s : SplitList(o.Get("tets-series")))
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

// Each --tets-series reduced to the --tets-levels budgets in one run.
void AddReducedSeries(const cli::Options& o, vtkImageData* volume, const std::string& in,
  const art::TransferFunction& tf, std::vector<MeshEntry>& meshes)
{
#ifdef ART_HAVE_Reduction
  std::vector<long long> levels;
  for (const std::string& item : SplitList(o.Get("tets-levels")))
  {
    levels.push_back(std::stoll(item));
  }
  std::sort(levels.begin(), levels.end());
  if (levels.empty())
  {
    return;
  }
  const art::VoxelVolume voxels = art::VolumeFromImage(volume, in);
  for (const std::string& series : SeriesNames(o))
  {
    std::fprintf(stderr, "reducing to %zu budgets (%s) ...\n", levels.size(), series.c_str());
    art::ReducerOptions ro;
    ro.TargetTets = levels.back();
    ro.Levels = levels;
    ro.RelocateVertices = series != "bisection"; // as render reduces
    if (series == "anisotropic")
    {
      ro.Refine = art::ReducerOptions::Refinement::Anisotropic;
    }
    if (!o.Flag("tets-plain-reduction"))
    {
      ro.ScalarOpacity = tf.OpacityPoints();
    }
    const std::string prefix = series == "anisotropic" ? "anisotropic " : "reduced ";
    for (const auto& r : art::TetReducer(ro).Run(voxels))
    {
      meshes.push_back({ prefix + std::to_string(r.NumberOfTets()), series,
        std::make_unique<art::TetMesh>(cli::ToTetMesh(r)) });
    }
  }
#else
  (void)o, (void)volume, (void)in, (void)tf, (void)meshes;
#endif
}

std::vector<MeshEntry> BuildMeshes(const cli::Options& o, vtkImageData* volume, const std::string& in,
  const art::TransferFunction& tf)
{
  std::vector<MeshEntry> meshes;
  AddReducedSeries(o, volume, in, tf, meshes);
  const std::string series = o.Get("tets-meshes-name");
  for (const std::string& file : SplitList(o.Get("tets-meshes")))
  {
    std::fprintf(stderr, "reading %s ...\n", file.c_str());
    auto m = std::make_unique<art::TetMesh>(art::TetMesh::FromVTK(art::LoadMesh(file), {}, nullptr, file));
    meshes.push_back({ series + " " + std::to_string(m->NumberOfTets()), series, std::move(m) });
  }
  if (!o.Flag("tets-no-full"))
  {
    std::fprintf(stderr, "full-resolution tets ...\n");
    meshes.push_back({ "full resolution", "full resolution",
      std::make_unique<art::TetMesh>(art::TetMesh::FromImage(volume, in)) });
  }
  return meshes;
}

struct Scene
{
  const art::Camera& camera;
  vtkCamera* cam;
  vtkVolumeProperty* prop;
  const art::TransferFunction& tf;
  const art::Image& ref;
  std::string dir;
  int W, H, runs;
  bool vtk, mainOnly;
  long long bunykMax;
};

// Every method on one mesh, timed in turn, a frame each per round (TimeInterleaved): this
// machine's speed drifts, and runs of one method after another would put the drift into the ratios.
void TimeMesh(const Scene& sc, const MeshEntry& me, const std::function<void(const Row&)>& report)
{
  const art::TetMesh& m = *me.mesh;
  std::string file = me.name;
  std::replace(file.begin(), file.end(), ' ', '-');
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
  std::vector<Variant> variants{ { "ours exact, ERT 0.99", art::RenderSettings::Rule::Exact, 0.99 },
    { "ours exact, no ERT", art::RenderSettings::Rule::Exact, 2.0 },
    { "ours trapezoid, ERT 0.99", art::RenderSettings::Rule::Trapezoid, 0.99 },
    { "ours exact, ERT 0.99, every tet", art::RenderSettings::Rule::Exact, 0.99, false } };
  variants.resize(sc.mainOnly ? 1 : variants.size());
  for (const Variant& v : variants)
  {
    art::RenderSettings s;
    s.tf = sc.tf;
    s.rule = v.rule;
    s.earlyTermination = v.ert;
    s.skipEmpty = v.skip; // "every tet": without empty-space skipping
    ours.push_back(std::make_unique<Ours>());
    Ours* o = ours.back().get();
    o->caster = std::make_unique<art::TetRayCaster>(m, s);
    const bool keep = v.ert < 1 && v.rule == art::RenderSettings::Rule::Exact && v.skip;
    methods.push_back({ row(v.name),
      [&sc, o] {
        o->st = o->caster->Render(sc.camera, o->img);
        return o->st.seconds;
      },
      [&sc, o, keep, file](Row& r) {
        r.err = art::CompareImages(OverBlack(o->img), sc.ref);
        r.tetsPerRay = o->st.counters.PerRay(o->st.counters.tetsCrossed);
        r.nsPerTet = o->st.counters.tetsCrossed
          ? r.seconds.median * 1e9 * art::GetThreadCount() / o->st.counters.tetsCrossed : 0;
        if (keep)
        {
          art::WriteImage(OverBlack(o->img), sc.dir + "/tets-ours-" + file + ".png");
        }
      } });
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid;
  vtkNew<vtkUnstructuredGridVolumeRayCastMapper> bunyk;
  vtkNew<vtkTetRayCastMapper> mapper;
  std::unique_ptr<VTKWindow> bunykWin, mapperWin;
  if (sc.vtk && static_cast<long long>(m.NumberOfTets()) <= sc.bunykMax)
  {
    grid = ToGrid(m);
    bunyk->SetInputData(grid);
    bunyk->SetAutoAdjustSampleDistances(0);
    bunyk->SetImageSampleDistance(1.0f);
    bunykWin = std::make_unique<VTKWindow>(bunyk, sc.prop, sc.cam, sc.W, sc.H);
    methods.push_back({ row("VTK Bunyk (UG ray cast)"), [&] { return bunykWin->Frame(); },
      [&](Row& r) {
        const art::Image img = bunykWin->Read();
        r.err = art::CompareImages(img, sc.ref);
        art::WriteImage(img, sc.dir + "/tets-bunyk-" + file + ".png");
      } });
    // Ours the same way, mapper against mapper: window draw and read-back included.
    mapper->SetInputData(grid);
    mapper->SetAutoAdjustSampleDistances(0); // one ray a pixel, as Bunyk's
    mapperWin = std::make_unique<VTKWindow>(mapper, sc.prop, sc.cam, sc.W, sc.H);
    methods.push_back({ row("ours mapper in a window"), [&] { return mapperWin->Frame(); },
      [&](Row& r) { r.err = art::CompareImages(mapperWin->Read(), sc.ref); } });
  }
  std::vector<std::function<double()>> frames;
  for (const Method& method : methods)
  {
    frames.push_back(method.frame);
  }
  const std::vector<cli::BenchStats> times = cli::TimeInterleaved(sc.runs, frames);
  for (std::size_t i = 0; i < methods.size(); ++i)
  {
    methods[i].row.seconds = times[i];
    methods[i].finish(methods[i].row);
    report(methods[i].row);
  }
}

Row TimeFixedPoint(const Scene& sc, vtkImageData* volume, long long voxels)
{
  double spacing[3];
  volume->GetSpacing(spacing);
  // VTK 9.1's FixedPoint ignores an image's direction matrix (a NIfTI's [-1 0 0; 0 -1 0; 0 0 1]
  // drew the brain off screen): it gets the voxels at the origin, axis-aligned, and the volume the
  // direction and origin as its matrix, so it draws where the reference does.
  vtkNew<vtkImageData> aligned;
  aligned->ShallowCopy(volume);
  aligned->SetOrigin(0, 0, 0);
  aligned->SetDirectionMatrix(1, 0, 0, 0, 1, 0, 0, 0, 1);
  vtkNew<vtkMatrix4x4> place;
  const double* o = volume->GetOrigin();
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      place->SetElement(r, c, volume->GetDirectionMatrix()->GetElement(r, c));
    }
    place->SetElement(r, 3, o[r]);
  }
  vtkNew<vtkFixedPointVolumeRayCastMapper> fp;
  fp->SetInputData(aligned);
  fp->SetAutoAdjustSampleDistances(0);
  fp->SetImageSampleDistance(1.0f);
  fp->SetSampleDistance(0.5 * std::min(spacing[0], std::min(spacing[1], spacing[2])));
  VTKWindow win(fp, sc.prop, sc.cam, sc.W, sc.H);
  win.Place(place);
  Row r{ "VTK FixedPoint (voxels)", "voxels", "voxels", 0, voxels };
  r.seconds = cli::TimeRuns(sc.runs, [&] { return win.Frame(); });
  const art::Image img = win.Read();
  r.err = art::CompareImages(img, sc.ref);
  art::WriteImage(img, sc.dir + "/tets-fixedpoint.png");
  return r;
}

int Run(const cli::Options& o)
{
  SeriesNames(o); // a usage error before any work
  cli::TetBenchSetup setup;
  const std::string in = o.Get("tets-input");
  const std::string dir = o.Get("results");
  setup.runs = static_cast<int>(std::max(1LL, o.GetInt("runs")));
  o.GetSize("tets-size", setup.width, setup.height);
  std::filesystem::create_directories(dir);
  const bool vtk = !o.Flag("tets-no-vtk") && std::getenv("DISPLAY");
  if (!o.Flag("tets-no-vtk") && !vtk)
  {
    std::fprintf(stderr, "bench tets: no DISPLAY, VTK's mappers skipped (run under xvfb-run -a)\n");
  }

  vtkSmartPointer<vtkImageData> volume = LoadBenchVolume(in, o.GetDouble("tets-resample"), setup);
  double range[2], b[6];
  volume->GetPointData()->GetScalars()->GetRange(range);
  volume->GetBounds(b);
  setup.transferFunction = o.Get("tets-tf");
  const std::string& tfName = setup.transferFunction;
  const art::TransferFunction tf = std::filesystem::exists(tfName) ? art::TransferFunction::FromFile(tfName)
    : art::TransferFunction::PresetFor(tfName, volume, range[0], range[1]);
  setup.reduction = std::string(o.Flag("tets-plain-reduction") ? "plain L2 reduction" : "reduction weighted by its opacity") +
    (o.Flag("tets-no-relocate") ? "" : ", vertices relocated");
  vtkNew<vtkCamera> cam;
  cam->SetPosition(0, -1, 0);
  cam->SetFocalPoint(0, 0, 0);
  cam->SetViewUp(0, 0, 1);
  art::Camera::Frame(cam, art::Box3::FromBounds(b), 30, 10, 1.0);
  const art::Camera camera = art::Camera::FromVTK(cam, setup.width, setup.height);
  vtkNew<vtkVolumeProperty> prop;
  tf.ToVTK(prop);

  // The reference: voxels, trilinear, 2 samples per voxel, exact steps, no early termination.
  std::fprintf(stderr, "reference (voxel caster) ...\n");
  art::Image refRaw;
  const auto refCaster = art::VoxelReferenceCaster::FromVTK(volume, tf, in);
  setup.referenceSeconds = refCaster.Render(camera, refRaw).seconds;
  const art::Image ref = OverBlack(refRaw);
  art::WriteImage(ref, dir + "/tets-reference.png");

  const Scene sc{ camera, cam, prop, tf, ref, dir, setup.width, setup.height, setup.runs, vtk,
    o.Flag("tets-main-only"), o.GetInt("tets-bunyk-max") };
  std::vector<Row> rows;
  auto report = [&](const Row& r) {
    std::fprintf(stderr, "  %-22s %-18s %9lld tets  %8.3f s [%.3f-%.3f]  PSNR %6.2f dB  SSIM %.4f\n",
      r.method.c_str(), r.mesh.c_str(), r.tets, r.seconds.median, r.seconds.lo, r.seconds.hi, r.err.psnr, r.err.ssim);
    rows.push_back(r);
  };
  for (const MeshEntry& me : BuildMeshes(o, volume, in, tf))
  {
    TimeMesh(sc, me, report);
  }
  if (vtk)
  {
    report(TimeFixedPoint(sc, volume, setup.voxels));
  }

  const std::string stem = dir + "/tets";
  std::printf("%s", cli::WriteTetBenchResults(stem, setup, rows).c_str());
  cli::FinishResults(cli::ThisRun().source + "/tests/benchmarks/tets_chart.py", stem);
  return cli::ExitOk;
}

cli::BenchRegistrar reg({ "tets",
  "a volume's reduction series cast cell by cell vs VTK's Bunyk and FixedPoint mappers (time vs PSNR)", Declare,
  Run });
} // namespace
