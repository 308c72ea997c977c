// Shared by the files of `adaptivert bench triangles`: a scene with its rays, a query engine over
// them, the timing helpers, and the parts kept in files of their own (the Embree 3 anchor in
// TriangleBenchEmbree.cxx, the closest-point table in TriangleBenchClosestPoint.cxx).
#ifndef art_TriangleBench_h
#define art_TriangleBench_h

#include "benchmarks/BenchUtil.h"
#include "Ray.h"
#include "TriangleStore.h"

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#ifdef ART_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace trianglebench
{
using Clock = std::chrono::steady_clock;

inline double Since(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Median of `runs` timings after one warm-up run.
inline cli::BenchStats Time(int runs, const std::function<void()>& fn)
{
  return cli::TimeRuns(runs, [&] {
    const auto t0 = Clock::now();
    fn();
    return Since(t0);
  });
}

struct Scene
{
  std::string name, path;
  vtkSmartPointer<vtkPolyData> pd;
  std::shared_ptr<art::TriangleStore> store;
  std::vector<art::Ray> primary, shadow;
  std::string view;
};

/// A query engine over the scene's rays.
struct Engine
{
  std::function<bool(const art::Ray&, double&)> closest;
  std::function<bool(const art::Ray&)> any;
  std::function<size_t(const art::Ray&)> all;
};

#ifdef ART_HAVE_EMBREE
/// Embree 3 on the scene's own float vertices, with an intersection filter for all-hits queries.
struct EmbreeScene
{
  RTCDevice dev = nullptr;
  RTCScene scene = nullptr;
  long long bytes = 0; ///< what Embree allocated for the scene
  explicit EmbreeScene(const art::TriangleStore& s);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  Engine Queries() const;
};
#endif

/// One locator's closest-point figures on one scene.
struct PointRow
{
  std::string scene, engine;
  double buildMs = 0;
  cli::BenchStats rate; // queries/s
  size_t points = 0;    // points timed
  double maxRelError = -1; // max |d - d_brute| / d_brute over the reference points
  size_t sameCell = 0, refPoints = 0;
  std::string note;
};

/// FindClosestPoint of vtkTriangleGridLocator (each accelerator) and of VTK's static and classic
/// cell locators on the same query points of scene s, one thread, with the distance error against
/// brute force; a row each is appended to rows.
void BenchClosestPoint(const Scene& s, std::size_t nPoints, int runs, std::vector<PointRow>& rows);
} // namespace trianglebench

#endif
