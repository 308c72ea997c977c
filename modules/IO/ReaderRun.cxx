#include "ReaderRun.h"
#include "Error.h"

#include <filesystem>
#include <new>

namespace fs = std::filesystem;

namespace art
{
void RequireFile(const std::string& path, bool allowDirectory)
{
  std::error_code ec;
  if (path.empty())
  {
    throw Error("empty file name");
  }
  if (!fs::exists(path, ec))
  {
    throw Error("no such file or directory", path);
  }
  if (fs::is_directory(path, ec) && !allowDirectory)
  {
    throw Error("is a directory, expected a file", path);
  }
  if (!fs::is_directory(path, ec) && fs::file_size(path, ec) == 0)
  {
    throw Error("file is empty", path);
  }
}

void RunReader(vtkAlgorithm* reader, const std::string& path)
{
  ErrorCatcher catcher(reader);
  try
  {
    reader->Update();
  }
  catch (const std::bad_alloc&)
  {
    throw Error("out of memory while reading it (are the header's sizes right?)", path);
  }
  // VTK's XML readers call a data set of no points and no cells (as VTK writes an empty
  // vtkUnstructuredGrid or vtkPolyData) an error; the callers say plainly that it holds nothing.
  if (!catcher.Message.empty() && catcher.Message.rfind("No Points element available", 0) != 0)
  {
    throw Error("cannot read: " + catcher.Message, path);
  }
}
} // namespace art
