// StreamCapture: while alive, what code writes to std::cerr and std::cout, and what VTK sends to
// its output window, goes into buffers instead of the terminal. VTK's MetaIO code prints its own
// lines to std::cerr (eight lines naming the wrong cause came before the one-line error), and the
// legacy readers warn of a file cut short only through the output window, from no object an
// observer could watch; the loaders keep the first and read the second.
#ifndef art_StreamCapture_h
#define art_StreamCapture_h

#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include <iostream>
#include <sstream>
#include <string>

namespace art
{
/// An output window that keeps the text it is given.
class CapturingOutputWindow : public vtkOutputWindow
{
public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override
  {
    if (text && Text.size() < 4096)
    {
      Text += text;
      Text += "\n";
    }
  }
  std::string Text;

protected:
  CapturingOutputWindow() = default;
};

class StreamCapture
{
public:
  StreamCapture();
  ~StreamCapture();
  StreamCapture(const StreamCapture&) = delete;
  StreamCapture& operator=(const StreamCapture&) = delete;
  /// What was written to std::cerr so far.
  std::string Errors() const { return Err.str(); }
  /// What VTK sent to its output window so far.
  std::string VtkMessages() const { return Window->Text; }

private:
  std::ostringstream Err, Out;
  std::streambuf* OldErr;
  std::streambuf* OldOut;
  vtkSmartPointer<vtkOutputWindow> OldWindow;
  int OldVerbosity = 0;
  vtkSmartPointer<CapturingOutputWindow> Window;
};
} // namespace art

#endif
