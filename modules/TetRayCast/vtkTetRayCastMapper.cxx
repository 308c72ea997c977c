#include "vtkTetRayCastMapper.h"

#include "ArrayChoice.h"

#include "Camera.h"
#include "Error.h"
#include "MapperGrid.h"
#include "MapperLabels.h"
#include "Progress.h"
#include "TetMesh.h"
#include "TetRayCaster.h"

#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPointData.h>
#include <vtkOpenGLRayCastImageDisplayHelper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <thread>
#include <vector>

vtkStandardNewMacro(vtkTetRayCastMapper);

namespace
{
// Where each of cam's rays meets the opaque geometry already drawn in ren's viewport (vw x vh
// window pixels): the depth buffer at the ray's pixel, taken back through the camera's projection
// into world and then data coordinates (toData), as a t along cam.Generate(x, y). Infinity where
// nothing was drawn.
std::vector<double> RayEndsFromDepth(
  vtkRenderer* ren, int vw, int vh, const art::Camera& cam, vtkMatrix4x4* toData)
{
  std::vector<float> z(static_cast<std::size_t>(vw) * vh, 1.0f);
  const int* org = ren->GetOrigin();
  ren->GetRenderWindow()->GetZbufferData(org[0], org[1], org[0] + vw - 1, org[1] + vh - 1, z.data());
  double aspect[2];
  ren->ComputeAspect();
  ren->GetAspect(aspect);
  vtkNew<vtkMatrix4x4> fromNdc;
  vtkMatrix4x4::Invert(
    ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect[0] / aspect[1], -1, 1), fromNdc);
  const int w = cam.Width(), h = cam.Height();
  std::vector<double> ends(static_cast<std::size_t>(w) * h, std::numeric_limits<double>::infinity());
  for (int y = 0; y < h; ++y)
  {
    // Ray rows count from the top, window rows from the bottom.
    const int vy = vh - 1 - std::min(vh - 1, static_cast<int>((y + 0.5) * vh / h));
    for (int x = 0; x < w; ++x)
    {
      const int vx = std::min(vw - 1, static_cast<int>((x + 0.5) * vw / w));
      const double d = z[static_cast<std::size_t>(vy) * vw + vx];
      if (!(d < 1.0))
      {
        continue;
      }
      const double ndc[4] = { 2.0 * (vx + 0.5) / vw - 1.0, 2.0 * (vy + 0.5) / vh - 1.0, 2.0 * d - 1.0, 1.0 };
      double world[4], p[4];
      fromNdc->MultiplyPoint(ndc, world);
      toData->MultiplyPoint(world, p);
      if (p[3] == 0.0)
      {
        continue;
      }
      const art::Ray r = cam.Generate(x, y);
      const art::Vec3 hit(p[0] / p[3], p[1] / p[3], p[2] / p[3]);
      ends[static_cast<std::size_t>(y) * w + x] = art::Dot(hit - r.org, r.dir) / art::Dot(r.dir, r.dir);
    }
  }
  return ends;
}

// Moves `cam` into the data's coordinates (the inverse of the volume's matrix, a rotation times
// one scale: SimilarityScale), its parallel scale divided by the matrix's scale.
void IntoData(vtkCamera* cam, vtkMatrix4x4* toWorld, vtkMatrix4x4* toData)
{
  double pos[4], fp[4], up[3], q[4];
  cam->GetPosition(pos);
  cam->GetFocalPoint(fp);
  cam->GetViewUp(up);
  pos[3] = fp[3] = 1.0;
  toData->MultiplyPoint(pos, q);
  cam->SetPosition(q[0] / q[3], q[1] / q[3], q[2] / q[3]);
  toData->MultiplyPoint(fp, q);
  cam->SetFocalPoint(q[0] / q[3], q[1] / q[3], q[2] / q[3]);
  double up4[4] = { up[0], up[1], up[2], 0.0 };
  toData->MultiplyPoint(up4, q);
  cam->SetViewUp(q[0], q[1], q[2]);
  // Column lengths of the linear part: the scale along each axis.
  double len[3];
  for (int c = 0; c < 3; ++c)
  {
    len[c] = std::sqrt(toWorld->GetElement(0, c) * toWorld->GetElement(0, c) +
      toWorld->GetElement(1, c) * toWorld->GetElement(1, c) + toWorld->GetElement(2, c) * toWorld->GetElement(2, c));
  }
  cam->SetParallelScale(cam->GetParallelScale() / std::cbrt(len[0] * len[1] * len[2]));
}

// Depth of the image's quad: the nearest corner of the data's bounds `b`, as VTK's ray cast
// mappers place it.
double QuadDepth(vtkRenderer* ren, const double b[6], vtkMatrix4x4* toWorld)
{
  double aspect[2];
  ren->ComputeAspect();
  ren->GetAspect(aspect);
  vtkMatrix4x4* m = ren->GetActiveCamera()->GetCompositeProjectionTransformMatrix(aspect[0] / aspect[1], 0, 1);
  double minZ = 1.0;
  for (int k = 0; k < 8; ++k)
  {
    double p[4] = { b[k & 1], b[2 + ((k >> 1) & 1)], b[4 + ((k >> 2) & 1)], 1.0 }, pw[4], q[4];
    toWorld->MultiplyPoint(p, pw);
    m->MultiplyPoint(pw, q);
    if (q[3] != 0)
    {
      minZ = std::min(minZ, q[2] / q[3]);
    }
  }
  return std::min(std::max(minZ, 0.0), 1.0);
}
} // namespace

struct vtkTetRayCastMapper::Internals
{
  std::unique_ptr<art::TetMesh> Mesh;
  std::unique_ptr<art::TetRayCaster> Caster; ///< kept with the mesh: a non-convex one's boundary grid
  vtkMTimeType MeshTime = 0;
  vtkDataSet* MeshInput = nullptr;
  std::string MeshArray;
  bool MeshRefused = false; ///< the build for MeshInput, MeshTime and MeshArray failed (said once)
  std::string LastError;    ///< FrameError's message while it repeats
  std::vector<art::IsoSurface> Isos;
  std::unique_ptr<art::LabelMesh> Labels; ///< the mesh split per label (LabelColoring), else none
  std::vector<std::array<double, 4>> LastPlanes; ///< the last frame's clipping planes (engine coordinates)
  vtkSmartPointer<vtkImageData> Last = vtkSmartPointer<vtkImageData>::New();
  std::vector<unsigned char> Bytes;
  vtkSmartPointer<vtkOpenGLRayCastImageDisplayHelper> Helper;
};

vtkTetRayCastMapper::vtkTetRayCastMapper()
  : Impl(new Internals)
{
  // The OpenGL helper itself, not vtkRayCastImageDisplayHelper::New(): the factory override
  // needs the application to initialise vtkRenderingVolumeOpenGL2, and a library must not.
  this->Impl->Helper.TakeReference(vtkOpenGLRayCastImageDisplayHelper::New());
  this->SetLabelArrayName("label");
}

vtkTetRayCastMapper::~vtkTetRayCastMapper()
{
  this->SetLabelArrayName(nullptr);
  delete this->Impl;
}

void vtkTetRayCastMapper::AddIsoSurface(double value, double r, double g, double b, double opacity)
{
  this->Impl->Isos.push_back({ value, { { r, g, b } }, std::min(std::max(opacity, 0.0), 1.0) });
  this->Modified();
}

void vtkTetRayCastMapper::RemoveAllIsoSurfaces()
{
  this->Impl->Isos.clear();
  this->Modified();
}

int vtkTetRayCastMapper::GetNumberOfIsoSurfaces()
{
  return static_cast<int>(this->Impl->Isos.size());
}

vtkImageData* vtkTetRayCastMapper::GetLastImage()
{
  return this->Impl->Last;
}

void vtkTetRayCastMapper::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->Impl->Helper)
  {
    this->Impl->Helper->ReleaseGraphicsResources(w);
  }
}

// One frame's state as Render's steps pass it on.
struct vtkTetRayCastMapper::Frame
{
  vtkDataSet* input = nullptr;
  vtkUnstructuredGrid* grid = nullptr;
  vtkSmartPointer<vtkUnstructuredGrid> engineGrid; ///< the selected scalars as the engine's array
  std::string key;                                 ///< what the engine's mesh was built from
  vtkMatrix4x4* toWorld = nullptr;
  vtkNew<vtkMatrix4x4> engineToWorld, meshToEngine, toData; // the engine's mesh is meshToEngine * data
  bool similar = true; ///< toWorld is a rotation times one positive scale
  bool labels = false;  ///< LabelColoring applies to this frame (if the grid has labels)
  art::RenderSettings settings;
  int vw = 1, vh = 1, w = 1, h = 1; ///< viewport and image sizes
  art::Image img;
};

void vtkTetRayCastMapper::Render(vtkRenderer* ren, vtkVolume* vol)
{
  Frame f;
  f.input = this->GetDataSetInput();
  if (!f.input || !ren || !vol || !this->SelectScalars(f))
  {
    return;
  }
  this->PlaceInData(vol, f);
  if (!this->UpdateMesh(f))
  {
    return;
  }
  // A frame's time, for AutoAdjustSampleDistances, leaves out (re)building the mesh.
  const auto frameStart = std::chrono::steady_clock::now();
  if (!this->FrameSettings(vol, f))
  {
    return;
  }
  this->AdjustSampleDistance(vol);
  if (!this->CastFrame(ren, f))
  {
    return;
  }
  this->DrawFrame(ren, vol, f);
  this->LastFrameSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - frameStart).count();
}

bool vtkTetRayCastMapper::SelectScalars(Frame& f)
{
  f.grid = vtkUnstructuredGrid::SafeDownCast(f.input);
  if (!f.grid)
  {
    this->FrameError("input must be a vtkUnstructuredGrid");
    return false;
  }
  if (f.grid->GetNumberOfCells() == 0)
  {
    return false; // nothing to draw (a threshold that keeps nothing), as VTK's mappers draw nothing; no error each frame
  }
  // The array the usual vtkAbstractVolumeMapper settings select (ScalarMode, SelectScalarArray).
  std::string error;
  const int component = this->VectorMode == MAGNITUDE ? art::Magnitude
    : this->VectorMode == COMPONENT                   ? this->VectorComponent
                                                      : art::WholeArray;
  f.engineGrid = art::mapper::SelectedScalars(f.grid, this->ScalarMode,
    this->ArrayAccessMode == VTK_GET_ARRAY_BY_NAME ? this->ArrayName : nullptr, this->ArrayId, component, f.key, error);
  if (!f.engineGrid)
  {
    this->FrameError(error);
    return false;
  }
  // Label colouring needs the composite blend and no iso-surface (its scalars are per label).
  f.labels = this->LabelColoring != LABEL_COLORING_OFF && this->LabelArrayName && *this->LabelArrayName &&
    this->BlendMode == COMPOSITE_BLEND && this->Impl->Isos.empty();
  if (f.labels)
  {
    f.key += std::string(" labels:") + std::to_string(this->LabelColoring) + ":" + this->LabelArrayName;
  }
  return true;
}

void vtkTetRayCastMapper::PlaceInData(vtkVolume* vol, Frame& f)
{
  // Rays are cast in the data's own coordinates when the volume's matrix is a rotation times one
  // scale (the camera goes through its inverse; segment lengths, and so the opacity unit
  // distance, are measured in data units). Any other matrix moves the mesh's points through its
  // linear part instead, rebuilt when that part changes: a mirror (a negative scale: the camera
  // moved through it sees right and left swapped, and the volume was drawn on the wrong side of
  // the view) divided by its scale, so lengths stay in data units; an anisotropic scale
  // (SetScale(1, 1, 3) for thick slices) or a shear as it is, lengths in world units.
  f.toWorld = vol->GetMatrix();
  const double scale = art::mapper::SimilarityScale(f.toWorld);
  f.similar = scale > 0 && f.toWorld->Determinant() > 0;
  // Every digit: a key that rounds would keep a stale mesh for a slightly changed matrix or plane.
  auto exact = [](double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, " %.17g", v);
    return std::string(buf);
  };
  if (f.similar)
  {
    f.engineToWorld->DeepCopy(f.toWorld);
  }
  else
  {
    // Only the linear part goes into the mesh (divided by a mirror's scale); the translation
    // stays with the camera, so moving such a volume does not rebuild its mesh.
    const double k = scale > 0 ? scale : 1.0;
    f.key += " world";
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        f.meshToEngine->SetElement(r, c, f.toWorld->GetElement(r, c) / k);
        f.key += exact(f.toWorld->GetElement(r, c));
      }
      f.meshToEngine->SetElement(r, 3, 0.0);
      f.engineToWorld->SetElement(r, r, k);
      f.engineToWorld->SetElement(r, 3, f.toWorld->GetElement(r, 3));
    }
  }
  vtkMatrix4x4::Invert(f.engineToWorld, f.toData);
}

bool vtkTetRayCastMapper::UpdateMesh(Frame& f)
{
  // (Re)build the engine's arrays only when the data, the array or the matrix's linear part
  // changed; clipping planes cut the rays, not the mesh.
  Internals& I = *this->Impl;
  if ((I.Mesh || I.MeshRefused) && I.MeshInput == f.input && I.MeshTime >= f.input->GetMTime() && I.MeshArray == f.key)
  {
    return I.Mesh != nullptr; // a refused input said why when it was built
  }
  try
  {
    std::string note;
    I.Caster.reset();
    I.Mesh.reset();
    I.Labels = f.labels ? art::mapper::SplitLabels(f.engineGrid, f.grid, this->LabelArrayName,
                            this->LabelColoring == LABEL_COLORING_FLAT)
                        : nullptr;
    vtkSmartPointer<vtkUnstructuredGrid> engineGrid =
      I.Labels ? vtkSmartPointer<vtkUnstructuredGrid>(I.Labels->Grid()) : art::mapper::WithoutGhosts(f.engineGrid, f.grid);
    if (engineGrid->GetNumberOfCells() == 0)
    {
      return false; // only ghosts: their own pieces draw them
    }
    if (!f.similar)
    {
      engineGrid = art::mapper::Transformed(engineGrid, f.meshToEngine);
    }
    I.Mesh = std::make_unique<art::TetMesh>(art::TetMesh::FromVTK(engineGrid, {}, &note));
    I.Caster = std::make_unique<art::TetRayCaster>(*I.Mesh, art::RenderSettings{});
    if (!note.empty())
    {
      vtkWarningMacro(<< note);
    }
    I.MeshRefused = false;
  }
  catch (const art::Error& e)
  {
    // Said once for this input: every frame (each camera move in ParaView) said it again.
    I.Caster.reset();
    I.Mesh.reset();
    I.Labels.reset();
    I.MeshRefused = true;
    vtkErrorMacro(<< e.what());
  }
  I.MeshInput = f.input;
  I.MeshTime = f.input->GetMTime();
  I.MeshArray = f.key;
  return I.Mesh != nullptr;
}

bool vtkTetRayCastMapper::FrameSettings(vtkVolume* vol, Frame& f)
{
  art::RenderSettings& s = f.settings;
  this->WarnUnsupported(vol->GetProperty(), f.grid);
  try
  {
    s.tf = this->Impl->Labels ? art::mapper::LabelFunction(*this->Impl->Labels, vol->GetProperty())
                              : art::TransferFunction::FromVTK(vol->GetProperty());
  }
  catch (const art::Error& e)
  {
    this->FrameError(e.what());
    return false;
  }
  s.earlyTermination = this->EarlyRayTermination >= 1.0 ? 2.0 : this->EarlyRayTermination;
  s.rule = this->TrapezoidRule ? art::RenderSettings::Rule::Trapezoid : art::RenderSettings::Rule::Exact;
  s.mode = this->BlendMode == MAXIMUM_INTENSITY_BLEND ? art::RenderSettings::Mode::MaxIntensity
                                                      : art::RenderSettings::Mode::Composite;
  s.isos = this->Impl->Isos;
  vtkVolumeProperty* p = vol->GetProperty();
  s.shading.on = p->GetShade(0) != 0; // lit by a headlight, as a renderer with no lights of its own
  s.shading.ambient = p->GetAmbient(0), s.shading.diffuse = p->GetDiffuse(0);
  s.shading.specular = p->GetSpecular(0), s.shading.power = p->GetSpecularPower(0);
  s.clipPlanes = art::mapper::PlanesInData(this->ClippingPlanes, f.engineToWorld);
  // While a plane moves, each frame only cuts its rays; once it stands still, the tets it cuts
  // away also leave the walked region (a rebuild per change, worth it only for planes that stay).
  s.cullClipped = s.clipPlanes == this->Impl->LastPlanes;
  this->Impl->LastPlanes = s.clipPlanes;
  return true;
}

void vtkTetRayCastMapper::AdjustSampleDistance(vtkVolume* vol)
{
  const double allocated = vol->GetAllocatedRenderTime();
  if (this->AutoAdjustSampleDistances && this->LastFrameSeconds > 0 && allocated > 0)
  {
    // A frame's time goes with the number of rays, 1 / distance^2.
    const double lo = this->MinimumImageSampleDistance,
                 hi = std::max(this->MinimumImageSampleDistance, this->MaximumImageSampleDistance);
    this->ImageSampleDistance = static_cast<float>(std::min(hi,
      std::max(lo, this->ImageSampleDistance * std::sqrt(this->LastFrameSeconds / allocated))));
  }
}

bool vtkTetRayCastMapper::CastFrame(vtkRenderer* ren, Frame& f)
{
  int* size = ren->GetSize();
  f.vw = std::max(1, size[0]), f.vh = std::max(1, size[1]);
  f.w = std::max(1, static_cast<int>(f.vw / this->ImageSampleDistance + 0.5));
  f.h = std::max(1, static_cast<int>(f.vh / this->ImageSampleDistance + 0.5));
  vtkNew<vtkCamera> local;
  local->DeepCopy(ren->GetActiveCamera());
  if (!f.engineToWorld->IsIdentity())
  {
    IntoData(local, f.engineToWorld, f.toData);
  }
  this->WarnUnsupported(ren->GetActiveCamera());
  const art::Camera cam = art::Camera::FromVTK(local, f.w, f.h);
  std::vector<double> ends;
  if (this->IntermixIntersectingGeometry && ren->GetNumberOfPropsRendered() > 0 && ren->GetRenderWindow())
  {
    ends = RayEndsFromDepth(ren, f.vw, f.vh, cam, f.toData);
  }
  this->Impl->Caster->SetSettings(std::move(f.settings));
  // Progress goes to observers on the thread that called Render only, as VTK's own ray casters
  // report from their thread 0: observers (Python ones too) run where VTK runs them. There the
  // render window's abort check (an interactor's pending event) can also stop the frame.
  const std::thread::id caller = std::this_thread::get_id();
  vtkRenderWindow* win = ren->GetRenderWindow();
  double reported = -1.0;
  art::Progress progress([&](double p, const std::string&) {
    if (std::this_thread::get_id() != caller)
    {
      return;
    }
    reported = p;
    this->InvokeEvent(vtkCommand::VolumeMapperRenderProgressEvent, &p);
    if (win && win->CheckAbortStatus())
    {
      progress.Cancel(); // called only once the render has started, with progress built
    }
  });
  this->InvokeEvent(vtkCommand::VolumeMapperRenderStartEvent);
  const art::RenderStats st = this->Impl->Caster->Render(cam, f.img, &progress, ends.empty() ? nullptr : &ends);
  if (progress.Cancelled())
  {
    // An aborted frame is not drawn; the last whole image stays.
    this->InvokeEvent(vtkCommand::VolumeMapperRenderEndEvent);
    return false;
  }
  if (reported < 1.0)
  {
    double one = 1.0;
    this->InvokeEvent(vtkCommand::VolumeMapperRenderProgressEvent, &one);
  }
  this->InvokeEvent(vtkCommand::VolumeMapperRenderEndEvent);
  this->LastRenderTime = st.seconds;
  this->Impl->LastError.clear();
  this->LastTetsCrossed = static_cast<double>(st.counters.tetsCrossed);
  return true;
}

void vtkTetRayCastMapper::DrawFrame(vtkRenderer* ren, vtkVolume* vol, Frame& f)
{
  // Keep the float image (bottom row first, as VTK images are) and draw 8-bit premultiplied RGBA.
  const int w = f.w, h = f.h;
  vtkImageData* last = this->Impl->Last;
  last->SetDimensions(w, h, 1);
  last->AllocateScalars(VTK_FLOAT, 4);
  float* dst = static_cast<float*>(last->GetScalarPointer());
  auto& bytes = this->Impl->Bytes;
  bytes.resize(static_cast<std::size_t>(4) * w * h);
  for (int y = 0; y < h; ++y)
  {
    const float* row = f.img.Pixel(0, h - 1 - y);
    std::copy(row, row + 4 * w, dst + static_cast<std::size_t>(4) * w * y);
    for (int i = 0; i < 4 * w; ++i)
    {
      bytes[static_cast<std::size_t>(4) * w * y + i] =
        static_cast<unsigned char>(std::min(std::max(row[i], 0.f), 1.f) * 255.f + 0.5f);
    }
  }
  last->Modified();

  double b[6];
  f.input->GetBounds(b);
  const double minZ = QuadDepth(ren, b, f.toWorld);
  // The quad is placed in image samples: the image's own size is the viewport's (VTK's ray-cast
  // mappers pass the same), so a coarser ImageSampleDistance still fills the viewport.
  int mem[2] = { w, h }, view[2] = { w, h }, use[2] = { w, h }, origin[2] = { 0, 0 };
  this->Impl->Helper->SetPreMultipliedColors(1);
  this->Impl->Helper->RenderTexture(vol, ren, mem, view, use, origin, static_cast<float>(minZ), bytes.data());
}

void vtkTetRayCastMapper::WarnUnsupported(vtkVolumeProperty* p, vtkUnstructuredGrid* grid)
{
  // Said once each, as the property is read every frame: VTK's own unstructured-grid mappers
  // drop these without a word, which leaves a user wondering why the setting does nothing.
  if (!p)
  {
    return;
  }
  if (!p->GetIndependentComponents() && !(this->Warned & 4))
  {
    int cellFlag = 0;
    vtkDataArray* shown = vtkAbstractMapper::GetScalars(
      grid, this->ScalarMode, this->ArrayAccessMode, this->ArrayId, this->ArrayName, cellFlag);
    if (shown && shown->GetNumberOfComponents() > 1)
    {
      // VTK's image mappers then take the colour from the components themselves (RGBA, or a value
      // and its opacity); the mapper draws one scalar through the functions, a different image.
      this->Warned |= 4;
      vtkWarningMacro("the vtkVolumeProperty's IndependentComponents off (colour from the array's "
        << shown->GetNumberOfComponents()
        << " components themselves) is not supported: one scalar of them (VectorMode) is drawn through "
           "the colour and opacity functions");
    }
  }
  bool gradient = p->GetTransferFunctionMode() == vtkVolumeProperty::TF_2D;
  if (!gradient && p->HasGradientOpacity(0) && !p->GetDisableGradientOpacity(0))
  {
    // A set function that is not 1 everywhere (VTK's default) would change the image.
    vtkPiecewiseFunction* g = p->GetStoredGradientOpacity(0);
    double node[4];
    for (int i = 0; g && i < g->GetSize() && !gradient; ++i)
    {
      g->GetNodeValue(i, node);
      gradient = node[1] != 1.0;
    }
  }
  if (gradient && !(this->Warned & 2))
  {
    this->Warned |= 2;
    vtkWarningMacro("gradient opacity (SetGradientOpacity, or a 2-D transfer function) is not supported and is "
                    "ignored: opacity follows the scalar-opacity function only");
  }
}

void vtkTetRayCastMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ImageSampleDistance: " << this->ImageSampleDistance << "\n";
  os << indent << "AutoAdjustSampleDistances: " << this->AutoAdjustSampleDistances << " (from "
     << this->MinimumImageSampleDistance << " to " << this->MaximumImageSampleDistance << ")\n";
  os << indent << "EarlyRayTermination: " << this->EarlyRayTermination << "\n";
  os << indent << "TrapezoidRule: " << this->TrapezoidRule << "\n";
  os << indent << "IntermixIntersectingGeometry: " << this->IntermixIntersectingGeometry << "\n";
  os << indent << "VectorMode: " << this->VectorMode << " (component " << this->VectorComponent << ")\n";
  os << indent << "IsoSurfaces: " << this->Impl->Isos.size() << "\n";
  os << indent << "LabelColoring: " << this->LabelColoring << " (labels in cell array '"
     << (this->LabelArrayName ? this->LabelArrayName : "") << "')\n";
  os << indent << "LastRenderTime: " << this->LastRenderTime << "\n";
}

void vtkTetRayCastMapper::WarnUnsupported(vtkCamera* cam)
{
  if (!cam || (this->Warned & 8))
  {
    return;
  }
  std::string what;
  const double* shear = cam->GetViewShear();
  if ((shear[0] != 0.0 || shear[1] != 0.0) && cam->GetParallelProjection())
  {
    what = "view shear (SetViewShear) under parallel projection";
  }
  else if (cam->GetUseOffAxisProjection())
  {
    what = "off-axis projection";
  }
  else if (cam->GetUserTransform() || cam->GetUserViewTransform())
  {
    what = "user transform";
  }
  else if (!cam->GetModelTransformMatrix()->IsIdentity())
  {
    what = "model transform matrix";
  }
  else if (cam->GetStereo() && cam->GetParallelProjection() && cam->GetEyeAngle() != 0.0)
  {
    what = "stereo eye shear under parallel projection";
  }
  if (!what.empty())
  {
    this->Warned |= 8;
    vtkWarningMacro("the camera's " << what << " is not supported: the volume is drawn as without it, "
      "while opaque geometry follows it (position, focal point, view up, view angle, parallel scale, "
      "window centre, and a perspective camera's view shear and stereo eyes are followed)");
  }
}

void vtkTetRayCastMapper::FrameError(const std::string& message)
{
  if (message != this->Impl->LastError)
  {
    this->Impl->LastError = message;
    vtkErrorMacro(<< message);
  }
}
