// ReaderRun: a VTK reader run on a user's file with its errors caught and named after the file,
// shared by the volume loader (VolumeLoader.cxx) and the surface and mesh loaders (DataLoader.cxx).
#ifndef art_ReaderRun_h
#define art_ReaderRun_h

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <string>

namespace art
{
// Keeps the first error and the first warning a VTK object reports instead of letting them reach
// the output window.
struct ErrorCatcher
{
  std::string Message, Warning;
  vtkNew<vtkCallbackCommand> Cmd;

  explicit ErrorCatcher(vtkAlgorithm* alg)
  {
    Cmd->SetClientData(this);
    Cmd->SetCallback([](vtkObject*, unsigned long event, void* self, void* data) {
      auto* me = static_cast<ErrorCatcher*>(self);
      std::string& keep = event == vtkCommand::ErrorEvent ? me->Message : me->Warning;
      if (keep.empty() && data)
      {
        keep = Clean(static_cast<const char*>(data));
      }
    });
    alg->AddObserver(vtkCommand::ErrorEvent, Cmd);
    alg->AddObserver(vtkCommand::WarningEvent, Cmd);
    alg->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, Cmd);
  }
  /// The executive's "Algorithm ... returned failure for request: vtkInformation (0x..) ..." names
  /// no cause (a dump of the request followed); the algorithm's own message comes first.
  static bool IsRequestDump(const std::string& m) { return m.find("returned failure for request") != std::string::npos; }
  // VTK messages carry "ERROR: In file, line N\nclass (0x..): text"; keep only the text.
  static std::string Clean(std::string m)
  {
    auto p = m.rfind("): ");
    if (p != std::string::npos)
    {
      m = m.substr(p + 3);
    }
    while (!m.empty() && (m.back() == '\n' || m.back() == ' ' || m.back() == '\r'))
    {
      m.pop_back();
    }
    for (char& c : m)
    {
      c = (c == '\n' || c == '\r' || c == '\t') ? ' ' : c;
    }
    return m.size() > 300 ? m.substr(0, 300) + "..." : m;
  }
};

/// Throws art::Error naming `path` when it is missing, empty, or a folder (unless allowed).
void RequireFile(const std::string& path, bool allowDirectory);
/// Updates `reader`; its first error, a warning that data could not be read (VTK's legacy
/// readers only warn of a file cut short), or running out of memory, becomes an art::Error
/// naming `path`. What VTK code prints to std::cerr meanwhile is kept off the terminal.
void RunReader(vtkAlgorithm* reader, const std::string& path);
/// UpdateInformation on `reader` (a header read), its first error an art::Error naming `path`.
void RunReaderInformation(vtkAlgorithm* reader, const std::string& path);
/// The reader of a legacy .vtk file for the data set its header names (vtkDataSetReader runs an
/// inner reader whose errors and warnings no observer of its own sees).
vtkSmartPointer<vtkAlgorithm> LegacyReader(const std::string& path);

template <class Reader>
vtkSmartPointer<vtkAlgorithm> FileReader(const std::string& path)
{
  auto r = vtkSmartPointer<Reader>::New();
  r->SetFileName(path.c_str());
  return r;
}
} // namespace art

#endif
