// `adaptivert bench triangles`: the TriangleGrid accelerators against Embree 3 (rtcIntersect1,
// rtcOccluded1, all hits through an intersection filter) and VTK 9.1's vtkStaticCellLocator,
// vtkModifiedBSPTree and vtkOBBTree, on the same primary and shadow rays; plus the paper's
// parameter tables (Dmitriev: R[thr,N] and O[thr,w]); and FindClosestPoint through
// vtkTriangleGridLocator against vtkStaticCellLocator and vtkCellLocator on the same points, with
// the distance error against brute force (TriangleBenchClosestPoint.cxx; Embree's side in
// TriangleBenchEmbree.cxx). Writes JSON, a markdown table and a chart.
#ifdef ART_HAVE_TriangleGrid
#include "Accelerator.h"
#include "benchmarks/Bench.h"
#include "benchmarks/BenchUtil.h"
#include "Camera.h"
#include "cli/Command.h"
#include "DataLoader.h"
#include "Error.h"
#include "cli/Json.h"
#include "ParallelTiles.h"
#include "benchmarks/TriangleBench.h"

#include "vtkTriangleGridLocator.h"
#include "cli/ResourcePath.h"

#include <vtkCamera.h>
#include <vtkCellLocator.h>
#include <vtkGenericCell.h>
#ifdef ART_HAVE_VTK_FLOWPATHS
#include <vtkModifiedBSPTree.h>
#endif
#include <vtkNew.h>
#include <vtkOBBTree.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <thread>

namespace
{
using namespace trianglebench;

// Seconds -> Mrays/s (the median of rates is the rate of the median time; min-max swap).
cli::BenchStats Rate(const cli::BenchStats& s, size_t rays)
{
  const double r = double(rays) / 1e6;
  return { r / s.median, r / s.hi, r / s.lo };
}

/// One engine's figures on one scene.
struct Row
{
  std::string scene, engine, group; // group: ours, anchor, table
  double buildMs = 0, bytesPerTri = -1;
  cli::BenchStats prim1, prim2, shad1, shad2, all1;
  bool havePrim2 = false, haveShadow = false, haveAll = false;
  double voxelsPerRay = -1, trisPerRay = -1;
  size_t rays = 0;     // primary rays timed
  std::string note;
  double agree = -1;   // % of primary rays with the same hit/miss and distance (1e-4) as Embree
};

// Closest-hit distances of `rays` (rays[i] by index stride), on the current thread count.
void RunClosest(const Engine& e, const std::vector<art::Ray>& rays, size_t stride, std::vector<double>* t)
{
  const long long n = static_cast<long long>((rays.size() + stride - 1) / stride);
  if (t)
  {
    t->assign(static_cast<size_t>(n), -1.0);
  }
  art::ForEachRange(n, 256, [&](long long b, long long en, art::Counters&) {
    for (long long i = b; i < en; ++i)
    {
      double th = -1;
      const bool hit = e.closest(rays[static_cast<size_t>(i) * stride], th);
      if (t)
      {
        (*t)[static_cast<size_t>(i)] = hit ? th : -1.0;
      }
    }
  });
}

void RunAny(const Engine& e, const std::vector<art::Ray>& rays)
{
  std::atomic<long long> blocked{ 0 };
  art::ForEachRange(static_cast<long long>(rays.size()), 256, [&](long long b, long long en, art::Counters&) {
    long long k = 0;
    for (long long i = b; i < en; ++i)
    {
      k += e.any(rays[static_cast<size_t>(i)]) ? 1 : 0;
    }
    blocked += k;
  });
}

void RunAll(const Engine& e, const std::vector<art::Ray>& rays)
{
  art::ForEachRange(static_cast<long long>(rays.size()), 256, [&](long long b, long long en, art::Counters&) {
    for (long long i = b; i < en; ++i)
    {
      e.all(rays[static_cast<size_t>(i)]);
    }
  });
}

// An interior viewpoint for enclosed scenes (levels): the lattice point whose 26 probe rays hit (all
// but a few: open sky), mostly on one side of the walls,
// and whose mean free distance is largest; lights at the next best points. Framed outside otherwise.
void MakeRays(Scene& s, int width, int height, int nLights)
{
  art::AcceleratorOptions ro;
  auto acc = art::MakeAccelerator(s.store, ro);
  const art::Box3 b = s.store->Bounds();
  struct Cand
  {
    art::Vec3 p;
    double score;
    art::Vec3 look;
  };
  std::vector<Cand> cands;
  const int K = 11;
  for (int i = 1; i <= K; ++i)
  {
    for (int j = 1; j <= K; ++j)
    {
      for (int k = 1; k <= K; ++k)
      {
        const art::Vec3 p(b.lo.x + b.Size().x * i / (K + 1), b.lo.y + b.Size().y * j / (K + 1),
          b.lo.z + b.Size().z * k / (K + 1));
        double sum = 0, best = -1;
        art::Vec3 look;
        int misses = 0; // open sky: a level may have no ceiling over some of its rooms
        bool enclosed = true;
        int front = 0;
        for (int dx = -1; dx <= 1 && enclosed; ++dx)
        {
          for (int dy = -1; dy <= 1 && enclosed; ++dy)
          {
            for (int dz = -1; dz <= 1 && enclosed; ++dz)
            {
              if (!dx && !dy && !dz)
              {
                continue;
              }
              art::Ray r;
              r.org = p;
              r.dir = art::Normalize(art::Vec3(dx, dy, dz));
              art::Hit h;
              art::Counters c;
              const bool hit = acc->Closest(r, h, c);
              misses += hit ? 0 : 1;
              enclosed = misses <= 5;
              sum += hit ? h.t : 0.0;
              if (hit)
              {
                const size_t rec = static_cast<size_t>(h.record);
                const art::Vec3 n = art::Cross(s.store->Vertex(rec, 1) - s.store->Vertex(rec, 0),
                  s.store->Vertex(rec, 2) - s.store->Vertex(rec, 0));
                front += art::Dot(n, r.dir) < 0;
              }
              if (dz == 0 && h.t > best)
              {
                best = h.t;
                look = r.dir;
              }
            }
          }
        }
        // Most probes should meet the same side of the walls (a room, not the inside of a solid).
        if (enclosed && (front >= 18 - misses || front <= 8))
        {
          cands.push_back({ p, sum / 26, look });
        }
      }
    }
  }
  std::sort(cands.begin(), cands.end(), [](const Cand& a, const Cand& c) { return a.score > c.score; });
  vtkNew<vtkCamera> vcam;
  std::vector<art::Vec3> lights;
  // Architectural scenes (many coplanar triangles, like game levels) are seen from inside; objects
  // (nearly every triangle its own plane, like the bunny) are framed from outside.
  const bool architectural = double(s.store->PlaneCount()) < 0.8 * double(s.store->Size());
  if (architectural && !cands.empty() && cands[0].score > 0.01 * b.Diagonal())
  {
    const Cand& c = cands[0];
    vcam->SetPosition(c.p.x, c.p.y, c.p.z);
    vcam->SetFocalPoint(c.p.x + c.look.x, c.p.y + c.look.y, c.p.z + c.look.z);
    vcam->SetViewUp(0, 0, 1);
    vcam->SetViewAngle(70);
    lights.push_back(c.p + art::Vec3(0, 0, 0.02 * b.Diagonal()));
    for (size_t i = 1; i < cands.size() && int(lights.size()) < nLights; ++i)
    {
      lights.push_back(cands[i].p);
    }
    char buf[160];
    std::snprintf(buf, sizeof buf, "inside at (%.0f, %.0f, %.0f), 70 deg", c.p.x, c.p.y, c.p.z);
    s.view = buf;
  }
  else
  {
    vcam->SetPosition(0, -1, 0);
    vcam->SetFocalPoint(0, 0, 0);
    vcam->SetViewUp(0, 0, 1);
    art::Camera::Frame(vcam, b);
    double pos[3];
    vcam->GetPosition(pos);
    const art::Vec3 eye(pos);
    const double d = b.Diagonal();
    const art::Vec3 offs[] = { { 0, 0, 0.6 }, { 0.6, 0, 0.3 }, { -0.6, 0.2, 0.4 }, { 0.3, -0.3, 0.8 } };
    for (int i = 0; i < nLights; ++i)
    {
      lights.push_back(eye + offs[i % 4] * d);
    }
    s.view = "framed from -y";
  }
  const art::Camera cam = art::Camera::FromVTK(vcam, width, height);
  s.primary.resize(size_t(width) * height);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      s.primary[size_t(y) * width + x] = cam.Generate(x, y);
    }
  }
  // Shadow rays from every visible point to every light, as the surface tracer casts them.
  std::vector<art::Hit> hits;
  acc->ClosestBatch(s.primary, hits);
  const double eps = 1e-5 * b.Diagonal();
  s.shadow.clear();
  for (size_t i = 0; i < hits.size(); ++i)
  {
    if (hits[i].record < 0)
    {
      continue;
    }
    const size_t rec = static_cast<size_t>(hits[i].record);
    art::Vec3 ng = art::Normalize(art::Cross(s.store->Vertex(rec, 1) - s.store->Vertex(rec, 0),
      s.store->Vertex(rec, 2) - s.store->Vertex(rec, 0)));
    if (art::Dot(ng, s.primary[i].dir) > 0)
    {
      ng = -ng;
    }
    const art::Vec3 p = s.primary[i].At(hits[i].t) + ng * eps;
    for (const art::Vec3& L : lights)
    {
      art::Ray r;
      r.org = p;
      r.dir = L - p;
      r.tmax = 1.0;
      s.shadow.push_back(r);
    }
  }
}

std::string Fmt(double v, int prec = 2)
{
  if (v < 0)
  {
    return "n/a";
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", prec, v);
  return buf;
}

std::string FmtStats(const cli::BenchStats& s)
{
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.3g (%.3g-%.3g)", s.median, s.lo, s.hi);
  return buf;
}

cli::Json StatsJson(const cli::BenchStats& s)
{
  cli::Json j;
  j.Set("median", s.median).Set("min", s.lo).Set("max", s.hi);
  return j;
}

Engine OurEngine(const art::Accelerator& acc, art::Counters* work)
{
  Engine e;
  e.closest = [&acc](const art::Ray& r, double& t) {
    art::Counters c;
    art::Hit h;
    const bool hit = acc.Closest(r, h, c);
    t = h.t;
    return hit;
  };
  e.any = [&acc](const art::Ray& r) {
    art::Counters c;
    return acc.Any(r, c);
  };
  e.all = [&acc](const art::Ray& r) {
    thread_local std::vector<art::Hit> hits;
    art::Counters c;
    acc.All(r, hits, c);
    return hits.size();
  };
  (void)work;
  return e;
}

// Work per ray (voxels visited, triangles tested) over primary and shadow rays together.
void Work(const art::Accelerator& acc, const Scene& s, Row& row)
{
  art::Counters c = art::ForEachRange(static_cast<long long>(s.primary.size()), 1024,
    [&](long long b, long long e, art::Counters& cc) {
      for (long long i = b; i < e; ++i)
      {
        art::Hit h;
        acc.Closest(s.primary[static_cast<size_t>(i)], h, cc);
      }
    });
  c += art::ForEachRange(static_cast<long long>(s.shadow.size()), 1024, [&](long long b, long long e, art::Counters& cc) {
    for (long long i = b; i < e; ++i)
    {
      acc.Any(s.shadow[static_cast<size_t>(i)], cc);
    }
  });
  row.voxelsPerRay = c.PerRay(c.voxelsVisited);
  row.trisPerRay = c.PerRay(c.trianglesTested);
}


// A VTK cell locator's IntersectWithLine as a closest-hit query (and as the only any-hit it has).
template <class Locator>
Engine VTKEngine(Locator* loc, double far)
{
  Engine e;
  e.closest = [loc, far](const art::Ray& r, double& t) {
    thread_local vtkNew<vtkGenericCell> cell;
    const double len = art::Length(r.dir);
    const double tmax = std::isinf(r.tmax) ? far / len : r.tmax;
    const art::Vec3 a = r.At(r.tmin), b = r.At(tmax);
    double p1[3] = { a.x, a.y, a.z }, p2[3] = { b.x, b.y, b.z }, x[3], pc[3], tt = 0;
    int sub = 0;
    vtkIdType id = -1;
    const int hit = loc->IntersectWithLine(p1, p2, 0.0, tt, x, pc, sub, id, cell);
    t = r.tmin + tt * (tmax - r.tmin);
    return hit != 0;
  };
  e.any = [e](const art::Ray& r) {
    double t;
    return e.closest(r, t);
  };
  return e;
}

void Declare(cli::Options& o)
{
  // The larger scenes: where data/fetch puts them (data/full), else the development copy beside
  // the source tree (../shared/data); named in data/full when neither holds them, so that the
  // "skipped" line says where fetch would put them.
  auto scene = [](const std::string& name) {
    const std::string full = std::string(ART_DATA_DIR) + "/full/" + name;
    const std::string shared = std::string(ART_DATA_DIR) + "/../../shared/data/" + name;
    return std::filesystem::exists(full) || !std::filesystem::exists(shared) ? full : shared;
  };
  o.Add("tri-scenes", 0, "FILE,..",
    "triangles: scenes (data/fetch gets the bunny, hydronex2, oa_minia and the CT skull surface, surface_0.vtp)",
    cli::DataDir() + "/am_underworks.ply," + scene("bunny.ply") + "," + scene("hydronex2.ply") + "," +
      scene("oa_minia.ply") + "," + scene("surface_0.vtp"));
  o.Add("tri-size", 0, "WxH", "triangles: primary rays per scene", "800x600");
  o.Add("tri-lights", 0, "N", "triangles: point lights (shadow rays per visible point)", "3");
  o.Add("tri-vtk-rays", 0, "N", "triangles: primary rays given to each VTK locator (a strided subset)", "20000");
  o.Add("tri-no-tables", 0, "", "triangles: skip the paper's parameter tables");
  o.Add("tri-no-vtk", 0, "", "triangles: skip VTK's locators");
  o.Add("tri-points", 0, "N", "triangles: closest-point queries per scene (a third inside the box, near the "
    "surface, far away)", "30000");
  o.Add("tri-no-closest-point", 0, "", "triangles: skip the closest-point table");
}

int Run(const cli::Options& o)
{
  const std::string dir = o.Get("results");
  std::filesystem::create_directories(dir);
  const int runs = std::max(1, static_cast<int>(o.GetInt("runs")));
  int width = 800, height = 600;
  o.GetSize("tri-size", width, height);
  const int nLights = std::max(1, static_cast<int>(o.GetInt("tri-lights")));
  const size_t vtkRays = static_cast<size_t>(std::max(100LL, o.GetInt("tri-vtk-rays")));
  const int userThreads = art::GetThreadCount();
  std::vector<Row> rows;
  std::vector<PointRow> pointRows;
  const size_t nPoints = static_cast<size_t>(std::max(300LL, o.GetInt("tri-points")));
  std::vector<Scene> scenes;
  {
    std::stringstream ss(o.Get("tri-scenes"));
    std::string p;
    while (std::getline(ss, p, ','))
    {
      if (p.empty())
      {
        continue;
      }
      if (!std::filesystem::exists(p))
      {
        std::fprintf(stderr, "adaptivert: %s: no such file, skipped\n", p.c_str());
        continue;
      }
      Scene s;
      s.path = p;
      s.name = std::filesystem::path(p).stem().string();
      s.pd = art::LoadSurface(p);
      s.store = std::make_shared<art::TriangleStore>(art::TriangleStore::FromPolyData(s.pd));
      scenes.push_back(std::move(s));
    }
  }
  if (scenes.empty())
  {
    throw art::Error("no scene to benchmark", o.Get("tri-scenes"));
  }

  for (Scene& s : scenes)
  {
    art::SetThreadCount(userThreads);
    MakeRays(s, width, height, nLights);
    std::fprintf(stderr, "%s: %zu triangles, %zu primary + %zu shadow rays, camera %s\n", s.name.c_str(),
      s.store->Size(), s.primary.size(), s.shadow.size(), s.view.c_str());
    const double ntri = double(s.store->Size());
    std::vector<double> embreeT;

    // Anchors first: Embree on every ray, 1 and 2 threads.
#ifdef ART_HAVE_EMBREE
    {
      Row r;
      r.scene = s.name;
      r.engine = "Embree 3 rtcIntersect1/rtcOccluded1";
      r.group = "anchor";
      std::unique_ptr<EmbreeScene> es;
      const cli::BenchStats b = Time(runs, [&] { es.reset(); es.reset(new EmbreeScene(*s.store)); });
      r.buildMs = b.median * 1e3;
      r.bytesPerTri = double(es->bytes) / ntri;
      const Engine e = es->Queries();
      r.rays = s.primary.size();
      art::SetThreadCount(1);
      r.prim1 = Rate(Time(runs, [&] { RunClosest(e, s.primary, 1, nullptr); }), s.primary.size());
      r.shad1 = Rate(Time(runs, [&] { RunAny(e, s.shadow); }), s.shadow.size());
      r.all1 = Rate(Time(runs, [&] { RunAll(e, s.primary); }), s.primary.size());
      art::SetThreadCount(2);
      r.prim2 = Rate(Time(runs, [&] { RunClosest(e, s.primary, 1, nullptr); }), s.primary.size());
      r.shad2 = Rate(Time(runs, [&] { RunAny(e, s.shadow); }), s.shadow.size());
      r.havePrim2 = r.haveShadow = r.haveAll = true;
      RunClosest(e, s.primary, 1, &embreeT);
      r.note = "all hits through an intersection filter";
      rows.push_back(r);
    }
#endif
    // VTK's locators: one thread, a strided subset of the primary rays (they are slow).
    if (!o.Flag("tri-no-vtk"))
    {
      const size_t baseStride = std::max<size_t>(1, s.primary.size() / vtkRays);
      const double far = 4 * s.store->Bounds().Diagonal() + 1e3;
      auto vtkRow = [&](const char* name, auto* loc) {
        Row r;
        r.scene = s.name;
        r.engine = name;
        r.group = "anchor";
        loc->SetDataSet(s.pd);
        loc->LazyEvaluationOff();
        const cli::BenchStats b = Time(std::min(runs, 3), [&] { loc->FreeSearchStructure(); loc->Modified(); loc->BuildLocator(); });
        r.buildMs = b.median * 1e3;
        const Engine e = VTKEngine(loc, far);
        art::SetThreadCount(1);
        // As many rays as fit in about half a second per run (some VTK locators are very slow).
        size_t stride = baseStride;
        {
          const size_t probeStride = std::max<size_t>(1, s.primary.size() / 50);
          const auto t0 = Clock::now();
          RunClosest(e, s.primary, probeStride, nullptr);
          const double perRay = Since(t0) / double((s.primary.size() + probeStride - 1) / probeStride);
          const size_t fit = static_cast<size_t>(0.5 / std::max(perRay, 1e-9));
          stride = std::max(stride, s.primary.size() / std::max<size_t>(fit, 50));
        }
        r.rays = (s.primary.size() + stride - 1) / stride;
        r.prim1 = Rate(Time(std::min(runs, 3), [&] { RunClosest(e, s.primary, stride, nullptr); }), r.rays);
        char buf[128];
        std::snprintf(buf, sizeof buf, "1 thread, %zu of the primary rays", r.rays);
        r.note = buf;
        rows.push_back(r);
      };
      vtkNew<vtkStaticCellLocator> st;
      vtkRow("VTK vtkStaticCellLocator", st.GetPointer());
#ifdef ART_HAVE_VTK_FLOWPATHS
      vtkNew<vtkModifiedBSPTree> bsp;
      vtkRow("VTK vtkModifiedBSPTree", bsp.GetPointer());
#endif
      vtkNew<vtkOBBTree> obb;
      vtkRow("VTK vtkOBBTree", obb.GetPointer());
    }
    // Ours: the three accelerators with defaults; then the paper's tables.
    struct Config
    {
      std::string group;
      art::AcceleratorOptions o;
    };
    std::vector<Config> configs;
    for (auto k : { art::AcceleratorKind::UniformGrid, art::AcceleratorKind::RecursiveGrid, art::AcceleratorKind::Octree })
    {
      art::AcceleratorOptions ao;
      ao.kind = k;
      configs.push_back({ "ours", ao });
    }
    if (!o.Flag("tri-no-tables"))
    {
      for (int thr : { 10, 16, 22, 31 })
      {
        art::AcceleratorOptions ao;
        ao.voxelThreshold = thr;
        ao.subdivisions = 4;
        configs.push_back({ "table", ao });
      }
      {
        art::AcceleratorOptions ao;
        ao.voxelThreshold = 16;
        ao.subdivisions = 4;
        ao.topLevelGrid = false;
        configs.push_back({ "table", ao });
      }
      for (int thr : { 4, 8, 16 })
      {
        art::AcceleratorOptions ao;
        ao.voxelThreshold = thr;
        ao.subdivisions = 2;
        configs.push_back({ "table", ao });
      }
      for (int thr : { 2, 4, 6, 8 })
      {
        art::AcceleratorOptions ao;
        ao.kind = art::AcceleratorKind::Octree;
        ao.voxelThreshold = thr;
        ao.planeWeight = 15;
        configs.push_back({ "table", ao });
      }
    }
    for (const Config& cfg : configs)
    {
      art::SetThreadCount(userThreads);
      Row r;
      r.scene = s.name;
      r.group = cfg.group;
      std::unique_ptr<art::Accelerator> acc;
      const cli::BenchStats b = Time(runs, [&] { acc.reset(); acc = art::MakeAccelerator(s.store, cfg.o); });
      r.engine = acc->Name();
      r.buildMs = b.median * 1e3;
      r.bytesPerTri = double(acc->MemoryBytes() + s.store->MemoryBytes()) / ntri;
      r.rays = s.primary.size();
      const Engine e = OurEngine(*acc, nullptr);
      art::SetThreadCount(1);
      r.prim1 = Rate(Time(runs, [&] { RunClosest(e, s.primary, 1, nullptr); }), s.primary.size());
      r.shad1 = Rate(Time(runs, [&] { RunAny(e, s.shadow); }), s.shadow.size());
      r.haveShadow = true;
      if (cfg.group == "ours")
      {
        r.all1 = Rate(Time(runs, [&] { RunAll(e, s.primary); }), s.primary.size());
        r.haveAll = true;
        art::SetThreadCount(2);
        r.prim2 = Rate(Time(runs, [&] { RunClosest(e, s.primary, 1, nullptr); }), s.primary.size());
        r.shad2 = Rate(Time(runs, [&] { RunAny(e, s.shadow); }), s.shadow.size());
        r.havePrim2 = true;
      }
      Work(*acc, s, r);
      if (!embreeT.empty())
      {
        std::vector<double> t;
        RunClosest(e, s.primary, 1, &t);
        size_t same = 0;
        for (size_t i = 0; i < t.size(); ++i)
        {
          const bool h1 = t[i] >= 0, h2 = embreeT[i] >= 0;
          same += h1 == h2 && (!h1 || std::fabs(t[i] - embreeT[i]) <= 1e-4 * std::max(t[i], embreeT[i]));
        }
        r.agree = 100.0 * double(same) / double(t.size());
      }
      rows.push_back(r);
      std::fprintf(stderr, "  %-40s build %8.1f ms  %6.1f B/tri  closest %6.2f Mrays/s  shadow %6.2f Mrays/s\n",
        r.engine.c_str(), r.buildMs, r.bytesPerTri, r.prim1.median, r.shad1.median);
    }
    if (!o.Flag("tri-no-closest-point"))
    {
      BenchClosestPoint(s, nPoints, runs, pointRows);
    }
  }
  art::SetThreadCount(userThreads);

  // Ratios: our recursive grid (the default) against Embree and vtkStaticCellLocator.
  auto find = [&](const std::string& scene, const std::string& prefix, const std::string& group) -> const Row* {
    for (const Row& r : rows)
    {
      if (r.scene == scene && r.group == group && r.engine.rfind(prefix, 0) == 0)
      {
        return &r;
      }
    }
    return nullptr;
  };
  std::vector<cli::Json> jrows, jratios;
  for (const Row& r : rows)
  {
    cli::Json j;
    j.Set("scene", r.scene).Set("engine", r.engine).Set("group", r.group).Set("buildMs", r.buildMs);
    j.Set("bytesPerTriangle", r.bytesPerTri).Set("primaryRays", static_cast<long long>(r.rays));
    j.Set("closest1", StatsJson(r.prim1));
    if (r.havePrim2)
    {
      j.Set("closest2", StatsJson(r.prim2)).Set("shadow2", StatsJson(r.shad2));
    }
    if (r.haveShadow)
    {
      j.Set("shadow1", StatsJson(r.shad1));
    }
    if (r.haveAll)
    {
      j.Set("allHits1", StatsJson(r.all1));
    }
    j.Set("voxelsPerRay", r.voxelsPerRay).Set("trianglesPerRay", r.trisPerRay).Set("agreeWithEmbreePercent", r.agree);
    j.Set("note", r.note);
    jrows.push_back(j);
  }
  std::string ratioText;
  for (const Scene& s : scenes)
  {
    const Row* ours = find(s.name, "R[", "ours");
    const Row* emb = find(s.name, "Embree", "anchor");
    const Row* vst = find(s.name, "VTK vtkStaticCellLocator", "anchor");
    cli::Json j;
    j.Set("scene", s.name).Set("triangles", static_cast<long long>(s.store->Size()));
    j.Set("primaryRays", static_cast<long long>(s.primary.size())).Set("shadowRays", static_cast<long long>(s.shadow.size()));
    j.Set("view", s.view);
    char line[512];
    if (ours && emb)
    {
      j.Set("closestVsEmbree1", ours->prim1.median / emb->prim1.median);
      j.Set("closestVsEmbree2", ours->prim2.median / emb->prim2.median);
      j.Set("shadowVsEmbree1", ours->shad1.median / emb->shad1.median);
      j.Set("allHitsVsEmbree1", ours->all1.median / emb->all1.median);
    }
    if (ours && vst)
    {
      j.Set("closestVsVtkStatic1", ours->prim1.median / vst->prim1.median);
    }
    if (ours)
    {
      j.Set("bytesPerTriangle", ours->bytesPerTri);
    }
    if (ours && emb)
    {
      j.Set("buildVsEmbree", ours->buildMs / emb->buildMs);
    }
    std::snprintf(line, sizeof line,
      "| %s | %zu | %s | %s | %s | %s | %s | %s | %s |\n", s.name.c_str(), s.store->Size(),
      ours && emb ? Fmt(ours->prim1.median / emb->prim1.median).c_str() : "n/a",
      ours && emb ? Fmt(ours->prim2.median / emb->prim2.median).c_str() : "n/a",
      ours && emb ? Fmt(ours->shad1.median / emb->shad1.median).c_str() : "n/a",
      ours && emb ? Fmt(ours->all1.median / emb->all1.median).c_str() : "n/a",
      ours && vst ? Fmt(ours->prim1.median / vst->prim1.median, 1).c_str() : "n/a",
      ours ? Fmt(ours->bytesPerTri, 0).c_str() : "n/a",
      ours && emb ? Fmt(ours->buildMs / emb->buildMs).c_str() : "n/a");
    ratioText += line;
    jratios.push_back(j);
  }

  const cli::RunInfo run = cli::ThisRun();
  const std::string &src = run.source, &commit = run.commit, &cpu = run.cpu, &date = run.date;
  cli::Json top;
  top.Set("benchmark", "triangles").Set("date", date).Set("commit", commit).Set("cpu", cpu);
  top.Set("cores", static_cast<long long>(std::thread::hardware_concurrency()));
  top.Set("runs", runs).Set("width", width).Set("height", height).Set("lights", nLights);
#ifdef ART_HAVE_EMBREE
  top.Set("embree", true);
#else
  top.Set("embree", false);
#endif
  // Closest point: ours (default R) against VTK's two locators, same points.
  std::vector<cli::Json> jpoints;
  std::string pointText;
  for (const PointRow& r : pointRows)
  {
    auto rateOf = [&](const std::string& engine) {
      for (const PointRow& q : pointRows)
      {
        if (q.scene == r.scene && q.engine == engine)
        {
          return q.rate.median;
        }
      }
      return -1.0;
    };
    const double vs = rateOf("VTK vtkStaticCellLocator"), vc = rateOf("VTK vtkCellLocator");
    cli::Json j;
    j.Set("scene", r.scene).Set("engine", r.engine).Set("buildMs", r.buildMs).Set("queriesPerSecond", StatsJson(r.rate));
    j.Set("points", static_cast<long long>(r.points)).Set("maxRelErrorVsBruteForce", r.maxRelError);
    j.Set("referencePoints", static_cast<long long>(r.refPoints)).Set("sameCellAsBruteForce", static_cast<long long>(r.sameCell));
    j.Set("vsVtkStatic", vs > 0 ? r.rate.median / vs : -1.0).Set("vsVtkCellLocator", vc > 0 ? r.rate.median / vc : -1.0);
    jpoints.push_back(j);
    char err[32];
    std::snprintf(err, sizeof err, "%.1e", r.maxRelError);
    pointText += "| " + r.scene + " | " + r.engine + " | " + Fmt(r.buildMs, 1) + " | " + FmtStats(r.rate) + " | " +
      std::to_string(r.points) + " | " + err + " | " + std::to_string(r.sameCell) + " / " + std::to_string(r.refPoints) +
      " | " + (vs > 0 ? Fmt(r.rate.median / vs, 1) : "n/a") + " | " + (vc > 0 ? Fmt(r.rate.median / vc, 1) : "n/a") +
      " |\n";
  }
  const std::string pointHead =
    "## Closest point: FindClosestPoint, 1 thread, same points\n\n" + std::to_string(nPoints) +
    " query points per scene: a third uniform in the box grown by 5%, a third within 1% of the diagonal of the "
    "surface, a third 1-10 diagonals away. Error: max |d - d_brute| / d_brute against our brute force (every "
    "triangle, exact in double) on the reference points; same cell: equal cell ids there (the rest are ties: "
    "points equally near several cells, e.g. a shared vertex).\n\n"
    "| scene | locator | build ms | queries/s | points timed | max rel. distance error | same cell as brute force | "
    "vs vtkStaticCellLocator | vs vtkCellLocator |\n|---|---|---:|---|---:|---:|---:|---:|---:|\n";
  top.Set("ratios", jratios).Set("rows", jrows);
  if (!jpoints.empty())
  {
    top.Set("closestPoint", jpoints).Set("closestPointQueries", static_cast<long long>(nPoints));
  }
  const std::string stem = dir + "/triangles";
  {
    std::ofstream f(stem + ".json");
    f << top.Str() << "\n";
  }
  {
    std::ofstream f(stem + ".md");
    f << "# TriangleGrid benchmark\n\n" << date << ", commit " << commit << ", " << cpu << ", median of " << runs
      << " runs after a warm-up (min-max in brackets). " << width << " x " << height << " primary rays per scene plus "
      << nLights << " shadow rays per visible point. Mrays/s; closest = primary rays, shadow = any-hit, "
      << "all = every hit along the primary rays.\n\n";
    f << "## Ratios: our recursive grid (default R) / anchor\n\n"
      << "| scene | triangles | closest vs Embree, 1 thread | closest vs Embree, 2 threads | shadow vs Embree | all hits vs Embree | closest vs vtkStaticCellLocator | bytes/tri | build time / Embree's |\n"
      << "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n"
      << ratioText << "\n";
    if (!pointText.empty())
    {
      f << pointHead << pointText << "\n";
    }
    for (const Scene& s : scenes)
    {
      f << "## " << s.name << " (" << s.store->Size() << " triangles, " << s.primary.size() << " primary + "
        << s.shadow.size() << " shadow rays, camera " << s.view << ")\n\n";
      f << "| engine | group | build ms | bytes/tri | closest 1T | closest 2T | shadow 1T | shadow 2T | all 1T | voxels/ray | tris/ray | same as Embree % | note |\n"
        << "|---|---|---:|---:|---|---|---|---|---|---:|---:|---:|---|\n";
      for (const Row& r : rows)
      {
        if (r.scene != s.name)
        {
          continue;
        }
        f << "| " << r.engine << " | " << r.group << " | " << Fmt(r.buildMs, 1) << " | " << Fmt(r.bytesPerTri, 0) << " | "
          << FmtStats(r.prim1) << " | " << (r.havePrim2 ? FmtStats(r.prim2) : "") << " | "
          << (r.haveShadow ? FmtStats(r.shad1) : "") << " | " << (r.havePrim2 && r.haveShadow ? FmtStats(r.shad2) : "")
          << " | " << (r.haveAll ? FmtStats(r.all1) : "") << " | " << Fmt(r.voxelsPerRay, 1) << " | "
          << Fmt(r.trisPerRay, 1) << " | " << Fmt(r.agree, 3) << " | " << r.note << " |\n";
      }
      f << "\n";
    }
  }

  std::printf("## Ratios: our recursive grid / anchor\n\n| scene | triangles | closest vs Embree 1T | 2T | shadow vs Embree | "
              "all hits vs Embree | closest vs vtkStaticCellLocator | bytes/tri | build / Embree |\n"
              "|---|---:|---:|---:|---:|---:|---:|---:|---:|\n%s\n",
    ratioText.c_str());
  if (!pointText.empty())
  {
    std::printf("%s%s\n", pointHead.c_str(), pointText.c_str());
  }
  cli::FinishResults(src + "/tests/benchmarks/triangles_chart.py", stem);
  return cli::ExitOk;
}

cli::BenchRegistrar reg({ "triangles",
  "TriangleGrid accelerators vs Embree 3 and VTK's cell locators, and the paper's R/O tables", Declare, Run });
} // namespace
#endif // ART_HAVE_TriangleGrid
