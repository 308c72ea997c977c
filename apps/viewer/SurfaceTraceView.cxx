#include "SurfaceTraceView.h"

#include "Error.h"
#include "ViewerScene.h"

#ifdef ART_HAVE_TriangleGrid
#include "Accelerator.h"
#include "Camera.h"
#include "SurfaceColours.h"
#include "SurfaceTracer.h"
#include "TriangleStore.h"
#endif

#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <algorithm>
#include <chrono>

#ifdef ART_HAVE_TriangleGrid
namespace view
{
struct SurfaceTraceView::Internals
{
  std::shared_ptr<art::TriangleStore> Store;
  art::Vec3 Origin; ///< the store's coordinates are taken from here (TriangleStore::OriginFor)
  std::unique_ptr<art::Accelerator> Acc;
  std::vector<std::array<float, 3>> Colors;
  vtkNew<vtkImageData> Frame;
  vtkNew<vtkTexture> Texture;
  vtkNew<vtkCallbackCommand> OnStart;
  double Last = 0;
};

SurfaceTraceView::SurfaceTraceView(vtkPolyData* input, const std::string& file)
  : Impl(new Internals)
{
  vtkSmartPointer<vtkPolyData> pd = art::WithColoursOnPoints(input); // face colours onto corners
  double b[6];
  pd->GetBounds(b);
  Impl->Origin = art::TriangleStore::OriginFor(art::Box3::FromBounds(b));
  Impl->Store = std::make_shared<art::TriangleStore>(art::TriangleStore::FromPolyData(pd, Impl->Origin));
  if (Impl->Store->Size() == 0)
  {
    throw art::Error("has no triangles to show: all " +
        std::to_string(pd->GetNumberOfPolys() + pd->GetNumberOfStrips()) +
        " polygons have zero area or non-finite points (float coordinates far from the origin lose small detail)",
      file);
  }
  Impl->Acc = art::MakeAccelerator(Impl->Store);
  Impl->Colors = art::PointColours(pd);
  Impl->Texture->SetInputData(Impl->Frame);
  Impl->Texture->InterpolateOff();
}

SurfaceTraceView::~SurfaceTraceView() = default;

void SurfaceTraceView::Attach(vtkRenderer* ren)
{
  ren->SetBackgroundTexture(Impl->Texture);
  ren->TexturedBackgroundOn();
  Impl->OnStart->SetClientData(this);
  Impl->OnStart->SetCallback([](vtkObject* caller, unsigned long, void* self, void*) {
    static_cast<SurfaceTraceView*>(self)->Trace(static_cast<vtkRenderer*>(caller));
  });
  // StartEvent fires before the renderer clears, i.e. before the background is drawn.
  ren->AddObserver(vtkCommand::StartEvent, Impl->OnStart);
}

void SurfaceTraceView::Trace(vtkRenderer* ren)
{
  const int* size = ren->GetSize();
  const int w = std::max(1, size[0] / Sample), h = std::max(1, size[1] / Sample);
  // The camera in the store's coordinates.
  vtkNew<vtkCamera> vcam;
  vcam->DeepCopy(ren->GetActiveCamera());
  const art::Vec3 pos = art::Vec3(vcam->GetPosition()) - Impl->Origin, fp = art::Vec3(vcam->GetFocalPoint()) - Impl->Origin;
  vcam->SetPosition(pos.x, pos.y, pos.z);
  vcam->SetFocalPoint(fp.x, fp.y, fp.z);
  // A headlight and a key light above-left of the camera (the CLI's default lights).
  art::SurfaceTracerSettings s;
  s.lights = art::HeadAndKeyLights(
    art::Vec3(vcam->GetPosition()), art::Vec3(vcam->GetFocalPoint()), art::Vec3(vcam->GetViewUp()));
  art::SurfaceTracer tracer(*Impl->Acc, s);
  if (!Impl->Colors.empty())
  {
    tracer.SetPointColors(Impl->Colors);
  }
  const auto t0 = std::chrono::steady_clock::now();
  art::Image img = tracer.Render(art::Camera::FromVTK(vcam, w, h));
  Impl->Last = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  double bg[3];
  ren->GetBackground(bg);
  img.CompositeOver({ { float(bg[0]), float(bg[1]), float(bg[2]) } });

  vtkImageData* f = Impl->Frame;
  f->SetDimensions(w, h, 1);
  f->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* dst = static_cast<unsigned char*>(f->GetScalarPointer());
  for (int y = 0; y < h; ++y)
  {
    const float* row = img.Pixel(0, h - 1 - y); // VTK rows run bottom-up
    for (int x = 0; x < w; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        dst[3 * (static_cast<size_t>(y) * w + x) + c] =
          static_cast<unsigned char>(std::min(std::max(row[4 * x + c], 0.f), 1.f) * 255.f + 0.5f);
      }
    }
  }
  f->Modified();
}

art::Box3 SurfaceTraceView::Bounds() const
{
  const art::Box3 b = Impl->Store->Bounds();
  return art::Box3(b.lo + Impl->Origin, b.hi + Impl->Origin);
}

double SurfaceTraceView::LastTraceSeconds() const
{
  return Impl->Last;
}

std::string SurfaceTraceView::Description() const
{
  const std::string acc = Impl->Acc->Name(); // "R[12,4] top 12x10x6 depth 3": the short form
  return Grouped(static_cast<long long>(Impl->Store->Size())) + " triangles, SurfaceTracer, " +
    acc.substr(0, acc.find(' '));
}
} // namespace view

#else
// Built without AdaptiveRT::TriangleGrid: the scene is drawn by a plain vtkPolyDataMapper, and
// the status line says so.
#include <vtkActor.h>
#include <vtkPolyDataMapper.h>

namespace view
{
struct SurfaceTraceView::Internals
{
  vtkSmartPointer<vtkPolyData> Scene;
  vtkNew<vtkPolyDataMapper> Mapper;
  vtkNew<vtkActor> Actor;
};

SurfaceTraceView::SurfaceTraceView(vtkPolyData* input, const std::string& file)
  : Impl(new Internals)
{
  vtkSmartPointer<vtkPolyData> pd = art::WithColoursOnPoints(input); // face colours onto corners
  if (!pd || pd->GetNumberOfPolys() == 0)
  {
    throw art::Error("has no triangles to show", file);
  }
  Impl->Scene = pd;
  Impl->Mapper->SetInputData(pd);
  Impl->Actor->SetMapper(Impl->Mapper);
}
SurfaceTraceView::~SurfaceTraceView() = default;
void SurfaceTraceView::Attach(vtkRenderer* ren)
{
  ren->AddActor(Impl->Actor);
}
void SurfaceTraceView::Trace(vtkRenderer*) {}
art::Box3 SurfaceTraceView::Bounds() const
{
  double b[6];
  Impl->Scene->GetBounds(b);
  return art::Box3::FromBounds(b);
}
double SurfaceTraceView::LastTraceSeconds() const
{
  return 0;
}
std::string SurfaceTraceView::Description() const
{
  return Grouped(Impl->Scene->GetNumberOfPolys()) + " polygons, plain vtkPolyDataMapper (no TriangleGrid in this build)";
}
} // namespace view
#endif
