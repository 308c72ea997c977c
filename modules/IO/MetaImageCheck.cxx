#include "MetaImageCheck.h"
#include "Error.h"
#include "RegularFile.h"

#include <vtk_zlib.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;

namespace art
{
namespace
{
int ElementSize(const std::string& type)
{
  static const std::map<std::string, int> sizes = { { "MET_CHAR", 1 }, { "MET_UCHAR", 1 },
    { "MET_SHORT", 2 }, { "MET_USHORT", 2 }, { "MET_INT", 4 }, { "MET_UINT", 4 },
    { "MET_LONG", 4 }, { "MET_ULONG", 4 }, { "MET_LONG_LONG", 8 }, { "MET_ULONG_LONG", 8 },
    { "MET_FLOAT", 4 }, { "MET_DOUBLE", 8 } };
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

std::string Trim(const std::string& s)
{
  const auto b = s.find_first_not_of(" \t\r");
  const auto e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

using Keys = std::map<std::string, std::string>;

// The header's "Key = Value" lines up to ElementDataFile; dataStart is where the data begins.
Keys ReadHeader(const std::string& path, std::streamoff& dataStart)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw Error("cannot open file", path);
  }
  Keys keys;
  std::string line;
  dataStart = -1;
  // The header is text lines "Key = Value" ending with ElementDataFile.
  for (int n = 0; n < 200 && std::getline(in, line); ++n)
  {
    const auto eq = line.find('=');
    if (eq == std::string::npos)
    {
      throw Error("not a MetaImage header (line " + std::to_string(n + 1) + ")", path);
    }
    const std::string key = Trim(line.substr(0, eq));
    keys[key] = Trim(line.substr(eq + 1));
    if (key == "ElementDataFile")
    {
      dataStart = in.tellg();
      break;
    }
  }
  return keys;
}

// Up to n numbers of a header value; fewer when the value is shorter or not numeric.
std::vector<double> Numbers(const Keys& keys, const std::string& key, size_t n)
{
  std::vector<double> v;
  const auto it = keys.find(key);
  if (it != keys.end())
  {
    std::istringstream s(it->second);
    double x;
    while (v.size() < n && s >> x)
    {
      v.push_back(x);
    }
  }
  return v;
}

// A whole number from the header; std::stoi's bare "stoi" reached the user as the whole message.
long long Integer(const Keys& keys, const std::string& key, long long fallback, const std::string& path)
{
  const auto it = keys.find(key);
  if (it == keys.end())
  {
    return fallback;
  }
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(it->second.c_str(), &end, 10);
  if (it->second.empty() || *end != '\0' || errno == ERANGE)
  {
    throw Error(key + " is not a whole number: '" + it->second + "'", path);
  }
  return v;
}
// The files of "ElementDataFile = LIST" (names on the following lines) or of a printf pattern
// "name%03d.raw first last step" must all exist and together hold `need` bytes.
void CheckFileSeries(const std::string& path, const std::string& edf, std::streamoff dataStart, long long need)
{
  std::vector<std::string> names;
  if (edf.compare(0, 4, "LIST") == 0)
  {
    std::ifstream in(path, std::ios::binary);
    in.seekg(dataStart);
    std::string line;
    while (std::getline(in, line))
    {
      if (!Trim(line).empty())
      {
        names.push_back(Trim(line));
      }
    }
  }
  else
  {
    std::istringstream s(edf);
    std::string pattern;
    long long first = 0, last = -1, step = 1;
    s >> pattern >> first >> last >> step;
    // The pattern is a printf format: allow exactly one integer conversion (%d, %03d, %i).
    int conversions = 0;
    for (std::size_t i = 0; i < pattern.size(); ++i)
    {
      if (pattern[i] != '%')
      {
        continue;
      }
      std::size_t j = i + 1;
      while (j < pattern.size() && (std::isdigit(static_cast<unsigned char>(pattern[j])) || pattern[j] == '-'))
      {
        ++j;
      }
      if (j < pattern.size() && pattern[j] == '%' && j == i + 1)
      {
        i = j; // "%%"
        continue;
      }
      conversions += (j < pattern.size() && (pattern[j] == 'd' || pattern[j] == 'i')) ? 1 : 100;
      i = j;
    }
    if (!s || conversions != 1 || step == 0 || (last - first) / step > 100000 || (last - first) / step < 0)
    {
      throw Error("ElementDataFile '" + edf + "' is not 'pattern first last step' with one %d in the pattern", path);
    }
    for (long long i = first; step > 0 ? i <= last : i >= last; i += step)
    {
      char name[4096];
      std::snprintf(name, sizeof name, pattern.c_str(), static_cast<int>(i));
      names.push_back(name);
    }
  }
  long long have = 0;
  for (const std::string& n : names)
  {
    const fs::path file = fs::path(n).is_absolute() ? fs::path(n) : fs::path(path).parent_path() / n;
    std::error_code ec;
    if (!fs::is_regular_file(file, ec))
    {
      throw Error("data file '" + n + "' of the series named in the header does not exist", path);
    }
    have += static_cast<long long>(fs::file_size(file, ec));
  }
  if (names.empty())
  {
    throw Error("ElementDataFile " + edf + " names no files", path);
  }
  if (have < need)
  {
    throw Error("truncated: header promises " + std::to_string(need) + " data bytes, its " +
        std::to_string(names.size()) + " files hold " + std::to_string(have),
      path);
  }
}
// Compressed data (zlib) must inflate to exactly the voxels' bytes: vtkMetaImageReader read data
// that is not zlib as zeros, and data inflating short left the rest of the image uninitialised.
void CheckInflatedSize(const std::string& dataFile, std::streamoff offset, long long packed, long long need,
  const std::string& path)
{
  std::ifstream in(dataFile, std::ios::binary);
  in.seekg(offset);
  z_stream z{};
  if (inflateInit(&z) != Z_OK)
  {
    return;
  }
  std::vector<unsigned char> src(1 << 16), dst(1 << 16);
  long long left = packed, out = 0;
  int rc = Z_OK;
  while (rc == Z_OK && left > 0 && in)
  {
    in.read(reinterpret_cast<char*>(src.data()), static_cast<std::streamsize>(std::min<long long>(left, src.size())));
    const std::streamsize got = in.gcount();
    left -= got;
    z.next_in = src.data();
    z.avail_in = static_cast<uInt>(got);
    do
    {
      z.next_out = dst.data();
      z.avail_out = static_cast<uInt>(dst.size());
      rc = inflate(&z, Z_NO_FLUSH);
      out += static_cast<long long>(dst.size() - z.avail_out);
    } while (rc == Z_OK && z.avail_out == 0);
    if (got == 0)
    {
      break;
    }
  }
  inflateEnd(&z);
  if (rc != Z_STREAM_END && rc != Z_OK)
  {
    throw Error("the compressed data is not readable zlib data (" + std::string(rc == Z_DATA_ERROR ? "corrupt" : "broken") +
        " after " + std::to_string(out) + " bytes)",
      path);
  }
  if (out != need)
  {
    throw Error("the compressed data inflates to " + std::to_string(out) + " bytes; the header's DimSize and "
                "ElementType need " + std::to_string(need),
      path);
  }
}
// MetaIO reads the header in order and needs NDims before the fields sized by it: ElementSpacing
// first failed with MetaIO's own lines ("ElementSpacing defined prior to defining NDims").
void RequireNDimsFirst(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  for (int n = 0; n < 200 && std::getline(in, line); ++n)
  {
    const std::string key = Trim(line.substr(0, line.find('=')));
    if (key == "NDims" || key == "ElementDataFile")
    {
      return;
    }
    for (const char* sized : { "DimSize", "ElementSpacing", "ElementSize", "Offset", "Origin", "Position",
           "TransformMatrix", "Rotation", "Orientation", "CenterOfRotation" })
    {
      if (key == sized)
      {
        throw Error(key + " comes before NDims in the header; MetaIO needs NDims first", path);
      }
    }
  }
}

// Text voxels (BinaryData = False): as many numbers as DimSize needs (MetaIO read a short list
// with a line of its own and left the rest of the image unset).
void RequireTextValues(const Keys& keys, const std::string& path, std::streamoff dataStart, long long need)
{
  const auto edf = keys.find("ElementDataFile");
  if (edf == keys.end() || (edf->second != "LOCAL" && edf->second != "Local" && edf->second != "local"))
  {
    return; // a separate text file: MetaIO's reader reports it
  }
  std::ifstream in(path, std::ios::binary);
  in.seekg(dataStart);
  long long values = 0;
  for (std::string word; values < need && in >> word; ++values)
  {
    char* end = nullptr;
    std::strtod(word.c_str(), &end);
    if (*end != '\0')
    {
      throw Error("text voxel " + std::to_string(values + 1) + " is not a number: '" + word.substr(0, 20) + "'", path);
    }
  }
  if (values < need)
  {
    throw Error("holds " + std::to_string(values) + " text voxel values; DimSize needs " + std::to_string(need), path);
  }
}

// Far more bytes than the voxels need: the header's ElementType or DimSize does not describe the
// data (MET_CHAR over float data read as garbage). A few bytes more (a line end) are allowed.
void RequireNoExtraBytes(Keys& keys, long long have, long long need, int esize, const std::string& path)
{
  if (have <= need + std::max(16LL, need / 64))
  {
    return;
  }
  std::string hint;
  if (have % need == 0 && have / need <= 8)
  {
    const long long wider = esize * (have / need);
    hint = " (" + std::to_string(have / need) + " times as many: " + std::to_string(wider) + "-byte voxels, e.g. " +
      (wider == 2 ? "MET_SHORT" : wider == 4 ? "MET_FLOAT or MET_INT" : wider == 8 ? "MET_DOUBLE" : "another type") +
      ", or more channels?)";
  }
  throw Error("holds " + std::to_string(have) + " data bytes where DimSize " + keys["DimSize"] + " of " +
      keys["ElementType"] + " needs " + std::to_string(need) + hint + ": the header does not describe the data",
    path);
}
} // namespace

void CheckMetaImage(const std::string& path)
{
  std::streamoff dataStart = -1;
  Keys keys = ReadHeader(path, dataStart);
  if (dataStart < 0 || !keys.count("DimSize") || !keys.count("ElementType"))
  {
    throw Error("not a MetaImage header (no DimSize, ElementType or ElementDataFile)", path);
  }
  RequireNDimsFirst(path);
  std::istringstream dims(keys["DimSize"]);
  unsigned long long count = 1;
  long long d;
  int ndims = 0;
  while (dims >> d)
  {
    if (d <= 0)
    {
      throw Error("DimSize has a non-positive size", path);
    }
    // 2^32 per axis wrapped the product to 0 and passed the size check.
    if (static_cast<unsigned long long>(d) > (1ULL << 48) / count)
    {
      throw Error("DimSize '" + keys["DimSize"] + "' is too large", path);
    }
    count *= static_cast<unsigned long long>(d);
    ++ndims;
  }
  if (ndims == 0)
  {
    throw Error("DimSize is empty", path);
  }
  // MetaIO refused a malformed NDims with lines of its own naming another field.
  if (keys.count("NDims") && Integer(keys, "NDims", ndims, path) != ndims)
  {
    throw Error("NDims = " + keys["NDims"] + " but DimSize lists " + std::to_string(ndims) + " sizes", path);
  }
  // vtkMetaImageReader (VTK 9.1) corrupts its heap on a file of more than three axes, even when
  // the further ones hold one sample ("double free or corruption").
  if (ndims > 3)
  {
    throw Error("a " + std::to_string(ndims) + "-D image (DimSize " + keys["DimSize"] +
        "): only 3-D volumes are read; save one volume (a time step or channel) as its own 3-D file",
      path);
  }
  const int esize = ElementSize(keys["ElementType"]);
  if (esize == 0)
  {
    throw Error("unknown ElementType '" + keys["ElementType"] + "'", path);
  }
  const long long channels = Integer(keys, "ElementNumberOfChannels", 1, path);
  if (channels < 1 || channels > 1024)
  {
    throw Error("ElementNumberOfChannels must be 1..1024, got " + std::to_string(channels), path);
  }
  const bool compressed = keys.count("CompressedData") &&
    (keys["CompressedData"] == "True" || keys["CompressedData"] == "true");
  if (keys.count("BinaryData") && (keys["BinaryData"] == "False" || keys["BinaryData"] == "false"))
  {
    RequireTextValues(keys, path, dataStart, static_cast<long long>(count) * channels);
    return;
  }

  std::string dataFile = path;
  std::streamoff offset = dataStart;
  const std::string& edf = keys["ElementDataFile"];
  if (edf != "LOCAL" && edf != "Local" && edf != "local")
  {
    if (edf.find('%') != std::string::npos || edf.compare(0, 4, "LIST") == 0)
    {
      // A file series: vtkMetaImageReader zero-fills the slices of a missing or short file.
      CheckFileSeries(path, edf, dataStart, compressed ? 0 : static_cast<long long>(count) * esize * channels);
      return;
    }
    dataFile = (fs::path(path).parent_path() / edf).string();
    offset = Integer(keys, "HeaderSize", 0, path);
    const std::string problem = RegularFileProblem(dataFile);
    if (!problem.empty())
    {
      throw Error("data file '" + edf + "' named in the header: " + problem, path);
    }
  }
  std::error_code ec;
  const auto size = static_cast<long long>(fs::file_size(dataFile, ec));
  long long need = static_cast<long long>(count) * esize * channels;
  if (offset < 0)
  {
    offset = std::max(0LL, size - need); // HeaderSize -1: the data are the file's last bytes
  }
  const long long have = size - offset;
  if (compressed)
  {
    if (!keys.count("CompressedDataSize") && dataFile == path)
    {
      // Data in the header's own file: vtkMetaImageReader then read every voxel as 0 without a
      // word (from a data file of its own it takes the file's size).
      throw Error("compressed data without CompressedDataSize, which VTK's MetaImage reader reads as zeros: add "
                  "'CompressedDataSize = " + std::to_string(std::max(0LL, have)) + "' to the header",
        path);
    }
    const long long packed = keys.count("CompressedDataSize") ? Integer(keys, "CompressedDataSize", 1, path) : have;
    if (have < packed)
    {
      throw Error("truncated: header promises " + std::to_string(packed) + " data bytes, file holds " +
          std::to_string(std::max(0LL, have)),
        path);
    }
    CheckInflatedSize(dataFile, offset, packed, need, path);
    return;
  }
  if (have < need)
  {
    throw Error("truncated: header promises " + std::to_string(need) + " data bytes, file holds " +
        std::to_string(std::max(0LL, have)),
      path);
  }
  RequireNoExtraBytes(keys, have, need, esize, path);
}

bool MetaImageDirection(const std::string& path, double direction[9])
{
  std::streamoff dataStart = -1;
  const Keys keys = ReadHeader(path, dataStart);
  // MetaIO reads the matrix under any of these three names.
  std::vector<double> m;
  for (const char* key : { "TransformMatrix", "Rotation", "Orientation" })
  {
    if (keys.count(key))
    {
      m = Numbers(keys, key, 9);
      break;
    }
  }
  const bool hasMatrix = m.size() == 9;
  if (!hasMatrix)
  {
    m = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  }
  // ITK writes the matrix axis by axis: numbers 3c..3c+2 are where index axis c points. VTK's
  // direction matrix holds those axes as columns.
  const std::vector<double> spacing = Numbers(keys, "ElementSpacing", 3);
  bool identity = true;
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      // A negative spacing (VTK keeps only its size) turns its axis around.
      const double sign = (c < static_cast<int>(spacing.size()) && spacing[c] < 0) ? -1.0 : 1.0;
      direction[3 * r + c] = sign * m[3 * c + r];
      identity = identity && direction[3 * r + c] == (r == c ? 1.0 : 0.0);
    }
  }
  return !identity;
}
} // namespace art
