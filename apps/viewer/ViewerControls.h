// ViewerControls: what the keys change (tet level, iso-value, early-termination threshold,
// integrator, mesh edges, help) as plain state, the on-screen help text, and the trackball
// interactor style that routes key presses to the viewer instead of VTK's default bindings.
#ifndef art_ViewerControls_h
#define art_ViewerControls_h

#include <vtkInteractorStyleTrackballCamera.h>

#include <functional>
#include <string>

namespace view
{
struct ViewerState
{
  int Level = -1;           ///< index of the shown tet level (-1: none yet)
  bool FollowNewest = true; ///< show each new level as it arrives until the user picks one
  bool Iso = false;
  double IsoValue = 0, IsoStep = 1;
  /// The data's range: + and - keep the iso-value in it (past it nothing is drawn).
  double IsoLo = -1e300, IsoHi = 1e300;
  int ErtIndex = 0;         ///< into ErtSteps()
  bool Trapezoid = false;
  bool Shade = false;       ///< light the volume by its gradient (vtkVolumeProperty::ShadeOn)
  bool Edges = false;
  bool Clip = false;        ///< a clipping plane widget cuts the volume
  bool Help = true;

  double Ert() const;
};

/// The early-termination thresholds `t` cycles through (1 = off).
const double* ErtSteps(int* count);

enum class KeyResult
{
  Ignored,
  Changed,     ///< rendering settings changed
  LevelChanged,
  Screenshot,
  ResetCamera,
  Quit
};

/// Applies one key to the state; `levels` is how many tet levels are ready.
KeyResult ApplyKey(ViewerState& s, char key, int levels);

/// The progress line once the reduction is done: "reduced: 3 levels from one run" ("1 level").
std::string ReducedText(int levels);

/// The key help (shown when s.Help), one line per control with its current value.
std::string HelpText(const ViewerState& s, bool volume);
} // namespace view

/**
 * Trackball camera whose key presses go to a callback (VTK's default keys -- wireframe,
 * stereo, fly-to, pick -- would fight the viewer's own). Mouse interaction is unchanged.
 */
class vtkViewerInteractorStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static vtkViewerInteractorStyle* New();
  vtkTypeMacro(vtkViewerInteractorStyle, vtkInteractorStyleTrackballCamera);

  std::function<void(char)> KeyHandler;

  void OnChar() override;
  void OnKeyPress() override {}
  void OnKeyRelease() override {}

protected:
  vtkViewerInteractorStyle() = default;
  ~vtkViewerInteractorStyle() override = default;

private:
  vtkViewerInteractorStyle(const vtkViewerInteractorStyle&) = delete;
  void operator=(const vtkViewerInteractorStyle&) = delete;
};

#endif
