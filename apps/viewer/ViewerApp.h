// ViewerApp: the adaptivert-view window. Loads a volume, tet mesh or triangle scene; volumes are
// reduced to nested tet levels in a worker thread (ReductionWorker) whose progress a repeating
// interactor timer polls, swapping vtkTetRayCastMapper's input as levels arrive; keys and an
// optional script drive the controls (ViewerControls, ViewerScript).
#ifndef art_ViewerApp_h
#define art_ViewerApp_h

#include "ViewerOptions.h"

#include <memory>

namespace view
{
class ViewerApp
{
public:
  /// Loads the data and the script; throws art::Error naming the file for bad input.
  explicit ViewerApp(ViewerOptions options);
  ~ViewerApp();
  ViewerApp(const ViewerApp&) = delete;
  ViewerApp& operator=(const ViewerApp&) = delete;

  /// Opens the window and runs until it is closed (or the scripted screenshot is taken).
  /// Returns the exit code; run-time failures are printed as one line on stderr.
  int Run();

private:
  struct Internals;
  std::shared_ptr<void> XDisplay; ///< declared first: closed after every VTK object is gone
  std::unique_ptr<Internals> Impl;
};
} // namespace view

#endif
