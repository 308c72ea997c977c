#include "ImageIO.h"
#include "AtomicFile.h"
#include "Error.h"
#include "OiioImageIO.h"

#include <vtkErrorCode.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>

namespace art
{
namespace
{
struct OiioPlugin
{
  ArtOiioWrite write = nullptr;
  ArtOiioRead read = nullptr;
  std::string error;
};

// Loaded once, on the first image that is not a PNG; from the folder this library is in.
const OiioPlugin& Oiio()
{
  static OiioPlugin plugin;
  static std::once_flag once;
  std::call_once(once, [] {
    Dl_info info{};
    std::string file = ART_OIIO_PLUGIN;
    if (dladdr(reinterpret_cast<void*>(&WriteImage), &info) && info.dli_fname)
    {
      file = (std::filesystem::path(info.dli_fname).parent_path() / ART_OIIO_PLUGIN).string();
    }
    void* lib = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!lib)
    {
      const char* e = dlerror();
      plugin.error = std::string("cannot load the OpenImageIO plug-in: ") + (e ? e : file.c_str());
      return;
    }
    plugin.write = reinterpret_cast<ArtOiioWrite>(dlsym(lib, "ArtOiioWriteImage"));
    plugin.read = reinterpret_cast<ArtOiioRead>(dlsym(lib, "ArtOiioReadImage"));
    if (!plugin.write || !plugin.read)
    {
      plugin.error = "the OpenImageIO plug-in " + file + " lacks its functions";
    }
  });
  if (!plugin.error.empty())
  {
    throw Error(plugin.error);
  }
  return plugin;
}

// 8-bit RGBA, straight colour, through VTK's libpng writer (rows bottom-up in VTK).
void WritePng(const Image& img, const std::string& file, const std::string& path)
{
  const int w = img.Width(), h = img.Height();
  vtkNew<vtkImageData> data;
  data->SetDimensions(w, h, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  auto* px = static_cast<unsigned char*>(data->GetScalarPointer());
  for (int y = 0; y < h; ++y)
  {
    const float* s = img.Pixel(0, y);
    unsigned char* d = px + 4 * static_cast<size_t>(h - 1 - y) * w;
    for (int i = 0; i < 4 * w; ++i)
    {
      const float v = s[i] >= 0.f ? std::min(s[i], 1.f) : 0.f; // NaN -> 0
      d[i] = static_cast<unsigned char>(std::lround(v * 255.f));
    }
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(data);
  writer->SetFileName(file.c_str());
  writer->AddText("Software", "AdaptiveRT");
  // zlib level 2 instead of VTK's 5: several times faster for files a little larger, so a batch
  // of frames does not spend as long writing as rendering.
  writer->SetCompressionLevel(2);
  writer->Write();
  if (writer->GetErrorCode() != vtkErrorCode::NoError)
  {
    throw Error(writer->GetErrorCode() == vtkErrorCode::OutOfDiskSpaceError
        ? std::string("cannot write image: no space left on device")
        : std::string("cannot write image: ") + vtkErrorCode::GetStringFromErrorCode(writer->GetErrorCode()),
      path);
  }
}

// 8- or 16-bit grey, grey-alpha, RGB or RGBA (VTK expands palettes and low bit depths).
bool ReadPng(const std::string& path, Image& img)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return false;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkImageData* data = reader->GetOutput();
  vtkDataArray* a = data ? data->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (data)
  {
    data->GetDimensions(dims);
  }
  if (reader->GetErrorCode() != vtkErrorCode::NoError || !a || dims[0] <= 0 || dims[1] <= 0)
  {
    return false;
  }
  const int nc = a->GetNumberOfComponents(), w = dims[0], h = dims[1];
  const double scale = a->GetDataType() == VTK_UNSIGNED_SHORT ? 1.0 / 65535.0 : 1.0 / 255.0;
  img = Image(w, h, { 0.f, 0.f, 0.f, 1.f });
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const vtkIdType id = static_cast<vtkIdType>(h - 1 - y) * w + x;
      float* d = img.Pixel(x, y);
      for (int c = 0; c < 3; ++c)
      {
        d[c] = static_cast<float>(a->GetComponent(id, nc < 3 ? 0 : c) * scale);
      }
      if (nc == 2 || nc == 4)
      {
        d[3] = static_cast<float>(a->GetComponent(id, nc - 1) * scale);
      }
    }
  }
  return true;
}
}

bool IsImageExtension(const std::string& path)
{
  const std::string e = LowerExtension(path);
  return e == ".png" || e == ".exr" || e == ".tif" || e == ".tiff";
}

void WriteImage(const Image& img, const std::string& path)
{
  if (!IsImageExtension(path))
  {
    throw Error("unknown image type '" + LowerExtension(path) + "' (use .png, .exr or .tif)", path);
  }
  if (img.Empty())
  {
    throw Error("refusing to write an empty image", path);
  }
  AtomicFile file(path);
  const std::string ext = LowerExtension(path);
  if (ext == ".png")
  {
    WritePng(img, file.TempPath(), path);
  }
  else
  {
    std::string error;
    if (!Oiio().write(img, file.TempPath().c_str(), ext.c_str(), error))
    {
      throw Error(error, path);
    }
  }
  file.Commit();
}

Image ReadImage(const std::string& path)
{
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
  {
    throw Error("no such file", path);
  }
  if (std::filesystem::is_directory(path, ec))
  {
    throw Error("is a directory, expected an image file", path);
  }
  Image img;
  if (ReadPng(path, img))
  {
    return img;
  }
  std::string error;
  if (!Oiio().read(path.c_str(), img, error))
  {
    throw Error(error, path);
  }
  return img;
}
} // namespace art
