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
// Keeps the first error a VTK object reports instead of letting it reach the output window.
struct ErrorCatcher
{
  std::string Message;
  vtkNew<vtkCallbackCommand> Cmd;

  explicit ErrorCatcher(vtkAlgorithm* alg)
  {
    Cmd->SetClientData(this);
    Cmd->SetCallback([](vtkObject*, unsigned long event, void* self, void* data) {
      auto* me = static_cast<ErrorCatcher*>(self);
      if (event == vtkCommand::ErrorEvent && me->Message.empty() && data)
      {
        me->Message = Clean(static_cast<const char*>(data));
      }
    });
    alg->AddObserver(vtkCommand::ErrorEvent, Cmd);
    alg->AddObserver(vtkCommand::WarningEvent, Cmd);
    alg->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, Cmd);
  }
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
      c = (c == '\n') ? ' ' : c;
    }
    return m;
  }
};

/// Throws art::Error naming `path` when it is missing, empty, or a folder (unless allowed).
void RequireFile(const std::string& path, bool allowDirectory);
/// Updates `reader`; its first error, or running out of memory, becomes an art::Error naming `path`.
void RunReader(vtkAlgorithm* reader, const std::string& path);

template <class Reader>
vtkSmartPointer<vtkAlgorithm> FileReader(const std::string& path)
{
  auto r = vtkSmartPointer<Reader>::New();
  r->SetFileName(path.c_str());
  return r;
}
} // namespace art

#endif
