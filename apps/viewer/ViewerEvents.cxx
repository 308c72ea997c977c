// ViewerApp's event side: keys, the repeating timer that polls the background reduction and
// steps the script, mouse drags for scripts, and screenshots (written atomically).
#include "ViewerAppInternals.h"

#include "Error.h"
#include "ImageIO.h"
#include "VTKImageConvert.h"

#ifdef ART_HAVE_Reduction
#include "ReducerVTK.h"
#endif

#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>

#include <cstdio>
#include <filesystem>

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
      // --screenshot names the file; otherwise the first free adaptivert-view-N.png here.
      std::string path = Opt.Screenshot;
      for (int n = 1; path.empty(); ++n)
      {
        const std::string candidate = "adaptivert-view-" + std::to_string(n) + ".png";
        if (!std::filesystem::exists(candidate))
        {
          path = candidate;
        }
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
    ScreenshotWritten = ScreenshotWritten || path == Opt.Screenshot;
    return true;
  }
  catch (const art::Error& e)
  {
    std::fprintf(stderr, "adaptivert-view: %s\n", e.what());
    return false;
  }
}

void ViewerApp::Internals::Drag(int dx, int dy)
{
  // The same events a mouse sends, so the trackball style (and its fast-while-moving
  // resolution switch) is what moves the camera.
  const int* size = Window->GetSize();
  const int x0 = size[0] / 2, y0 = size[1] / 2, steps = 8;
  Interactor->SetEventInformation(x0, y0);
  Interactor->InvokeEvent(vtkCommand::LeftButtonPressEvent);
  for (int k = 1; k <= steps; ++k)
  {
    Interactor->SetEventInformation(x0 + dx * k / steps, y0 + dy * k / steps);
    Interactor->InvokeEvent(vtkCommand::MouseMoveEvent);
  }
  Interactor->InvokeEvent(vtkCommand::LeftButtonReleaseEvent);
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
    // A budget past what the volume holds (or needs) stops at the same mesh as the one before:
    // said once, and not shown as another level (a 2 x 2 x 2 volume had '3 levels' of 6 tets).
    if (!m.TargetReached && m.TargetTets > 0)
    {
      std::fprintf(stderr, "adaptivert-view: %s: note: %lld tets not reached: the reduction stopped at %lld, the finest "
        "this volume allows or needs\n", Opt.File.c_str(), m.TargetTets, static_cast<long long>(m.NumberOfTets()));
    }
    if (!Scene.Levels.empty() && Scene.Levels.back()->GetNumberOfCells() == m.NumberOfTets())
    {
      continue;
    }
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
    bar = st.Error.empty() ? ReducedText(static_cast<int>(Scene.Levels.size())) : "reduction failed: " + st.Error;
    char note[96];
    std::snprintf(note, sizeof note, ", %zu level%s reduced in %.2f s", Scene.Levels.size(),
      Scene.Levels.size() == 1 ? "" : "s", st.Seconds);
    ReductionNote = note;
    TitleFrameSeconds = -1;
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
    // Relocation runs at each level the refinement emits, with its own 0 -> 100%.
    bar = std::string(st.Relocating ? "relocating level " + std::to_string(st.LevelsReady + 1) + " [" : "reducing [") +
      std::string(filled, '#') + std::string(20 - filled, '.') + "] " + std::to_string(percent) +
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
        if (Quitting)
        {
          // `key q` ends the script: the actions after it ran on a window that was closing
          // (their screenshots written after the quit).
          ++ScriptPos;
          return;
        }
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
      case ScriptAction::Kind::Drag:
        Drag(static_cast<int>(a.Value), static_cast<int>(a.Value2));
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
    const bool ok = Screenshot(Opt.Screenshot);
    if (ok)
    {
      // The figures a scripted run is for; the picture itself carries no timings.
      const double frame = Scene.Surface ? Scene.Surface->LastTraceSeconds() : Mapper->GetLastRenderTime();
      std::printf("adaptivert-view: wrote %s (%d x %d, last frame %.1f ms%s)\n", Opt.Screenshot.c_str(),
        Window->GetSize()[0], Window->GetSize()[1], frame * 1e3, ReductionNote.empty() ? "" : ReductionNote.c_str());
    }
    Quit(ok ? 0 : 1);
  }
}

void ViewerApp::Internals::UpdateTitle()
{
  // Timings go to the title bar, not into the picture: screenshots stay deterministic.
  const double frame = Scene.Surface ? Scene.Surface->LastTraceSeconds() : Mapper->GetLastRenderTime();
  if (frame == TitleFrameSeconds)
  {
    return;
  }
  TitleFrameSeconds = frame;
  char title[512];
  std::snprintf(title, sizeof title, "adaptivert-view - %s - %.1f ms/frame%s", Opt.File.c_str(), frame * 1e3,
    ReductionNote.c_str());
  Window->SetWindowName(title);
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
  UpdateTitle();
}
} // namespace view
