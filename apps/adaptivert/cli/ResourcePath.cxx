#include "cli/ResourcePath.h"

#include <filesystem>

namespace fs = std::filesystem;

namespace cli
{
std::string ResourcePath(const std::string& sub, const std::string& source)
{
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec && exe.parent_path().filename() == "bin")
  {
    const fs::path installed = exe.parent_path().parent_path() / "share" / "adaptivert" / sub;
    if (fs::exists(installed, ec))
    {
      return installed.string();
    }
  }
  return source;
}

std::string DataDir()
{
  return ResourcePath("data", ART_DATA_DIR);
}
} // namespace cli
