// adaptivert-view: the interactive viewer. `adaptivert-view [options] FILE`.
// Errors: one line "adaptivert-view: <file>: <what>" on stderr, exit 1; usage errors exit 2.
#include "AtomicFile.h"
#include "Error.h"
#include "ViewerApp.h"
#include "ViewerOptions.h"

#include <vtkLogger.h>
#include <vtkOutputWindow.h>

#include <cstdio>
#include <exception>
#include <string>
#include <vector>

int main(int argc, char** argv)
{
  view::ViewerOptions opt;
  try
  {
    opt = view::ParseOptions(std::vector<std::string>(argv + 1, argv + argc));
  }
  catch (const view::UsageError& e)
  {
    std::fprintf(stderr, "adaptivert-view: %s (try 'adaptivert-view --help')\n", e.what());
    return 2;
  }
  if (opt.Help)
  {
    std::printf("%s", view::UsageText().c_str());
    return 0;
  }
  // VTK's readers and parsers report through its output window and logger (a coloured
  // "ERR| vtkXMLDataParser (0x...)" line before ours for a damaged .vti/.vtu/.vtp); the viewer
  // reports in one line itself, as adaptivert does, and takes the mapper's messages by observer.
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  try
  {
    if (!opt.Screenshot.empty())
    {
      // A --screenshot that cannot be written (its folder missing or read-only) is said before
      // the window opens, not after the whole reduction. The trial file is removed as it goes.
      art::AtomicFile trial(opt.Screenshot);
    }
    view::ViewerApp app(opt);
    return app.Run();
  }
  catch (const view::UsageError& e) // one that needs the file read first (--tets on a mesh)
  {
    std::fprintf(stderr, "adaptivert-view: %s (try 'adaptivert-view --help')\n", e.what());
    return 2;
  }
  catch (const art::Error& e)
  {
    std::fprintf(stderr, "adaptivert-view: %s\n", e.what());
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "adaptivert-view: %s: %s\n", opt.File.c_str(), e.what());
  }
  return 1;
}
