// SurfaceTracer: ray traces a triangle scene with point lights and shadows (Lambert shading,
// smooth normals). Transparent surfaces use the all-hits query, as Dmitriev's ray tracing machine
// does: a view ray composites every surface front to back, and light reaching a point is
// attenuated by each surface the shadow ray crosses.
#ifndef art_SurfaceTracer_h
#define art_SurfaceTracer_h

#include "Accelerator.h"
#include "AdaptiveRTTriangleGridModule.h"
#include "Camera.h"
#include "Image.h"

#include <array>
#include <vector>

namespace art
{
class Progress;

struct PointLight
{
  Vec3 position;
  double intensity = 1.0;
};

struct SurfaceTracerSettings
{
  std::vector<PointLight> lights; ///< empty: a headlight at the camera
  double opacity = 1.0;           ///< of every surface; < 1 makes the scene transparent
  double ambient = 0.15;
  bool shadows = true;
  bool smooth = true; ///< interpolate area-weighted vertex normals
  std::array<float, 3> color{ { 0.85f, 0.82f, 0.75f } };
  int maxLayers = 32; ///< transparent surfaces composited per view ray at most
};

/// The default lighting of the CLI and the viewer: a headlight at the eye and a shadow-casting key
/// light above and to the left of the camera, both scaled to the eye's distance from the focus.
ADAPTIVERTTRIANGLEGRID_EXPORT std::vector<PointLight> HeadAndKeyLights(
  const Vec3& eye, const Vec3& focalPoint, const Vec3& viewUp);

class ADAPTIVERTTRIANGLEGRID_EXPORT SurfaceTracer
{
public:
  SurfaceTracer(const Accelerator& acc, SurfaceTracerSettings s);
  /// Per-point colours (indexed like TriangleStore::Points), interpolated over each triangle.
  void SetPointColors(std::vector<std::array<float, 3>> c) { Colors = std::move(c); }
  /// Premultiplied RGBA (alpha = coverage). Work counts go to `stats` when given.
  Image Render(const Camera& cam, Progress* progress = nullptr, Counters* stats = nullptr) const;
  /// The colour (premultiplied) and alpha seen along one view ray.
  Image::RGBA Trace(const Ray& r, Counters& c) const;

private:
  std::array<float, 3> Shade(const Ray& r, const Hit& h, Counters& c) const;
  double Transmittance(const Vec3& from, const Vec3& to, Counters& c) const;

  const Accelerator& Acc;
  SurfaceTracerSettings S;
  std::vector<Vec3> Normals; ///< per point
  std::vector<std::array<float, 3>> Colors;
  double Eps = 1e-6;
};
} // namespace art

#endif
