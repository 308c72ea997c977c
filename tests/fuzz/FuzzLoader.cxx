// A libFuzzer target for one loader: each input becomes a file of the loader's extension (or
// the one file of a DICOM folder) and goes through art::Load, as `adaptivert info` reads it. An
// art::Error is the right answer to a bad file; a crash, a sanitizer report, a hang (-timeout)
// or a blown memory limit is a finding. ART_FUZZ_EXT names the extension (".mha", "dicom").
#include "DataLoader.h"
#include "Error.h"

#include <vtkLogger.h>
#include <vtkObject.h>
#include <vtkOutputWindow.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <new>
#include <string>

#include <unistd.h>

namespace fs = std::filesystem;

namespace
{
std::string InputPath()
{
  static const std::string path = [] {
    const fs::path dir = fs::temp_directory_path() / ("art-fuzz-" + std::to_string(getpid()));
    fs::create_directories(dir);
    const std::string ext = ART_FUZZ_EXT;
    if (ext == "dicom")
    {
      fs::create_directories(dir / "series");
      return (dir / "series" / "slice.dcm").string();
    }
    return (dir / ("input" + ext)).string();
  }();
  return path;
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  vtkObject::GlobalWarningDisplayOff();
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string path = InputPath();
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  const std::string ext = ART_FUZZ_EXT;
  try
  {
    art::Load(ext == "dicom" ? fs::path(path).parent_path().string() : path);
  }
  catch (const art::Error&)
  {
  }
  catch (const std::bad_alloc&)
  {
  }
  return 0;
}
