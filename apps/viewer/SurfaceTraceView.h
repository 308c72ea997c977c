// SurfaceTraceView: shows a triangle scene through the project's own ray tracing machine
// (TriangleGrid recursive grid + art::SurfaceTracer, Dmitriev's closest-hit and shadow queries)
// in a VTK window: each frame is traced from the renderer's camera and drawn as the renderer's
// textured background, so the trackball camera drives the tracer directly. Built without
// AdaptiveRT::TriangleGrid, a plain vtkPolyDataMapper draws the scene and Description() says so.
#ifndef art_SurfaceTraceView_h
#define art_SurfaceTraceView_h

#include "Box3.h"

#include <vtkSmartPointer.h>

#include <memory>
#include <string>

class vtkPolyData;
class vtkRenderer;

namespace view
{
class SurfaceTraceView
{
public:
  /// Builds the accelerator; throws art::Error naming `file` for a scene without triangles.
  SurfaceTraceView(vtkPolyData* scene, const std::string& file);
  ~SurfaceTraceView();
  SurfaceTraceView(const SurfaceTraceView&) = delete;
  SurfaceTraceView& operator=(const SurfaceTraceView&) = delete;

  /// Traces into `ren`'s background on every render of it.
  void Attach(vtkRenderer* ren);
  /// Rays per pixel side: 1 = full resolution, 2 while the camera moves.
  void SetSampleDistance(int d) { Sample = d; }

  art::Box3 Bounds() const;
  double LastTraceSeconds() const;
  /// One line for the status text: "2,650 triangles, SurfaceTracer, R[12,4]".
  std::string Description() const;

private:
  void Trace(vtkRenderer* ren);

  struct Internals;
  std::unique_ptr<Internals> Impl;
  int Sample = 1;
};
} // namespace view

#endif
