#include "AtomicFile.h"
#include "Error.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace art
{
std::string LowerExtension(const std::string& path)
{
  std::string name = fs::path(path).filename().string();
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  for (const char* twoPart : { ".nii.gz", ".vtk.gz" })
  {
    const std::string e(twoPart);
    if (name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0)
    {
      return e;
    }
  }
  const auto dot = name.rfind('.');
  return (dot == std::string::npos || dot == 0) ? std::string() : name.substr(dot);
}

AtomicFile::AtomicFile(std::string target)
  : Dest(std::move(target))
{
  static std::atomic<int> serial{ 0 };
  const fs::path p(Dest);
  const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
  {
    throw Error("folder '" + dir.string() + "' does not exist", Dest);
  }
  if (fs::is_directory(p, ec))
  {
    throw Error("is a directory, expected a file name", Dest);
  }
  if (access(dir.c_str(), W_OK) != 0)
  {
    throw Error("folder '" + dir.string() + "' is not writable", Dest);
  }
  const std::string ext = LowerExtension(Dest);
  Temp = (dir / ("." + p.filename().string() + ".tmp" + std::to_string(getpid()) + "-" +
            std::to_string(serial++) + ext))
           .string();
}

AtomicFile::~AtomicFile()
{
  if (!Done)
  {
    std::remove(Temp.c_str());
  }
}

void WriteFileAtomic(const std::string& path, const std::string& content)
{
  AtomicFile file(path);
  {
    std::ofstream out(file.TempPath(), std::ios::binary);
    out << content;
    out.flush();
    if (!out)
    {
      throw Error("cannot write file", path);
    }
  }
  file.Commit();
}

void AtomicFile::Commit()
{
  if (std::rename(Temp.c_str(), Dest.c_str()) != 0)
  {
    const std::string why = std::strerror(errno);
    std::remove(Temp.c_str());
    Done = true;
    throw Error("cannot replace file: " + why, Dest);
  }
  Done = true;
}
} // namespace art
