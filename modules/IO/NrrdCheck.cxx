#include "NrrdCheck.h"
#include "Error.h"
#include "RegularFile.h"

#include <vtkDataArray.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;

namespace art
{
namespace
{
int NrrdTypeSize(const std::string& t)
{
  static const std::map<std::string, int> sizes = { { "signed char", 1 }, { "int8", 1 }, { "int8_t", 1 },
    { "uchar", 1 }, { "unsigned char", 1 }, { "uint8", 1 }, { "uint8_t", 1 }, { "short", 2 },
    { "short int", 2 }, { "signed short", 2 }, { "signed short int", 2 }, { "int16", 2 }, { "int16_t", 2 },
    { "ushort", 2 }, { "unsigned short", 2 }, { "unsigned short int", 2 }, { "uint16", 2 }, { "uint16_t", 2 },
    { "int", 4 }, { "signed int", 4 }, { "int32", 4 }, { "int32_t", 4 }, { "uint", 4 }, { "unsigned int", 4 },
    { "uint32", 4 }, { "uint32_t", 4 }, { "longlong", 8 }, { "long long", 8 }, { "long long int", 8 },
    { "signed long long", 8 }, { "signed long long int", 8 }, { "int64", 8 }, { "int64_t", 8 },
    { "ulonglong", 8 }, { "unsigned long long", 8 }, { "unsigned long long int", 8 }, { "uint64", 8 },
    { "uint64_t", 8 }, { "float", 4 }, { "double", 8 } };
  const auto it = sizes.find(t);
  return it == sizes.end() ? 0 : it->second;
}
// The detached data file a header names ("data file" or the older "datafile"), or "".
std::string DataFileField(std::map<std::string, std::string>& keys)
{
  return keys.count("data file") ? keys["data file"] : keys["datafile"];
}
} // namespace

std::map<std::string, std::string> ReadNrrdFields(std::istream& in)
{
  std::map<std::string, std::string> keys;
  std::string line;
  for (int n = 0; n < 1000 && std::getline(in, line); ++n)
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    if (line.empty())
    {
      break; // the data follows (when attached)
    }
    const auto colon = line.find(':');
    if (line[0] == '#' || colon == std::string::npos || line.compare(0, 4, "NRRD") == 0)
    {
      continue;
    }
    std::string value = line.substr(colon + 1);
    if (!value.empty() && value[0] == '=')
    {
      continue; // "key:=value" pairs are free-form
    }
    value.erase(0, value.find_first_not_of(" \t"));
    keys[line.substr(0, colon)] = value;
  }
  return keys;
}

namespace
{
using Fields = std::map<std::string, std::string>;

// No blank line ends the header. vtkNrrdReader (VTK 9.1) never returned on such a file when its
// last line had no line end (a detached .nhdr saved without a final newline).
void RequireHeaderEnd(const Fields& keys, const std::string& path)
{
  const bool detached = keys.count("data file") || keys.count("datafile");
  if (!detached)
  {
    throw Error("the header has no blank line before its data (a NRRD header ends with an empty line)", path);
  }
  std::ifstream last(path, std::ios::binary | std::ios::ate);
  char c = '\n';
  if (last.tellg() > 0)
  {
    last.seekg(-1, std::ios::end);
    last.get(c);
  }
  if (c != '\n')
  {
    throw Error("the header's last line has no line end, on which VTK's NRRD reader never returns: end the "
                "file with a newline",
      path);
  }
}

// "dimension: 0" (or 17) segfaulted vtkNrrdReader; so did sizes that do not match it.
void RequireDimension(Fields& keys, const std::string& path)
{
  char* end = nullptr;
  const long dimension = std::strtol(keys["dimension"].c_str(), &end, 10);
  if (keys["dimension"].empty() || *end != '\0' || dimension < 1 || dimension > 16)
  {
    throw Error("dimension '" + keys["dimension"].substr(0, 20) + "' is not 1..16 (NRRD's limit)", path);
  }
  std::istringstream sizes(keys["sizes"]);
  std::vector<std::string> w{ std::istream_iterator<std::string>(sizes), std::istream_iterator<std::string>() };
  for (const std::string& size : w)
  {
    char* e = nullptr;
    const long long n = std::strtoll(size.c_str(), &e, 10);
    if (*e != '\0' || n < 1)
    {
      throw Error("sizes '" + keys["sizes"].substr(0, 60) + "' holds '" + size.substr(0, 20) +
          "', not a positive whole number",
        path);
    }
  }
  if (static_cast<long>(w.size()) != dimension)
  {
    throw Error("sizes '" + keys["sizes"].substr(0, 60) + "' lists " + std::to_string(w.size()) +
        " sizes for dimension " + std::to_string(dimension),
      path);
  }
  if (dimension < 3 || dimension > 4)
  {
    // vtkNrrdReader (VTK 9.1) crashed on a 2-D image.
    throw Error("a " + std::to_string(dimension) + "-D image: only 3-D volumes, and 4-D ones with the first axis "
        "as components, are read",
      path);
  }
}

// vtkNrrdReader makes the first of four axes the components. When the header puts that axis in
// space (a time series: kinds 'domain domain domain list', or a direction for it), the volume
// came out one axis short with the time steps as components.
void RefuseSpatialFourthAxis(Fields& keys, const std::string& path)
{
  std::istringstream ks(keys["kinds"]), ds(keys["space directions"]);
  std::string first, dir;
  ks >> first;
  ds >> dir;
  std::transform(first.begin(), first.end(), first.begin(), [](unsigned char c) { return std::tolower(c); });
  const bool spatialFirst = first == "domain" || first == "space" || (first.empty() && !dir.empty() && dir != "none");
  if (std::atoi(keys["dimension"].c_str()) > 3 && spatialFirst)
  {
    throw Error("a " + keys["dimension"] + "-D image whose first axis is in space (sizes " + keys["sizes"] +
        (keys.count("kinds") ? ", kinds " + keys["kinds"] : "") +
        "): only 3-D volumes are read; save one volume (a time step) as its own 3-D file (unu slice)",
      path);
  }
}

// vtkNrrdReader (VTK 9.1) segfaults on every file series, even a complete one. It takes the field
// as NRRD does: LIST, or four words or more ("<format> <min> <max> <step> [<subdim>]"); fewer
// words are one file's name, spaces and all ("my scan.raw" was refused as a series).
void RefuseFileSeries(const std::string& df, const std::string& path)
{
  std::istringstream words(df);
  std::vector<std::string> w{ std::istream_iterator<std::string>(words), std::istream_iterator<std::string>() };
  auto integer = [](const std::string& t) {
    char* end = nullptr;
    std::strtol(t.c_str(), &end, 10);
    return !t.empty() && *end == '\0';
  };
  if ((!w.empty() && w[0] == "LIST") || (w.size() >= 4 && integer(w[1]) && integer(w[2]) && integer(w[3])))
  {
    throw Error("data file '" + df + "' is a series of files, which VTK's NRRD reader cannot read: join the "
                "slices into one data file (unu join, or save from Slicer as one .nrrd)",
      path);
  }
  if (w.size() >= 4)
  {
    throw Error("data file '" + df + "' has three spaces or more in its name, which VTK's NRRD reader takes "
                "for a series of files: rename the data file (and the header's 'data file' line)",
      path);
  }
}

// Raw data (attached, or in the data file) must hold every voxel the sizes and type promise.
void RequireRawBytes(Fields& keys, const std::string& df, long long attachedStart, const std::string& path)
{
  const int esize = NrrdTypeSize(keys["type"]);
  if (esize == 0 || keys["encoding"] != "raw" || !keys.count("sizes"))
  {
    return; // compressed, text or unusual data: VTK checks as it reads
  }
  unsigned long long count = 1;
  std::istringstream sizes(keys["sizes"]);
  long long d;
  while (sizes >> d)
  {
    if (d <= 0 || static_cast<unsigned long long>(d) > (1ULL << 48) / count)
    {
      throw Error("sizes '" + keys["sizes"] + "' are not positive or too large", path);
    }
    count *= static_cast<unsigned long long>(d);
  }
  const long long skip = keys.count("byte skip") ? std::atoll(keys["byte skip"].c_str()) : 0;
  if (skip < 0)
  {
    return; // -1: the data are the file's last bytes
  }
  std::string dataFile = path;
  long long start = attachedStart;
  if (!df.empty())
  {
    dataFile = (fs::path(df).is_absolute() ? fs::path(df) : fs::path(path).parent_path() / df).string();
    start = 0;
    const std::string problem = RegularFileProblem(dataFile);
    if (!problem.empty())
    {
      throw Error("data file '" + df + "' named in the header: " + problem, path);
    }
  }
  std::error_code ec;
  const long long have = static_cast<long long>(fs::file_size(dataFile, ec)) - start - skip;
  const long long need = static_cast<long long>(count) * esize;
  if (have < need)
  {
    throw Error("truncated: header promises " + std::to_string(need) + " data bytes, file holds " +
        std::to_string(std::max(0LL, have)),
      path);
  }
}
} // namespace

namespace
{
// Control bytes in the header (a NUL inside a line) sent vtkNrrdReader reading without end.
void RequirePrintableHeader(const std::string& path, long long end)
{
  std::ifstream in(path, std::ios::binary);
  std::string head(static_cast<std::size_t>(end < 0 ? 1 << 16 : std::min(end, 1LL << 20)), '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  bool comment = false, lineStart = true;
  for (std::size_t i = 0; i < head.size(); ++i)
  {
    const auto c = static_cast<unsigned char>(head[i]);
    comment = lineStart ? c == '#' : comment;
    lineStart = c == '\n';
    // Fields are ASCII (comments may hold UTF-8): other bytes in a field (kinds of stray bytes)
    // crashed vtkNrrdReader.
    if ((c < 0x20 && c != '\n' && c != '\r' && c != '\t') || (c >= 0x7F && !comment))
    {
      throw Error("the header holds a byte that is not ASCII text (" + std::to_string(c) + ") at byte " + std::to_string(i),
        path);
    }
  }
}

// The fields vtkNrrdReader needs, with values it reads (it crashed on a missing encoding).
void RequireTypeAndEncoding(Fields& keys, const std::string& path)
{
  if (NrrdTypeSize(keys["type"]) == 0)
  {
    throw Error("type '" + keys["type"].substr(0, 30) + "' is not a NRRD type VTK reads", path);
  }
  static const char* const encodings[] = { "raw", "ascii", "text", "txt", "gzip", "gz" };
  const std::string e = keys["encoding"];
  if (std::find(std::begin(encodings), std::end(encodings), e) == std::end(encodings))
  {
    throw Error(e.empty() ? std::string("the header has no encoding field")
                          : "encoding '" + e.substr(0, 30) + "' is not one VTK reads (raw, ascii, gzip)",
      path);
  }
  const std::string endian = keys["endian"];
  if (!endian.empty() && endian != "little" && endian != "big")
  {
    throw Error("endian '" + endian.substr(0, 30) + "' is neither little nor big", path);
  }
}
} // namespace

void CheckNrrd(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw Error("cannot open file", path);
  }
  Fields keys = ReadNrrdFields(in);
  if (in.eof())
  {
    RequireHeaderEnd(keys, path);
  }
  RequirePrintableHeader(path, in.eof() ? -1 : static_cast<long long>(in.tellg()));
  in.clear();
  const std::streamoff attachedStart = in.tellg();
  RequireDimension(keys, path);
  RequireTypeAndEncoding(keys, path);
  RefuseSpatialFourthAxis(keys, path);
  const std::string df = DataFileField(keys);
  RefuseFileSeries(df, path);
  RequireRawBytes(keys, df, attachedStart, path);
}

bool ReadNrrdText(const std::string& path, vtkDataArray* values)
{
  std::ifstream in(path, std::ios::binary);
  std::map<std::string, std::string> keys = ReadNrrdFields(in);
  const std::string encoding = keys["encoding"];
  if (encoding != "ascii" && encoding != "text" && encoding != "txt")
  {
    return false;
  }
  in.clear();
  const std::string df = DataFileField(keys);
  std::ifstream detached;
  std::istream* data = &in;
  if (!df.empty())
  {
    detached.open(fs::path(df).is_absolute() ? fs::path(df) : fs::path(path).parent_path() / df, std::ios::binary);
    if (!detached)
    {
      throw Error("cannot open data file '" + df + "' named in the header", path);
    }
    data = &detached;
  }
  std::string line;
  for (long long k = std::atoll(keys["line skip"].c_str()); k > 0 && std::getline(*data, line); --k)
  {
  }
  const vtkIdType n = values->GetNumberOfValues();
  std::string word;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (!(*data >> word))
    {
      throw Error("text data holds " + std::to_string(i) + " values; the header's sizes need " + std::to_string(n), path);
    }
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (end == word.c_str() || *end != '\0')
    {
      throw Error("text data value " + std::to_string(i + 1) + " is not a number: '" + word + "'", path);
    }
    values->SetVariantValue(i, v);
  }
  return true;
}
} // namespace art
