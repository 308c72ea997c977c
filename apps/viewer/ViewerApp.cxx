#include "ViewerApp.h"

#include "Camera.h"
#include "DataLoader.h"
#include "Error.h"
#include "ImageIO.h"
#include "SurfaceTraceView.h"
#include "TetMesh.h"
#include "TransferFunction.h"
#include "VTKImageConvert.h"
#include "ViewerControls.h"
#include "ViewerScene.h"
#include "ViewerScript.h"
#include "vtkTetRayCastMapper.h"

#ifdef ART_HAVE_Reduction
#include "ReducerVTK.h"
#include "ReductionWorker.h"
#endif

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCoordinate.h>
#include <vtkExtractEdges.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>
#include <vtkWindowToImageFilter.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace view
{
struct ViewerApp::Internals
{
  ViewerOptions Opt;
  ViewerScene Scene;
  std::vector<ScriptAction> Script;
  std::size_t ScriptPos = 0;
  double WaitUntil = -1;
#ifdef ART_HAVE_Reduction
  std::unique_ptr<ReductionWorker> Worker;
#endif
  bool ReductionFinished = true;
  int LastPercent = -1;
  double LastProgressRender = -1;
  ViewerState State;

  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Ren, Overlay;
  vtkNew<vtkRenderWindowInteractor> Interactor;
  vtkNew<vtkViewerInteractorStyle> Style;
  vtkNew<vtkTetRayCastMapper> Mapper;
  vtkNew<vtkVolume> Volume;
  vtkNew<vtkVolumeProperty> Property;
  vtkNew<vtkExtractEdges> Edges;
  vtkNew<vtkPolyDataMapper> EdgeMapper;
  vtkNew<vtkActor> EdgeActor;
  vtkNew<vtkTextActor> Help, Status, ProgressBar;
  vtkNew<vtkCallbackCommand> TimerCb, StartInteractCb, EndInteractCb;
  std::chrono::steady_clock::time_point T0 = std::chrono::steady_clock::now();
  bool Dirty = false, Quitting = false;
  int ExitCode = 0;

  double Now() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - T0).count(); }
  bool IsTets() const { return !Scene.Surface; }
  void Quit(int code)
  {
    ExitCode = code;
    Quitting = true;
    Interactor->TerminateApp();
  }

  void SetupWindow();
  void OnKey(char k);
  void OnTimer();
  void PollReduction();
  void StepScript();
  void ShowLevel(int i);
  void ApplySettings();
  void UpdateStatus();
  void ResetCamera();
  bool Screenshot(const std::string& path);
};

ViewerApp::ViewerApp(ViewerOptions options)
  : Impl(new Internals)
{
  Impl->Opt = std::move(options);
  Impl->Scene = LoadScene(Impl->Opt.File, Impl->Opt.TransferFunction);
  if (!Impl->Opt.Script.empty())
  {
    Impl->Script = ReadScript(Impl->Opt.Script);
  }
  const double lo = Impl->Scene.Range[0], hi = Impl->Scene.Range[1];
  Impl->State.IsoStep = std::max((hi - lo) / 50.0, 1e-12);
  Impl->State.IsoValue = lo + 15 * Impl->State.IsoStep; // 30% of the range: bone on CT
}

ViewerApp::~ViewerApp() = default;

int ViewerApp::Run()
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    std::fprintf(stderr, "adaptivert-view: no X display: set DISPLAY or run under xvfb-run -a\n");
    return 1;
  }
  Internals& I = *Impl;
  I.SetupWindow();
#ifdef ART_HAVE_Reduction
  if (I.Scene.Image)
  {
    I.Worker = std::make_unique<ReductionWorker>(art::VolumeFromImage(I.Scene.Image, I.Opt.File), I.Opt.Tets);
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
  EdgeActor->GetProperty()->SetOpacity(0.12); // dense levels read as a haze, densest where tets are small
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
  // Half the rays per side while the camera moves keeps the trackball smooth.
  StartInteractCb->SetClientData(this);
  StartInteractCb->SetCallback([](vtkObject*, unsigned long, void* self, void*) {
    auto* I = static_cast<Internals*>(self);
    I->Mapper->SetImageSampleDistance(2);
    if (I->Scene.Surface)
    {
      I->Scene.Surface->SetSampleDistance(2);
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
}

void ViewerApp::Internals::ResetCamera()
{
  vtkCamera* cam = Ren->GetActiveCamera();
  cam->SetPosition(0, -1, 0); // the CLI's default view: from the front, z up
  cam->SetFocalPoint(0, 0, 0);
  cam->SetViewUp(0, 0, 1);
  art::Camera::Frame(cam, Scene.Bounds);
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
  Mapper->RemoveAllIsoSurfaces();
  if (State.Iso)
  {
    Mapper->AddIsoSurface(State.IsoValue, 1.0, 0.92, 0.82, 1.0);
  }
  EdgeActor->SetVisibility(State.Edges && State.Level >= 0);
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
    s = "level " + std::to_string(State.Level + 1) + "/" + std::to_string(Scene.Levels.size()) + ": " +
      Scene.LevelLabels[State.Level];
  }
  Status->SetInput(s.c_str());
}
} // namespace view

namespace view
{
void ViewerApp::Internals::OnKey(char k)
{
  if (Scene.Surface && std::string("srhqe\x1b").find(k) == std::string::npos)
  {
    return; // the tet controls mean nothing for a triangle scene
  }
  switch (ApplyKey(State, k, static_cast<int>(Scene.Levels.size())))
  {
    case KeyResult::Ignored:
      return;
    case KeyResult::LevelChanged:
      ShowLevel(State.Level);
      break;
    case KeyResult::Changed:
      ApplySettings();
      break;
    case KeyResult::ResetCamera:
      ResetCamera();
      break;
    case KeyResult::Screenshot:
    {
      std::string path = Opt.Screenshot;
      for (int n = 1; path.empty() || (path == Opt.Screenshot ? false : std::filesystem::exists(path)); ++n)
      {
        path = "adaptivert-view-" + std::to_string(n) + ".png";
      }
      if (Screenshot(path))
      {
        std::printf("adaptivert-view: wrote %s\n", path.c_str());
      }
      break;
    }
    case KeyResult::Quit:
      Quit(0);
      return;
  }
  if (Dirty)
  {
    Dirty = false;
    Window->Render();
  }
}

bool ViewerApp::Internals::Screenshot(const std::string& path)
{
  try
  {
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(Window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->ShouldRerenderOn();
    grab->Update();
    art::WriteImage(art::FromVTKImage(grab->GetOutput()), path); // atomic: temp file + rename
    return true;
  }
  catch (const art::Error& e)
  {
    std::fprintf(stderr, "adaptivert-view: %s\n", e.what());
    return false;
  }
}

void ViewerApp::Internals::PollReduction()
{
#ifdef ART_HAVE_Reduction
  if (!Worker || ReductionFinished)
  {
    return;
  }
  const ReductionWorker::Status st = Worker->Poll();
  for (const art::ReducedMesh& m : Worker->TakeLevels())
  {
    Scene.AddLevel(art::ToUnstructuredGrid(m), m.NumberOfTets(), m.Rms);
    if (State.FollowNewest)
    {
      ShowLevel(static_cast<int>(Scene.Levels.size()) - 1);
    }
    else
    {
      UpdateStatus();
    }
    Dirty = true;
  }
  const int percent = static_cast<int>(st.Fraction * 100);
  std::string bar;
  if (st.Finished)
  {
    ReductionFinished = true;
    bar = st.Error.empty() ? "reduced: " + std::to_string(Scene.Levels.size()) + " nested levels from one run"
                           : "reduction failed: " + st.Error;
    char title[256];
    std::snprintf(title, sizeof title, "adaptivert-view - %s - reduced in %.2f s", Opt.File.c_str(), st.Seconds);
    Window->SetWindowName(title);
    if (!st.Error.empty())
    {
      std::fprintf(stderr, "adaptivert-view: %s: reduction failed: %s\n", Opt.File.c_str(), st.Error.c_str());
      if (!Opt.Screenshot.empty())
      {
        Quit(1);
      }
    }
    Dirty = true;
  }
  else if (percent != LastPercent && Now() - LastProgressRender > 0.5)
  {
    // Every redraw re-casts the volume, so the bar is redrawn at most twice a second.
    const int filled = percent / 5;
    bar = "reducing [" + std::string(filled, '#') + std::string(20 - filled, '.') + "] " + std::to_string(percent) +
      "%, " + std::to_string(st.LevelsReady) + "/" + std::to_string(Worker->NumberOfBudgets()) + " levels";
    LastPercent = percent;
    LastProgressRender = Now();
    Dirty = true;
  }
  if (!bar.empty())
  {
    ProgressBar->SetInput(bar.c_str());
    ProgressBar->VisibilityOn();
  }
#endif
}

void ViewerApp::Internals::StepScript()
{
  while (ScriptPos < Script.size())
  {
    const ScriptAction& a = Script[ScriptPos];
    vtkCamera* cam = Ren->GetActiveCamera();
    switch (a.What)
    {
      case ScriptAction::Kind::Wait:
        if (WaitUntil < 0)
        {
          WaitUntil = Now() + a.Value;
        }
        if (Now() < WaitUntil)
        {
          return;
        }
        WaitUntil = -1;
        break;
      case ScriptAction::Kind::WaitReduction:
        if (!ReductionFinished)
        {
          return;
        }
        break;
      case ScriptAction::Kind::Key:
        OnKey(a.Text[0]);
        break;
      case ScriptAction::Kind::Azimuth:
        cam->Azimuth(a.Value);
        break;
      case ScriptAction::Kind::Elevation:
        cam->Elevation(a.Value);
        cam->OrthogonalizeViewUp();
        break;
      case ScriptAction::Kind::Roll:
        cam->Roll(a.Value);
        break;
      case ScriptAction::Kind::Zoom:
        cam->Zoom(a.Value);
        break;
      case ScriptAction::Kind::Screenshot:
        if (!Screenshot(a.Text))
        {
          Quit(1);
          return;
        }
        break;
    }
    if (a.What >= ScriptAction::Kind::Azimuth && a.What <= ScriptAction::Kind::Zoom)
    {
      Ren->ResetCameraClippingRange();
      Dirty = true;
    }
    ++ScriptPos;
  }
  // The script is done (or there is none): --screenshot waits for the reduction, then exits.
  if (!Opt.Screenshot.empty() && ReductionFinished && !Quitting)
  {
    Window->Render();
    Quit(Screenshot(Opt.Screenshot) ? 0 : 1);
  }
}

void ViewerApp::Internals::OnTimer()
{
  if (Quitting)
  {
    return;
  }
  PollReduction();
  StepScript();
  if (Dirty)
  {
    Dirty = false;
    Window->Render();
  }
}
} // namespace view
