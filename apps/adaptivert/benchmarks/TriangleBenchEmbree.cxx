// The Embree 3 anchor of `adaptivert bench triangles`: rtcIntersect1 (closest hit), rtcOccluded1
// (any hit) and all hits through an intersection filter that counts and rejects every hit.
#ifdef ART_HAVE_TriangleGrid
#ifdef ART_HAVE_EMBREE
#include "benchmarks/TriangleBench.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace trianglebench
{
namespace
{
std::atomic<long long> EmbreeBytes{ 0 };
bool EmbreeMemory(void*, ssize_t bytes, bool)
{
  EmbreeBytes += bytes;
  return true;
}

struct AllHitsContext
{
  RTCIntersectContext ctx;
  size_t count;
};

// The intersection filter that turns rtcIntersect1 into an all-hits query: count, then reject.
void AllHitsFilter(const RTCFilterFunctionNArguments* args)
{
  auto* c = reinterpret_cast<AllHitsContext*>(args->context);
  if (c->count == size_t(-1))
  {
    return; // a plain closest-hit query
  }
  for (unsigned i = 0; i < args->N; ++i)
  {
    if (args->valid[i] == -1)
    {
      ++c->count;
      args->valid[i] = 0;
    }
  }
}

void Fill(const art::Ray& r, RTCRay& ray)
{
  ray.org_x = float(r.org.x);
  ray.org_y = float(r.org.y);
  ray.org_z = float(r.org.z);
  ray.dir_x = float(r.dir.x);
  ray.dir_y = float(r.dir.y);
  ray.dir_z = float(r.dir.z);
  ray.tnear = float(r.tmin);
  ray.tfar = std::isinf(r.tmax) ? std::numeric_limits<float>::infinity() : float(r.tmax);
  ray.time = 0;
  ray.mask = ~0u;
  ray.id = 0;
  ray.flags = 0;
}
} // namespace

EmbreeScene::EmbreeScene(const art::TriangleStore& s)
{
  dev = rtcNewDevice(nullptr);
  rtcSetDeviceMemoryMonitorFunction(dev, EmbreeMemory, nullptr);
  EmbreeBytes = 0;
  scene = rtcNewScene(dev);
  RTCGeometry g = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
  // The same float vertices our store traces, one vertex triple per triangle record.
  const size_t np = s.PointCount();
  float* v = static_cast<float*>(
    rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), np));
  std::copy(s.Vertices(), s.Vertices() + 3 * np, v);
  unsigned* idx = static_cast<unsigned*>(
    rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), s.Size()));
  for (size_t i = 0; i < s.Size(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      idx[3 * i + k] = s.Record(i).v[k];
    }
  }
  rtcSetGeometryIntersectFilterFunction(g, AllHitsFilter);
  rtcCommitGeometry(g);
  rtcAttachGeometry(scene, g);
  rtcReleaseGeometry(g);
  rtcCommitScene(scene);
  bytes = EmbreeBytes.load();
}
EmbreeScene::~EmbreeScene()
{
  rtcReleaseScene(scene);
  rtcReleaseDevice(dev);
}

Engine EmbreeScene::Queries() const
{
  Engine e;
  RTCScene sc = scene;
  e.closest = [sc](const art::Ray& r, double& t) {
    AllHitsContext c;
    rtcInitIntersectContext(&c.ctx);
    c.count = size_t(-1);
    RTCRayHit rh;
    Fill(r, rh.ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(sc, &c.ctx, &rh);
    t = rh.ray.tfar;
    return rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
  };
  e.any = [sc](const art::Ray& r) {
    AllHitsContext c;
    rtcInitIntersectContext(&c.ctx);
    c.count = size_t(-1);
    RTCRay ray;
    Fill(r, ray);
    rtcOccluded1(sc, &c.ctx, &ray);
    return ray.tfar < 0;
  };
  e.all = [sc](const art::Ray& r) {
    AllHitsContext c;
    rtcInitIntersectContext(&c.ctx);
    c.count = 0;
    RTCRayHit rh;
    Fill(r, rh.ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(sc, &c.ctx, &rh);
    return c.count;
  };
  return e;
}
} // namespace trianglebench
#endif // ART_HAVE_EMBREE
#endif // ART_HAVE_TriangleGrid
