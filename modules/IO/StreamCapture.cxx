#include "StreamCapture.h"

#include <vtkLogger.h>
#include <vtkObjectFactory.h>

#include <mutex>

namespace art
{
vtkStandardNewMacro(CapturingOutputWindow);

namespace
{
// Readers run in one thread at a time here; the viewer's worker may load while the window runs.
std::recursive_mutex& CaptureMutex()
{
  static std::recursive_mutex m;
  return m;
}
} // namespace

StreamCapture::StreamCapture()
  : OldErr(nullptr)
  , OldOut(nullptr)
{
  CaptureMutex().lock();
  OldErr = std::cerr.rdbuf(Err.rdbuf());
  OldOut = std::cout.rdbuf(Out.rdbuf());
  OldVerbosity = vtkLogger::GetCurrentVerbosityCutoff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // VTK's macros log there too
  OldWindow = vtkOutputWindow::GetInstance();
  Window = vtkSmartPointer<CapturingOutputWindow>::New();
  vtkOutputWindow::SetInstance(Window);
}

StreamCapture::~StreamCapture()
{
  vtkOutputWindow::SetInstance(OldWindow);
  vtkLogger::SetStderrVerbosity(static_cast<vtkLogger::Verbosity>(OldVerbosity));
  std::cerr.rdbuf(OldErr);
  std::cout.rdbuf(OldOut);
  CaptureMutex().unlock();
}
} // namespace art
