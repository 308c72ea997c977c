#include "DicomSeries.h"
#include "Error.h"

#include <DICOMAppHelper.h>
#include <DICOMCallback.h>
#include <DICOMParser.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <cctype>
#include <fstream>
#include <iterator>
#include <map>

namespace fs = std::filesystem;

namespace art
{
namespace
{
struct Image
{
  std::string File;
  int Width = 0, Height = 0;
  std::string Syntax; // transfer syntax UID
  double Position[3] = { 0, 0, 0 }, Orientation[6] = { 0, 0, 0, 0, 0, 0 };
  long Frames = 1;
  long long PixelBytes = 0; ///< what its size, bits and samples need
};

// NumberOfFrames (0028,0008), an integer string; DICOMAppHelper does not keep it.
struct FramesTag
{
  long Frames = 1;
  void Read(DICOMParser*, doublebyte, doublebyte, DICOMParser::VRTypes, unsigned char* val, quadbyte len)
  {
    if (val && len > 0)
    {
      Frames = std::atol(std::string(reinterpret_cast<const char*>(val), static_cast<std::size_t>(len)).c_str());
    }
  }
};

// vtkDICOMImageReader spaces the slices evenly (by the first two): a missing slice or a change of
// spacing squeezed the volume without a word, and two images at one position (two acquisitions)
// stacked both. Positions are compared along the slice normal.
void CheckSpacing(const std::vector<Image>& images, const std::string& dir)
{
  const double* o = images.front().Orientation;
  const double n[3] = { o[1] * o[5] - o[2] * o[4], o[2] * o[3] - o[0] * o[5], o[0] * o[4] - o[1] * o[3] };
  if (images.size() < 3 || !(n[0] * n[0] + n[1] * n[1] + n[2] * n[2] > 0.5))
  {
    return; // too few slices to compare, or no orientation
  }
  std::vector<std::pair<double, std::string>> at;
  for (const Image& im : images)
  {
    at.emplace_back(n[0] * im.Position[0] + n[1] * im.Position[1] + n[2] * im.Position[2],
      fs::path(im.File).filename().string());
  }
  std::sort(at.begin(), at.end());
  const double step = at[1].first - at[0].first;
  for (std::size_t i = 1; i < at.size(); ++i)
  {
    const double gap = at[i].first - at[i - 1].first;
    if (std::abs(gap - step) > 0.01 * std::abs(step) + 1e-3 || gap < 1e-4)
    {
      char text[400];
      std::snprintf(text, sizeof text,
        "slices are not evenly spaced: %s and %s are %.4g mm apart, %s and %s %.4g mm (a missing slice, two "
        "acquisitions in one series, or a change of spacing; VTK would stack them evenly)",
        at[0].second.c_str(), at[1].second.c_str(), step, at[i - 1].second.c_str(), at[i].second.c_str(), gap);
      throw Error(text, dir);
    }
  }
}

// Walks the data elements of a DICOM Part 10 file up to its pixel data and returns what is wrong
// with them, or "": DICOMParser trusts each element's length (a length past the end of the file
// corrupted its heap: a crash in ~DICOMAppHelper). Sequences of undefined length end the walk.
std::string ElementProblem(const fs::path& file)
{
  std::ifstream in(file, std::ios::binary);
  std::string b((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto size = static_cast<unsigned long long>(b.size());
  if (size < 132 || b.compare(128, 4, "DICM") != 0)
  {
    return ""; // not Part 10: DICOMParser says so
  }
  auto u16 = [&](std::size_t at, bool big) {
    const auto* p = reinterpret_cast<const unsigned char*>(b.data() + at);
    return big ? unsigned(p[0] << 8 | p[1]) : unsigned(p[1] << 8 | p[0]);
  };
  auto u32 = [&](std::size_t at, bool big) {
    return big ? (static_cast<unsigned long long>(u16(at, true)) << 16 | u16(at + 2, true))
               : (static_cast<unsigned long long>(u16(at + 2, false)) << 16 | u16(at, false));
  };
  std::size_t at = 132;
  bool explicitVr = true, big = false, meta = true;
  std::string syntax;
  while (at + 8 <= size)
  {
    const unsigned group = u16(at, big && !meta), element = u16(at + 2, big && !meta);
    char tag[16];
    std::snprintf(tag, sizeof tag, "(%04X,%04X)", group, element);
    if (meta && group != 0x0002)
    {
      // The data set after the meta group, in the transfer syntax it names.
      meta = false;
      explicitVr = syntax != "1.2.840.10008.1.2";
      big = syntax == "1.2.840.10008.1.2.2";
      continue;
    }
    if (group == 0x7FE0 && element == 0x0010)
    {
      return ""; // the pixel data: their length is checked against the image size later
    }
    unsigned long long length;
    std::size_t header = 8;
    const bool be = big && !meta;
    if (explicitVr || meta)
    {
      const std::string vr = b.substr(at + 4, 2);
      if (!(std::isupper(static_cast<unsigned char>(vr[0])) && std::isupper(static_cast<unsigned char>(vr[1]))))
      {
        return std::string("element ") + tag + " has no value representation";
      }
      static const std::string longVr = "OB OW OF SQ UT UN OD OL OV UC UR SV UV";
      if (longVr.find(vr) != std::string::npos)
      {
        if (at + 12 > size)
        {
          return "cut short inside an element's header";
        }
        length = u32(at + 8, be);
        header = 12;
      }
      else
      {
        length = u16(at + 6, be);
      }
    }
    else
    {
      length = u32(at + 4, be);
    }
    if (length == 0xFFFFFFFFULL)
    {
      return ""; // a sequence of undefined length: left to the parser
    }
    if (at + header + length > size)
    {
      return std::string("element ") + tag + " of " + std::to_string(length) +
        " bytes runs past the end of the file (" + std::to_string(size) + " bytes)";
    }
    if (meta && group == 0x0002 && element == 0x0010)
    {
      syntax = b.substr(at + header, static_cast<std::size_t>(length));
      while (!syntax.empty() && (syntax.back() == '\0' || syntax.back() == ' '))
      {
        syntax.pop_back();
      }
    }
    at += header + static_cast<std::size_t>(length);
  }
  return "";
}

// The bytes after the pixel data element's header (7FE0,0010; the last in the file), or -1 when
// none is found in the file's first megabyte.
long long PixelDataBytes(const fs::path& file)
{
  std::ifstream in(file, std::ios::binary);
  std::string head(1 << 20, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const std::string tag("\xE0\x7F\x10\x00", 4);
  std::size_t at = head.find(tag);
  while (at != std::string::npos && head.find(tag, at + 1) != std::string::npos)
  {
    at = head.find(tag, at + 1);
  }
  if (at == std::string::npos)
  {
    return -1;
  }
  // Explicit VR: "OB"/"OW", two reserved bytes and a 4-byte length; implicit: the length.
  const bool explicitVr = head.compare(at + 4, 2, "OW") == 0 || head.compare(at + 4, 2, "OB") == 0;
  std::error_code ec;
  return static_cast<long long>(fs::file_size(file, ec)) - static_cast<long long>(at + (explicitVr ? 12 : 8));
}

// Slices cut short (each missing its last bytes) read with the rest as zeros, and an empty file
// in the folder was dropped without a word.
void CheckSliceBytes(const std::vector<Image>& images, const std::string& dir)
{
  for (const Image& im : images)
  {
    const long long have = PixelDataBytes(im.File);
    if (have >= 0 && have < im.PixelBytes)
    {
      throw Error("slice " + fs::path(im.File).filename().string() + " is cut short: its " + std::to_string(im.Width) +
          " x " + std::to_string(im.Height) + " pixels need " + std::to_string(im.PixelBytes) + " bytes, it holds " +
          std::to_string(std::max(0LL, have)),
        dir);
    }
  }
}

// vtkDICOMImageReader reads only uncompressed pixels: implicit or explicit VR, little or big endian.
bool Uncompressed(std::string uid)
{
  while (!uid.empty() && (uid.back() == '\0' || uid.back() == ' '))
  {
    uid.pop_back(); // UIDs are padded to an even length
  }
  return uid.empty() || uid == "1.2.840.10008.1.2" || uid == "1.2.840.10008.1.2.1" || uid == "1.2.840.10008.1.2.2";
}
} // namespace

std::vector<std::string> DicomSeriesFiles(const std::string& dir, int* seriesInFolder)
{
  // One parser per file, as vtkDICOMImageReader does, so each image's own size is kept.
  std::map<std::string, std::vector<Image>> series;
  std::vector<fs::path> paths;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
  {
    if (entry.is_regular_file(ec))
    {
      if (entry.file_size(ec) == 0)
      {
        throw Error("slice " + entry.path().filename().string() + " is empty (0 bytes): restore or remove it", dir);
      }
      paths.push_back(entry.path());
    }
  }
  std::sort(paths.begin(), paths.end());
  for (const fs::path& p : paths)
  {
    const std::string problem = ElementProblem(p);
    if (!problem.empty())
    {
      throw Error("slice " + p.filename().string() + ": " + problem, dir);
    }
    DICOMParser parser;
    DICOMAppHelper helper;
    if (!parser.OpenFile(p.string()) || !parser.IsDICOMFile())
    {
      continue;
    }
    helper.RegisterCallbacks(&parser);
    FramesTag frames;
    DICOMMemberCallback<FramesTag> framesCallback;
    framesCallback.SetCallbackFunction(&frames, &FramesTag::Read);
    parser.AddDICOMTagCallback(0x0028, 0x0008, DICOMParser::VR_IS, &framesCallback);
    parser.ReadHeader();
    dicom_stl::vector<dicom_stl::string> uids;
    helper.GetSeriesUIDs(uids);
    Image im{ p.string(), helper.GetWidth(), helper.GetHeight(), helper.GetTransferSyntaxUID() };
    im.Frames = frames.Frames;
    im.PixelBytes = static_cast<long long>(im.Width) * im.Height * std::max(1, helper.GetNumberOfComponents()) *
      ((helper.GetBitsAllocated() + 7) / 8);
    std::copy(helper.GetImagePositionPatient(), helper.GetImagePositionPatient() + 3, im.Position);
    std::copy(helper.GetImageOrientationPatient(), helper.GetImageOrientationPatient() + 6, im.Orientation);
    series[uids.empty() ? std::string() : uids.front()].push_back(im);
  }
  if (seriesInFolder)
  {
    *seriesInFolder = static_cast<int>(series.size());
  }
  if (series.empty())
  {
    return {};
  }
  auto most = series.begin();
  int ties = 0;
  for (auto it = series.begin(); it != series.end(); ++it)
  {
    if (it->second.size() > most->second.size())
    {
      most = it;
      ties = 0;
    }
    else if (it != most && it->second.size() == most->second.size())
    {
      ++ties;
    }
  }
  if (ties > 0)
  {
    throw Error("holds " + std::to_string(series.size()) + " DICOM series, " + std::to_string(ties + 1) + " of them with " +
        std::to_string(most->second.size()) + " images: put the one to load in a folder of its own",
      dir);
  }
  const std::vector<Image>& chosen = most->second;
  for (const Image& im : chosen)
  {
    if (!Uncompressed(im.Syntax))
    {
      throw Error("holds compressed DICOM images (transfer syntax " + im.Syntax.substr(0, im.Syntax.find('\0')) +
          " in " + fs::path(im.File).filename().string() +
          "), which VTK's reader cannot decode: decompress them first (gdcmconv --raw or dcmdjpeg)",
        dir);
    }
    if (im.Frames > 1)
    {
      // vtkDICOMImageReader reads the first frame of an (enhanced) multi-frame image as one slice.
      throw Error("holds a multi-frame DICOM image (" + std::to_string(im.Frames) + " frames in " +
          fs::path(im.File).filename().string() +
          "), which VTK's reader reads as its first frame only: convert it first (dcm2niix to .nii, or to single frames)",
        dir);
    }
    if (im.Width != chosen.front().Width || im.Height != chosen.front().Height)
    {
      throw Error("images of one DICOM series differ in size: " + fs::path(im.File).filename().string() + " is " +
          std::to_string(im.Width) + " x " + std::to_string(im.Height) + ", " +
          fs::path(chosen.front().File).filename().string() + " " + std::to_string(chosen.front().Width) + " x " +
          std::to_string(chosen.front().Height),
        dir);
    }
  }
  CheckSpacing(chosen, dir);
  CheckSliceBytes(chosen, dir);
  std::vector<std::string> files;
  for (const Image& im : chosen)
  {
    files.push_back(im.File);
  }
  return files;
}

DicomLinkFolder::DicomLinkFolder(const std::vector<std::string>& files)
{
  std::string pattern = (fs::temp_directory_path() / "adaptivert-dicom-XXXXXX").string();
  if (!mkdtemp(pattern.data()))
  {
    throw Error("cannot make a temporary folder for the DICOM series", fs::temp_directory_path().string());
  }
  Dir = pattern;
  for (const std::string& f : files)
  {
    std::error_code ec;
    fs::create_symlink(fs::absolute(f), fs::path(Dir) / fs::path(f).filename(), ec);
    if (ec)
    {
      fs::remove_all(Dir, ec);
      throw Error("cannot link the DICOM series into a temporary folder: " + ec.message(), f);
    }
  }
}

DicomLinkFolder::~DicomLinkFolder()
{
  std::error_code ec;
  fs::remove_all(Dir, ec);
}
} // namespace art
