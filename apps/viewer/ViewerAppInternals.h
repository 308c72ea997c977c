// ViewerAppInternals: the state and VTK objects behind ViewerApp, shared by ViewerApp.cxx
// (window and scene set-up) and ViewerEvents.cxx (keys, timer, script, screenshots). Private.
#ifndef art_ViewerAppInternals_h
#define art_ViewerAppInternals_h

#include "ViewerApp.h"
#include "ViewerControls.h"
#include "ViewerScene.h"
#include "ViewerScript.h"
#include "vtkTetRayCastMapper.h"

#ifdef ART_HAVE_Reduction
#include "ReductionWorker.h"
#endif

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkExtractEdges.h>
#include <vtkImplicitPlaneRepresentation.h>
#include <vtkImplicitPlaneWidget2.h>
#include <vtkNew.h>
#include <vtkPlane.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkVolume.h>
#include <vtkVolumeProperty.h>

#include <chrono>
#include <memory>
#include <set>
#include <string>
#include <vector>

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
  std::string ReductionNote; ///< "reduced in 3.2 s", for the window title
  double TitleFrameSeconds = -1;

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
  // The mapper's warnings and errors as one line each, once ("adaptivert-view: FILE: what"),
  // instead of VTK's log lines; the mesh's note is said at load, so the mapper's copy is not.
  vtkNew<vtkCallbackCommand> MapperMessageCb;
  std::set<std::string> Said;
  void Say(const std::string& what);
  // The `c` key's clipping plane: the widget's plane is copied into ClipPlane, which the mapper
  // holds, at every move (the mapper cuts its rays, so dragging costs no rebuild).
  vtkNew<vtkImplicitPlaneRepresentation> ClipRep;
  vtkNew<vtkImplicitPlaneWidget2> ClipWidget;
  vtkNew<vtkPlane> ClipPlane;
  vtkNew<vtkCallbackCommand> ClipCb;
  bool ClipPlaced = false;
  std::chrono::steady_clock::time_point T0 = std::chrono::steady_clock::now();
  bool Dirty = false, Quitting = false;
  bool ScreenshotWritten = false; ///< the --screenshot file was written (by the end of the script or `s`)
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
  void UpdateTitle();
  void StepScript();
  void ShowLevel(int i);
  void ApplySettings();
  void ApplyClip();
  void UpdateStatus();
  void ResetCamera();
  bool Screenshot(const std::string& path);
  void Drag(int dx, int dy);
};
} // namespace view

#endif
