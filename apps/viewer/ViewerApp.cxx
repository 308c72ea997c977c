#include "ViewerApp.h"
#include "ViewerAppInternals.h"

#include "AtomicFile.h"
#include "Camera.h"
#include "DataLoader.h"
#include "DisplayCheck.h"
#include "Error.h"
#include "ImageIO.h"

#ifdef ART_HAVE_Reduction
#include "ReducerVTK.h"
#endif

#include <vtkCamera.h>
#include <vtkCoordinate.h>
#include <vtkImageData.h>
#include <vtkPlaneCollection.h>
#include <vtkProperty.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace view
{
ViewerApp::ViewerApp(ViewerOptions options)
  : Impl(new Internals)
{
  Impl->Opt = std::move(options);
  const ViewerOptions& o = Impl->Opt;
  const art::DataKind kind = art::KindOf(o.File, o.Load); // before loading: a large scene need not be read to say this
  if ((o.TetsGiven || o.Refinement != "bisection") && kind != art::DataKind::Volume)
  {
    // A mesh or a triangle scene is shown as it is: its --tets levels were ignored without a word.
    throw UsageError(std::string(o.TetsGiven ? "--tets sets" : "--refinement makes") + " the reduction levels of a volume; " +
      o.File + " is a " +
      (kind == art::DataKind::Surface ? "triangle scene" : "tet mesh") + ", shown as it is");
  }
  if (kind == art::DataKind::Surface && (!o.Array.empty() || o.TfGiven))
  {
    // A triangle scene is traced in its own colours: --array (even a name it lacks) and --tf were
    // ignored without a word; adaptivert render refuses them on a surface.
    throw UsageError(std::string(o.Array.empty() ? "--tf" : "--array") + " applies to volumes and meshes; " + o.File +
      " is a triangle scene, shown in its own colours");
  }
  art::LoadOptions load = o.Load;
  load.Array = o.Array;
  Impl->Scene = LoadScene(o.File, o.TransferFunction, load, o.LabelColours);
  Impl->Mapper->SetLabelColoring(vtkTetRayCastMapper::LABEL_COLORING_OFF); // the scene split the labels itself
  if (!Impl->Scene.Surface && !Impl->Scene.Image && !Impl->Scene.Note.empty())
  {
    Impl->Say(Impl->Scene.Note); // a mesh's: cells tetrahedralised or left out, points dropped or merged
  }
  Impl->MapperMessageCb->SetClientData(Impl.get());
  Impl->MapperMessageCb->SetCallback([](vtkObject*, unsigned long, void* self, void* data) {
    // VTK's text: "Warning: In FILE, line N\nvtkTetRayCastMapper (0x..): what\n\n"; keep "what".
    std::string text = data ? static_cast<const char*>(data) : "";
    const std::size_t at = text.find("): ");
    text = at == std::string::npos ? text : text.substr(at + 3);
    text.erase(text.find_last_not_of(" \n") + 1);
    static_cast<Internals*>(self)->Say(text);
  });
  Impl->Mapper->AddObserver(vtkCommand::WarningEvent, Impl->MapperMessageCb);
  Impl->Mapper->AddObserver(vtkCommand::ErrorEvent, Impl->MapperMessageCb);
  if (!Impl->Scene.ArrayName.empty())
  {
    // The mapper picks the same array by name from every level's grid: a mesh's cell array among
    // the cell data (looked for among the points, it was an error every frame and a blank view).
    Impl->Scene.ArrayOnCells ? Impl->Mapper->SetScalarModeToUseCellFieldData()
                             : Impl->Mapper->SetScalarModeToUsePointFieldData();
    Impl->Mapper->SelectScalarArray(Impl->Scene.ArrayName.c_str());
  }
  if (!Impl->Opt.Script.empty())
  {
    Impl->Script = ReadScript(Impl->Opt.Script);
    for (const ScriptAction& a : Impl->Script)
    {
      // Said now, not when the script gets there (after the whole reduction): an image type
      // that cannot be written, a missing or read-only folder.
      if (a.What == ScriptAction::Kind::Screenshot)
      {
        if (!art::IsImageExtension(a.Text))
        {
          throw art::Error("line " + std::to_string(a.Line) + ": screenshot '" + a.Text +
              "': unknown image type (use .png, .exr or .tif)",
            Impl->Opt.Script);
        }
        art::AtomicFile trial(a.Text); // its temporary file is removed as it goes
      }
    }
  }
  // A scripted or --screenshot run makes pictures of the data: the key help starts hidden there
  // (a script's 'key h' shows it). Opened by hand, the viewer shows it.
  Impl->State.Help = Impl->Opt.Script.empty() && Impl->Opt.Screenshot.empty();
  const double lo = Impl->Scene.Range[0], hi = Impl->Scene.Range[1];
  Impl->State.IsoStep = std::max((hi - lo) / 50.0, 1e-12);
  Impl->State.IsoValue = lo + 15 * Impl->State.IsoStep; // 30% of the range: bone on CT
  Impl->State.IsoLo = lo;
  Impl->State.IsoHi = hi;
#ifdef ART_HAVE_Reduction
  if (Impl->Scene.Image) // the voxel checks (NaN, 2-D, components) fail here, before any window
  {
    Impl->Worker = std::make_unique<ReductionWorker>(art::VolumeFromImage(Impl->Scene.Image, Impl->Opt.File),
      Budgets(Impl->Opt, Impl->Scene.Image->GetNumberOfPoints()),
      ReductionWorker::ShowingWith(Impl->Scene.Transfer, Impl->Opt.Refinement));
  }
#endif
}

ViewerApp::~ViewerApp() = default;

void ViewerApp::Internals::Say(const std::string& what)
{
  if (!what.empty() && Said.insert(what).second)
  {
    std::fprintf(stderr, "adaptivert-view: %s: %s\n", Opt.File.c_str(), what.c_str());
  }
}

int ViewerApp::Run()
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    std::fprintf(stderr, "adaptivert-view: no X display: set DISPLAY or run under xvfb-run -a\n");
    return 1;
  }
  XDisplay = OpenDisplay(); // VTK would crash on a display it cannot open
  if (!XDisplay)
  {
    std::fprintf(stderr, "adaptivert-view: cannot open X display '%s'\n", display);
    return 1;
  }
  Internals& I = *Impl;
  if (IsXDisplay(XDisplay))
  {
    I.Window->SetDisplayId(XDisplay.get()); // one connection, checked above, for window and interactor
  }
  I.SetupWindow();
#ifdef ART_HAVE_Reduction
  if (I.Worker)
  {
    I.Worker->Start();
    I.ReductionFinished = false;
  }
#endif
  if (!I.Scene.Levels.empty())
  {
    I.ShowLevel(0);
  }
  I.ApplySettings();
  I.Window->Render();
  I.Interactor->CreateRepeatingTimer(100);
  I.Interactor->Start();
#ifdef ART_HAVE_Reduction
  I.Worker.reset(); // cancels a reduction still running
#endif
  if (!I.Opt.Screenshot.empty() && !I.ScreenshotWritten && I.ExitCode == 0)
  {
    // Quit (`q`, a script's `key q`, the window closed) before the --screenshot was taken: it
    // exited 0 without the file and without a word.
    std::fprintf(stderr, "adaptivert-view: %s: not written: quit before the --screenshot was taken\n",
      I.Opt.Screenshot.c_str());
    return 1;
  }
  return I.ExitCode;
}

void ViewerApp::Internals::SetupWindow()
{
  Window->SetSize(Opt.Width, Opt.Height);
  Window->SetNumberOfLayers(2);
  Window->AddRenderer(Ren);
  Window->AddRenderer(Overlay);
  Window->SetWindowName(("adaptivert-view - " + Opt.File).c_str());
  Ren->SetBackground(0.08, 0.08, 0.1);
  // Edges and text go on a second layer with the same camera so the volume image (drawn as a
  // textured quad at the data's nearest depth) never hides them.
  Overlay->SetLayer(1);
  Overlay->InteractiveOff();
  Overlay->SetActiveCamera(Ren->GetActiveCamera());
  Interactor->SetRenderWindow(Window);
  Interactor->SetInteractorStyle(Style);
  Style->SetDefaultRenderer(Ren);
  Style->KeyHandler = [this](char k) { this->OnKey(k); };

  Volume->SetMapper(Mapper);
  Volume->SetProperty(Property);
  Scene.Transfer.ToVTK(Property);
  Edges->SetInputData(vtkNew<vtkUnstructuredGrid>());
  EdgeMapper->SetInputConnection(Edges->GetOutputPort());
  EdgeMapper->ScalarVisibilityOff();
  EdgeActor->SetMapper(EdgeMapper);
  EdgeActor->GetProperty()->SetColor(0.45, 0.85, 1.0);
  EdgeActor->VisibilityOff();
  Overlay->AddActor(EdgeActor);

  const int fs = std::max(10, std::min(18, Opt.Height / 26));
  auto place = [&](vtkTextActor* a, double x, double y, bool top) {
    a->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    a->GetPositionCoordinate()->SetValue(x, y);
    vtkTextProperty* p = a->GetTextProperty();
    p->SetFontFamilyToCourier();
    p->SetFontSize(fs);
    p->SetColor(0.95, 0.95, 0.9);
    p->SetBackgroundColor(0, 0, 0);
    p->SetBackgroundOpacity(0.45);
    p->SetVerticalJustification(top ? VTK_TEXT_TOP : VTK_TEXT_BOTTOM);
    Overlay->AddActor2D(a);
  };
  place(Help, 0.015, 0.985, true);
  place(Status, 0.015, 0.015, false);
  place(ProgressBar, 0.015, 0.015 + 1.6 * fs / Opt.Height, false);
  ProgressBar->SetInput(" ");
  ProgressBar->VisibilityOff(); // until a reduction reports

  if (Scene.Surface)
  {
    Scene.Surface->Attach(Ren);
  }
  ResetCamera();

  TimerCb->SetClientData(this);
  TimerCb->SetCallback([](vtkObject*, unsigned long, void* self, void*) { static_cast<Internals*>(self)->OnTimer(); });
  Interactor->Initialize();
  Interactor->AddObserver(vtkCommand::TimerEvent, TimerCb);
  // Fewer rays while the camera moves keeps the trackball smooth; full resolution when it stops.
  StartInteractCb->SetClientData(this);
  StartInteractCb->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    auto* I = static_cast<Internals*>(self);
    // Aim at ~12 frames a second from the last full-resolution frame's time (2x to 6x fewer rays per side).
    const double full = I->Scene.Surface ? I->Scene.Surface->LastTraceSeconds() : I->Mapper->GetLastRenderTime();
    const int d = std::max(2, std::min(6, static_cast<int>(std::ceil(std::sqrt(full / 0.08)))));
    I->Mapper->SetImageSampleDistance(static_cast<float>(d));
    if (I->Scene.Surface)
    {
      I->Scene.Surface->SetSampleDistance(d);
    }
  });
  EndInteractCb->SetClientData(this);
  EndInteractCb->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    auto* I = static_cast<Internals*>(self);
    I->Mapper->SetImageSampleDistance(1);
    if (I->Scene.Surface)
    {
      I->Scene.Surface->SetSampleDistance(1);
    }
    I->Dirty = true;
  });
  Style->AddObserver(vtkCommand::StartInteractionEvent, StartInteractCb);
  Style->AddObserver(vtkCommand::EndInteractionEvent, EndInteractCb);

  // The clipping plane: drawn faintly (it lies over the cut face); the left button on it pushes
  // it along its normal, on the arrow turns it, on the centre point slides it.
  ClipRep->SetPlaceFactor(1.0);
  ClipRep->GetPlaneProperty()->SetOpacity(0.08);
  ClipRep->GetSelectedPlaneProperty()->SetOpacity(0.15);
  ClipRep->OutlineTranslationOff(); // dragging the box would move the plane's frame, not the data
  ClipWidget->SetInteractor(Interactor);
  ClipWidget->SetRepresentation(ClipRep);
  ClipCb->SetClientData(this);
  ClipCb->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    auto* I = static_cast<Internals*>(self);
    I->ClipRep->GetPlane(I->ClipPlane);
  });
  ClipWidget->AddObserver(vtkCommand::InteractionEvent, ClipCb);
  ClipWidget->AddObserver(vtkCommand::StartInteractionEvent, StartInteractCb);
  ClipWidget->AddObserver(vtkCommand::EndInteractionEvent, EndInteractCb);
}

void ViewerApp::Internals::ResetCamera()
{
  vtkCamera* cam = Ren->GetActiveCamera();
  art::Camera::DefaultView(cam, Scene.Bounds); // the CLI's, flat data face on
  const int* size = Window->GetSize();
  // As `adaptivert render` frames it: the visible part to 85%; a flat, wide scene from above.
  const bool layout = Scene.Surface && art::Camera::LayoutView(Scene.Bounds);
  art::Camera::FrameObject(cam, Scene.Object, Scene.Bounds, 0.0, layout ? art::Camera::LayoutElevation : 0.0, 1.0,
    size[1] > 0 ? double(size[0]) / double(size[1]) : 1.0);
  double b[6] = { Scene.Bounds.lo.x, Scene.Bounds.hi.x, Scene.Bounds.lo.y, Scene.Bounds.hi.y, Scene.Bounds.lo.z,
    Scene.Bounds.hi.z };
  Ren->ResetCameraClippingRange(b);
  Dirty = true;
}

void ViewerApp::Internals::ShowLevel(int i)
{
  State.Level = i;
  Mapper->SetInputData(Scene.Levels[i]);
  Edges->SetInputData(Scene.Levels[i]);
  // Few tets: solid lines; many: a faint haze that is densest where the tets are small.
  const double tets = std::max<double>(1, Scene.Levels[i]->GetNumberOfCells());
  EdgeActor->GetProperty()->SetOpacity(std::min(0.9, std::max(0.08, std::sqrt(500.0 / tets))));
  if (!Ren->HasViewProp(Volume))
  {
    Ren->AddVolume(Volume);
  }
  ApplySettings();
}

void ViewerApp::Internals::ApplySettings()
{
  Mapper->SetEarlyRayTermination(State.Ert());
  Mapper->SetTrapezoidRule(State.Trapezoid);
  Volume->GetProperty()->SetShade(State.Shade ? 1 : 0);
  Mapper->RemoveAllIsoSurfaces();
  if (State.Iso)
  {
    Mapper->AddIsoSurface(State.IsoValue, 1.0, 0.92, 0.82, 1.0);
  }
  EdgeActor->SetVisibility(State.Edges && State.Level >= 0);
  ApplyClip();
  Help->SetInput(HelpText(State, IsTets()).c_str());
  Help->SetVisibility(State.Help);
  UpdateStatus();
  Dirty = true;
}

void ViewerApp::Internals::UpdateStatus()
{
  std::string s;
  if (Scene.Surface)
  {
    s = Scene.Note;
  }
  else if (State.Level < 0)
  {
    s = "waiting for the first tet level";
  }
  else
  {
    // While the reduction runs, out of the levels asked for, as its progress bar counts them.
    std::size_t total = Scene.Levels.size();
#ifdef ART_HAVE_Reduction
    if (Worker && !ReductionFinished)
    {
      total = std::max(total, Worker->NumberOfBudgets());
    }
#endif
    s = "level " + std::to_string(State.Level + 1) + "/" + std::to_string(total) + ": " + Scene.LevelLabels[State.Level];
  }
  Status->SetInput(s.c_str());
}

void ViewerApp::Internals::ApplyClip()
{
  if (!State.Clip || !IsTets())
  {
    Mapper->RemoveAllClippingPlanes();
    ClipWidget->Off();
    return;
  }
  if (!ClipPlaced)
  {
    // First shown through the middle, facing the camera: the near half goes and the cut face
    // looks at the viewer.
    const art::Box3& b = Scene.Bounds;
    double box[6] = { b.lo.x, b.hi.x, b.lo.y, b.hi.y, b.lo.z, b.hi.z };
    ClipRep->PlaceWidget(box);
    const art::Vec3 c = b.Center();
    ClipRep->SetOrigin(c.x, c.y, c.z);
    double d[3];
    Ren->GetActiveCamera()->GetDirectionOfProjection(d);
    ClipRep->SetNormal(d);
    ClipPlaced = true;
  }
  ClipRep->GetPlane(ClipPlane);
  if (!Mapper->GetClippingPlanes() || !Mapper->GetClippingPlanes()->IsItemPresent(ClipPlane))
  {
    Mapper->AddClippingPlane(ClipPlane);
  }
  ClipWidget->On();
}
} // namespace view
