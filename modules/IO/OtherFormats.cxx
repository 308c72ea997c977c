#include "OtherFormats.h"
#include "AtomicFile.h"
#include "Error.h"
#include "FormatChecks.h"
#include "ReaderPlugin.h"
#include "ReaderRun.h"
#include "RegularFile.h"

#include <vtkAVSucdReader.h>
#include <vtkBMPReader.h>
#include <vtkBYUReader.h>
#include <vtkFacetReader.h>
#include <vtkGAMBITReader.h>
#include <vtkImageReader.h>
#include <vtkJPEGReader.h>
#include <vtkMRCReader.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNMReader.h>
#include <vtkSLCReader.h>
#include <vtkStringArray.h>
#include <vtkTIFFReader.h>
#include <vtkTecplotReader.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <set>

namespace fs = std::filesystem;

namespace art
{
namespace
{
const std::set<std::string> SliceExt = { ".png", ".jpg", ".jpeg", ".tif", ".tiff", ".bmp", ".pgm", ".ppm", ".pnm" };

vtkSmartPointer<vtkImageReader2> SliceReader(const std::string& ext)
{
  if (ext == ".png")
  {
    return vtkSmartPointer<vtkPNGReader>::New();
  }
  if (ext == ".jpg" || ext == ".jpeg")
  {
    return vtkSmartPointer<vtkJPEGReader>::New();
  }
  if (ext == ".tif" || ext == ".tiff")
  {
    return vtkSmartPointer<vtkTIFFReader>::New();
  }
  if (ext == ".bmp")
  {
    return vtkSmartPointer<vtkBMPReader>::New();
  }
  return vtkSmartPointer<vtkPNMReader>::New();
}

// One slice's extent, read from its header (a slice of another size read as garbage).
void SliceExtent(const std::string& file, int extent[6], int* components)
{
  RequireRegularFile(file);
  const std::string e = LowerExtension(file);
  if (e == ".tif" || e == ".tiff")
  {
    CheckTiff(file);
  }
  vtkSmartPointer<vtkImageReader2> r = SliceReader(LowerExtension(file));
  if (!r->CanReadFile(file.c_str()))
  {
    throw Error("is not a readable " + LowerExtension(file).substr(1) + " image", file);
  }
  r->SetFileName(file.c_str());
  RunReaderInformation(r, file);
  r->GetDataExtent(extent);
  *components = r->GetNumberOfScalarComponents();
}

// Slices of one size, as a volume; spacing from the options (image files hold none for z).
vtkSmartPointer<vtkAlgorithm> StackReader(const std::vector<std::string>& files, const RawLayout& raw, const std::string& path)
{
  int first[6], components = 1;
  SliceExtent(files.front(), first, &components);
  if (first[5] > first[4])
  {
    throw Error("a stack of multi-page images (" + fs::path(files.front()).filename().string() + " holds " +
        std::to_string(first[5] - first[4] + 1) + " pages): give one multi-page file or a stack of 2-D slices",
      path);
  }
  vtkNew<vtkStringArray> names;
  for (const std::string& f : files)
  {
    int e[6], c = 1;
    SliceExtent(f, e, &c);
    if (!std::equal(e, e + 4, first) || c != components)
    {
      throw Error("slice " + fs::path(f).filename().string() + " is " + std::to_string(e[1] - e[0] + 1) + " x " +
          std::to_string(e[3] - e[2] + 1) + " (" + std::to_string(c) + " channels), " +
          fs::path(files.front()).filename().string() + " " + std::to_string(first[1] - first[0] + 1) + " x " +
          std::to_string(first[3] - first[2] + 1) + " (" + std::to_string(components) + ")",
        path);
    }
    names->InsertNextValue(f);
  }
  vtkSmartPointer<vtkImageReader2> r = SliceReader(LowerExtension(files.front()));
  r->SetFileNames(names);
  if (raw.SpacingGiven)
  {
    r->SetDataSpacing(raw.Spacing[0], raw.Spacing[1], raw.Spacing[2]);
  }
  return r;
}

int RawTypeCode(const std::string& t, const std::string& path)
{
  static const std::pair<const char*, int> types[] = { { "uint8", VTK_UNSIGNED_CHAR }, { "uchar", VTK_UNSIGNED_CHAR },
    { "int8", VTK_SIGNED_CHAR }, { "char", VTK_SIGNED_CHAR }, { "uint16", VTK_UNSIGNED_SHORT },
    { "ushort", VTK_UNSIGNED_SHORT }, { "int16", VTK_SHORT }, { "short", VTK_SHORT }, { "uint32", VTK_UNSIGNED_INT },
    { "uint", VTK_UNSIGNED_INT }, { "int32", VTK_INT }, { "int", VTK_INT }, { "uint64", VTK_UNSIGNED_LONG_LONG },
    { "int64", VTK_LONG_LONG }, { "float32", VTK_FLOAT }, { "float", VTK_FLOAT }, { "float64", VTK_DOUBLE },
    { "double", VTK_DOUBLE } };
  for (const auto& [name, code] : types)
  {
    if (t == name)
    {
      return code;
    }
  }
  throw Error("--raw-type '" + t + "' is not one of uint8 int8 uint16 int16 uint32 int32 uint64 int64 float32 float64", path);
}

// Raw voxels as ParaView's raw reader takes them: sizes, type, spacing, header bytes, byte order.
vtkSmartPointer<vtkAlgorithm> RawReader(const std::string& path, const RawLayout& raw)
{
  RequireRegularFile(path);
  if (raw.Type.empty())
  {
    throw Error("a raw volume needs its voxel type: --raw-type (uint8 int16 float32 ...)", path);
  }
  const int type = RawTypeCode(raw.Type, path);
  const long long need = static_cast<long long>(raw.Dims[0]) * raw.Dims[1] * raw.Dims[2] * raw.Components *
    vtkDataArray::GetDataTypeSize(type);
  std::error_code ec;
  const long long size = static_cast<long long>(fs::file_size(path, ec));
  const long long header = raw.HeaderBytes >= 0 ? raw.HeaderBytes : std::max(0LL, size - need);
  if (size - header < need)
  {
    throw Error("holds " + std::to_string(std::max(0LL, size - header)) + " data bytes" +
        (raw.HeaderBytes > 0 ? " after its " + std::to_string(header) + "-byte header" : std::string()) + "; " +
        std::to_string(raw.Dims[0]) + " x " + std::to_string(raw.Dims[1]) + " x " + std::to_string(raw.Dims[2]) +
        " " + raw.Type + " voxels need " + std::to_string(need) + " (check --raw-dims and --raw-type)",
      path);
  }
  if (raw.HeaderBytes >= 0 && size - header > need)
  {
    throw Error("holds " + std::to_string(size - header - need) + " bytes more than its header and " +
        std::to_string(need) + " data bytes (check --raw-dims, --raw-type and --raw-header)",
      path);
  }
  vtkNew<vtkImageReader> r;
  r->SetFileName(path.c_str());
  r->SetFileDimensionality(3);
  r->SetDataScalarType(type);
  r->SetNumberOfScalarComponents(raw.Components);
  r->SetDataExtent(0, raw.Dims[0] - 1, 0, raw.Dims[1] - 1, 0, raw.Dims[2] - 1);
  r->SetDataSpacing(raw.Spacing[0], raw.Spacing[1], raw.Spacing[2]);
  r->SetHeaderSize(static_cast<unsigned long>(header));
  r->FileLowerLeftOn(); // the first voxel is the first in the file, as ParaView reads raw files
  if (raw.BigEndian)
  {
    r->SetDataByteOrderToBigEndian();
  }
  else
  {
    r->SetDataByteOrderToLittleEndian();
  }
  r->SetScalarArrayName("ImageFile");
  return r;
}

// A multi-page TIFF is a volume; one 2-D image is not (a stack is a folder or a pattern).
vtkSmartPointer<vtkAlgorithm> TiffReader(const std::string& path)
{
  CheckTiff(path);
  vtkNew<vtkTIFFReader> r;
  if (!r->CanReadFile(path.c_str()))
  {
    throw Error("is not a TIFF file VTK reads", path);
  }
  r->SetFileName(path.c_str());
  RunReaderInformation(r, path);
  int e[6];
  r->GetDataExtent(e);
  if (e[5] <= e[4])
  {
    throw Error("is a 2-D image (" + std::to_string(e[1] - e[0] + 1) + " x " + std::to_string(e[3] - e[2] + 1) +
        "), not a volume: give a multi-page TIFF, or its slices as a folder or a pattern such as slice%03d.tif",
      path);
  }
  return r;
}
} // namespace

bool IsOtherVolume(const std::string& ext)
{
  static const std::set<std::string> v = { ".slc", ".mnc", ".pic", ".mrc", ".map", ".rec", ".hdr", ".img", ".tif",
    ".tiff", ".raw" };
  return v.count(ext) > 0;
}

bool IsOtherSurface(const std::string& ext)
{
  return ext == ".g" || ext == ".byu" || ext == ".facet";
}

bool IsOtherMesh(const std::string& ext)
{
  static const std::set<std::string> m = { ".exo", ".e", ".ex2", ".exii", ".inp", ".tec", ".dat", ".neu" };
  return m.count(ext) > 0;
}

std::vector<std::string> ImageStack(const std::string& path)
{
  std::vector<std::string> files;
  std::error_code ec;
  if (fs::is_directory(path, ec))
  {
    std::string kind;
    for (const auto& f : fs::directory_iterator(path, ec))
    {
      const std::string e = LowerExtension(f.path().string());
      if (f.is_regular_file(ec) && SliceExt.count(e) && (kind.empty() || kind == e))
      {
        kind = e;
        files.push_back(f.path().string());
      }
    }
    std::sort(files.begin(), files.end());
    return files;
  }
  // A printf pattern with one integer conversion: its files from the first number that exists.
  const std::size_t pc = path.find('%');
  if (pc == std::string::npos || path.find('%', pc + 1) != std::string::npos || !SliceExt.count(LowerExtension(path)))
  {
    return files;
  }
  std::size_t d = pc + 1;
  while (d < path.size() && (std::isdigit(static_cast<unsigned char>(path[d])) || path[d] == '0'))
  {
    ++d;
  }
  if (d >= path.size() || (path[d] != 'd' && path[d] != 'i'))
  {
    return files;
  }
  for (int i = 0, misses = 0; i < 1000000 && misses < 2; ++i)
  {
    char name[4096];
    std::snprintf(name, sizeof name, path.c_str(), i);
    if (fs::exists(name, ec))
    {
      files.push_back(name);
      misses = 0;
    }
    else if (!files.empty())
    {
      break;
    }
    else
    {
      misses = i >= 1 ? 2 : 0; // patterns start at 0 or 1
    }
  }
  return files;
}

vtkSmartPointer<vtkAlgorithm> OtherVolumeReader(const std::string& path, const RawLayout& raw)
{
  if (raw.Given())
  {
    return RawReader(path, raw);
  }
  const std::vector<std::string> stack = ImageStack(path);
  if (!stack.empty())
  {
    return StackReader(stack, raw, path);
  }
  const std::string e = LowerExtension(path);
  if (e == ".raw")
  {
    throw Error("a raw volume needs its layout: --raw-dims X,Y,Z --raw-type T (and --raw-spacing, --raw-header, "
                "--raw-endian as the data need)",
      path);
  }
  RequireRegularFile(path);
  if (e == ".slc")
  {
    CheckSlc(path);
    vtkNew<vtkSLCReader> r;
    r->SetFileName(path.c_str());
    return r;
  }
  if (e == ".mrc" || e == ".map" || e == ".rec")
  {
    CheckMrc(path);
    vtkNew<vtkMRCReader> r;
    r->SetFileName(path.c_str());
    return r;
  }
  if (e == ".pic")
  {
    return BioRadReader(path);
  }
  if (e == ".hdr" || e == ".img")
  {
    const std::string header = CheckAnalyze(path);
    vtkNew<vtkNIFTIImageReader> r;
    r->SetFileName(header.c_str());
    return r;
  }
  if (e == ".tif" || e == ".tiff")
  {
    return TiffReader(path);
  }
  if (e == ".mnc")
  {
    return PluginReader("minc", path);
  }
  throw Error("unknown volume type '" + e + "'", path);
}

vtkSmartPointer<vtkAlgorithm> OtherSurfaceReader(const std::string& path)
{
  RequireRegularFile(path);
  const std::string e = LowerExtension(path);
  if (e == ".facet")
  {
    vtkNew<vtkFacetReader> r;
    r->SetFileName(path.c_str());
    return r;
  }
  CheckByu(path);
  vtkNew<vtkBYUReader> r;
  r->SetGeometryFileName(path.c_str());
  return r;
}

vtkSmartPointer<vtkAlgorithm> OtherMeshReader(const std::string& path)
{
  RequireRegularFile(path);
  const std::string e = LowerExtension(path);
  if (e == ".inp")
  {
    CheckAvsUcd(path);
    vtkNew<vtkAVSucdReader> r;
    r->SetFileName(path.c_str());
    return r;
  }
  if (e == ".tec" || e == ".dat")
  {
    CheckTecplot(path);
    vtkNew<vtkTecplotReader> r;
    r->SetFileName(path.c_str());
    return r;
  }
  if (e == ".neu")
  {
    CheckGambit(path);
    vtkNew<vtkGAMBITReader> r;
    r->SetFileName(path.c_str());
    return r;
  }
  return PluginReader("exodus", path);
}
} // namespace art
