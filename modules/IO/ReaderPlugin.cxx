#include "ReaderPlugin.h"
#include "Error.h"

#include <dlfcn.h>

#include <filesystem>
#include <mutex>

namespace art
{
vtkSmartPointer<vtkAlgorithm> PluginReader(const std::string& format, const std::string& path)
{
  static ArtNewReaderFunction create = nullptr;
  static std::string failure;
  static std::once_flag once;
  std::call_once(once, [] {
    Dl_info info{};
    std::string file = ART_READERS_PLUGIN;
    if (dladdr(reinterpret_cast<void*>(&PluginReader), &info) && info.dli_fname)
    {
      file = (std::filesystem::path(info.dli_fname).parent_path() / ART_READERS_PLUGIN).string();
    }
    void* lib = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!lib)
    {
      const char* e = dlerror();
      failure = std::string("cannot load the readers plug-in: ") + (e ? e : file.c_str());
      return;
    }
    create = reinterpret_cast<ArtNewReaderFunction>(dlsym(lib, "ArtNewReader"));
    failure = create ? "" : "the readers plug-in " + file + " lacks its function";
  });
  if (!create)
  {
    throw Error(failure, path);
  }
  std::string error;
  vtkAlgorithm* r = create(format.c_str(), path.c_str(), error);
  if (!r)
  {
    throw Error(error, path);
  }
  return vtkSmartPointer<vtkAlgorithm>::Take(r);
}
} // namespace art
