#include "XmlCheck.h"
#include "Error.h"
#include "RegularFile.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;

namespace art
{
namespace
{
// The XML part of a file is read whole up to this size; VTK's own files keep it at the front (an
// appended file's data follow it), and a larger inline file has its end and first part checked.
constexpr std::size_t MaxXmlBytes = std::size_t(64) << 20;
constexpr int MaxDepth = 128; // VTK's files nest 7 deep; its parser recurses once per level
constexpr long long MaxCount = 1LL << 40;

using Attributes = std::map<std::string, std::string>;

struct Appended
{
  std::string Name;
  long long Offset = 0;
};

struct Scan
{
  std::string Type, HeaderType = "UInt32", Compressor, ByteOrder = "LittleEndian", Encoding = "raw";
  long long AppendStart = -1; ///< file offset of the appended data (after '_'), or -1
  std::vector<Appended> Arrays;
  std::vector<std::string> Files; ///< pieces (Source) and blocks (file) named by the file
  XmlCounts Counts;
};

bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

bool Integer(const std::string& text, long long& v)
{
  char* end = nullptr;
  errno = 0;
  v = std::strtoll(text.c_str(), &end, 10);
  while (end && IsSpace(*end))
  {
    ++end;
  }
  return !text.empty() && end && *end == '\0' && errno == 0;
}

std::vector<double> Numbers(const std::string& text)
{
  std::vector<double> v;
  const char* p = text.c_str();
  for (;;)
  {
    char* end = nullptr;
    const double x = std::strtod(p, &end);
    if (end == p)
    {
      break;
    }
    v.push_back(x);
    p = end;
  }
  return v;
}

// A count attribute (NumberOfCells="-5" crashed VTK's reader): a whole number in [0, 2^40).
long long Count(const Attributes& a, const std::string& key, const std::string& element, const std::string& path)
{
  const auto it = a.find(key);
  if (it == a.end())
  {
    return -1;
  }
  long long v = 0;
  if (!Integer(it->second, v) || v < 0 || v >= MaxCount)
  {
    throw Error(element + " " + key + "=\"" + it->second.substr(0, 40) + "\" is not a count (a whole number >= 0)", path);
  }
  return v;
}

void CheckExtent(const Attributes& a, const std::string& key, const std::string& element, const std::string& path)
{
  const auto it = a.find(key);
  if (it == a.end())
  {
    return;
  }
  std::istringstream in(it->second);
  long long e[6];
  for (long long& x : e)
  {
    std::string w;
    if (!(in >> w) || !Integer(w, x) || std::llabs(x) > (1LL << 31) - 1)
    {
      throw Error(element + " " + key + "=\"" + it->second.substr(0, 60) + "\" is not six whole numbers", path);
    }
  }
  for (int d = 0; d < 3; ++d)
  {
    if (e[2 * d + 1] < e[2 * d] - 1)
    {
      throw Error(element + " " + key + "=\"" + it->second.substr(0, 60) + "\" ends before it starts", path);
    }
  }
}

// Origin, Spacing and Direction of image data: finite numbers ("nan nan nan" read as spacing 1).
void CheckGeometry(const Attributes& a, const std::string& element, const std::string& path)
{
  for (const auto& [key, n] : { std::pair<const char*, std::size_t>{ "Origin", 3 }, { "Spacing", 3 }, { "Direction", 9 } })
  {
    const auto it = a.find(key);
    if (it == a.end())
    {
      continue;
    }
    const std::vector<double> v = Numbers(it->second);
    if (v.size() < n || std::any_of(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }))
    {
      throw Error(element + " " + key + "=\"" + it->second.substr(0, 60) + "\" is not " + std::to_string(n) +
          " finite numbers",
        path);
    }
  }
}

void CheckElement(const std::string& name, const Attributes& a, Scan& s, const std::string& path)
{
  auto value = [&a](const char* key) {
    const auto it = a.find(key);
    return it == a.end() ? std::string() : it->second;
  };
  if (name == "VTKFile")
  {
    s.Type = value("type");
    s.HeaderType = a.count("header_type") ? value("header_type") : s.HeaderType;
    s.Compressor = value("compressor");
    s.ByteOrder = a.count("byte_order") ? value("byte_order") : s.ByteOrder;
    if (s.HeaderType != "UInt32" && s.HeaderType != "UInt64")
    {
      throw Error("VTKFile header_type=\"" + s.HeaderType.substr(0, 20) + "\" is neither UInt32 nor UInt64", path);
    }
  }
  else if (name == "ImageData" || name == "PImageData" || name == "RectilinearGrid" || name == "StructuredGrid" ||
    name == "PRectilinearGrid" || name == "PStructuredGrid")
  {
    CheckExtent(a, "WholeExtent", name, path);
    CheckGeometry(a, name, path);
  }
  else if (name == "Piece")
  {
    CheckExtent(a, "Extent", name, path);
    const long long points = Count(a, "NumberOfPoints", name, path);
    const long long cells = Count(a, "NumberOfCells", name, path);
    const long long polys = Count(a, "NumberOfPolys", name, path), strips = Count(a, "NumberOfStrips", name, path);
    const long long lines = Count(a, "NumberOfLines", name, path), verts = Count(a, "NumberOfVerts", name, path);
    s.Counts.Complete = s.Counts.Complete && (points >= 0 || a.count("Source"));
    s.Counts.Points += std::max(0LL, points);
    s.Counts.Cells += std::max(0LL, cells);
    s.Counts.Polys += std::max(0LL, polys);
    s.Counts.Strips += std::max(0LL, strips);
    s.Counts.Lines += std::max(0LL, lines);
    s.Counts.Verts += std::max(0LL, verts);
    if (a.count("Source"))
    {
      s.Files.push_back(value("Source"));
    }
  }
  else if (name == "DataSet" && a.count("file"))
  {
    s.Files.push_back(value("file"));
  }
  else if (name == "DataArray" || name == "PDataArray" || name == "Array")
  {
    const long long components = Count(a, "NumberOfComponents", name, path);
    Count(a, "NumberOfTuples", name, path);
    if (components == 0)
    {
      throw Error(name + " '" + value("Name").substr(0, 40) + "' has NumberOfComponents=\"0\"", path);
    }
    if (value("format") == "appended")
    {
      const long long offset = Count(a, "offset", name, path);
      s.Arrays.push_back({ value("Name"), std::max(0LL, offset) });
    }
  }
}

// Reads the attributes of the tag starting at `p` (after its name) up to '>' or "/>".
std::size_t ParseAttributes(const std::string& t, std::size_t p, Attributes& a, bool& selfClosing)
{
  selfClosing = false;
  while (p < t.size())
  {
    while (p < t.size() && IsSpace(t[p]))
    {
      ++p;
    }
    if (p < t.size() && t[p] == '>')
    {
      return p + 1;
    }
    if (p + 1 < t.size() && t[p] == '/' && t[p + 1] == '>')
    {
      selfClosing = true;
      return p + 2;
    }
    const std::size_t k = p;
    while (p < t.size() && !IsSpace(t[p]) && t[p] != '=' && t[p] != '>' && t[p] != '/')
    {
      ++p;
    }
    const std::string key = t.substr(k, p - k);
    while (p < t.size() && IsSpace(t[p]))
    {
      ++p;
    }
    if (p >= t.size() || t[p] != '=' || key.empty())
    {
      return std::string::npos;
    }
    ++p;
    while (p < t.size() && IsSpace(t[p]))
    {
      ++p;
    }
    if (p >= t.size() || (t[p] != '"' && t[p] != '\''))
    {
      return std::string::npos;
    }
    const std::size_t close = t.find(t[p], p + 1);
    if (close == std::string::npos)
    {
      return std::string::npos;
    }
    a[key] = t.substr(p + 1, close - p - 1);
    p = close + 1;
  }
  return std::string::npos;
}

// Walks the tags of the XML part, checking each element, up to the appended data's '_'.
void ScanTags(const std::string& t, Scan& s, const std::string& path)
{
  int depth = 0;
  std::size_t p = 0;
  while ((p = t.find('<', p)) != std::string::npos)
  {
    auto skipTo = [&](const char* end) {
      const std::size_t e = t.find(end, p);
      p = e == std::string::npos ? t.size() : e + std::strlen(end);
    };
    if (t.compare(p, 4, "<!--") == 0)
    {
      skipTo("-->");
      continue;
    }
    if (t.compare(p, 2, "<?") == 0 || t.compare(p, 2, "<!") == 0)
    {
      skipTo(">");
      continue;
    }
    if (t.compare(p, 2, "</") == 0)
    {
      --depth;
      skipTo(">");
      continue;
    }
    std::size_t n = p + 1;
    while (n < t.size() && !IsSpace(t[n]) && t[n] != '>' && t[n] != '/')
    {
      ++n;
    }
    const std::string name = t.substr(p + 1, n - p - 1);
    Attributes a;
    bool selfClosing = false;
    const std::size_t end = ParseAttributes(t, n, a, selfClosing);
    if (end == std::string::npos)
    {
      if (t.size() >= MaxXmlBytes)
      {
        return; // the part read ends inside a tag: what was read is checked
      }
      throw Error("cannot read: malformed XML: the tag <" + name.substr(0, 30) + "> is not closed", path);
    }
    CheckElement(name, a, s, path);
    p = end;
    if (name == "AppendedData")
    {
      s.Encoding = a.count("encoding") ? a["encoding"] : s.Encoding;
      const std::size_t mark = t.find('_', p);
      s.AppendStart = mark == std::string::npos ? -1 : static_cast<long long>(mark + 1);
      if (mark == std::string::npos && t.size() < MaxXmlBytes)
      {
        throw Error("truncated: the appended data has no '_' mark", path);
      }
      return;
    }
    if (!selfClosing && ++depth > MaxDepth)
    {
      throw Error("XML elements nest more than " + std::to_string(MaxDepth) +
          " deep, which no VTK file does (VTK's reader would overflow its stack)",
        path);
    }
  }
}

unsigned long long ReadHeaderWord(std::ifstream& in, int size, bool bigEndian, bool& ok)
{
  unsigned char b[8] = {};
  ok = static_cast<bool>(in.read(reinterpret_cast<char*>(b), size));
  if (bigEndian)
  {
    std::reverse(b, b + size);
  }
  unsigned long long v = 0;
  for (int i = size - 1; i >= 0; --i)
  {
    v = (v << 8) | b[i];
  }
  return v;
}

// The first `n` bytes base64 encodes at `at` (VTK encodes each array's length header apart from
// its data); false when the file ends first or holds other characters.
bool DecodeBase64(std::ifstream& in, long long at, int n, unsigned char* out)
{
  static const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text((n + 2) / 3 * 4, '\0');
  in.clear();
  in.seekg(at);
  if (!in.read(&text[0], static_cast<std::streamsize>(text.size())))
  {
    return false;
  }
  int got = 0;
  for (std::size_t i = 0; i < text.size() && got < n; i += 4)
  {
    unsigned v = 0;
    for (int k = 0; k < 4; ++k)
    {
      const std::size_t d = text[i + k] == '=' ? 0 : alphabet.find(text[i + k]);
      if (d == std::string::npos)
      {
        return false;
      }
      v = v << 6 | static_cast<unsigned>(d);
    }
    for (int k = 2; k >= 0 && got < n; --k)
    {
      out[got++] = static_cast<unsigned char>(v >> (8 * k));
    }
  }
  return got == n;
}

// Base64 appended data: each array's length (or its compressed blocks' count) must be what the
// rest of the file can hold, 3 bytes for every 4 characters (a block count of billions had VTK
// allocate for them).
void CheckBase64Appended(const Scan& s, std::ifstream& in, int h, bool big, long long fileSize, const std::string& path)
{
  for (const Appended& a : s.Arrays)
  {
    const long long at = s.AppendStart + a.Offset;
    unsigned char word[8] = {};
    if (!DecodeBase64(in, at, h, word))
    {
      throw Error("truncated or damaged: the base64 appended data of array '" + a.Name.substr(0, 40) +
          "' have no readable length",
        path);
    }
    if (big)
    {
      std::reverse(word, word + h);
    }
    unsigned long long first = 0;
    for (int i = h - 1; i >= 0; --i)
    {
      first = (first << 8) | word[i];
    }
    const unsigned long long room = static_cast<unsigned long long>(std::max(0LL, fileSize - at)) * 3 / 4;
    const unsigned long long need = s.Compressor.empty() ? first : first * static_cast<unsigned long long>(h);
    if (need > room)
    {
      throw Error("truncated or damaged: the base64 appended data of array '" + a.Name.substr(0, 40) + "' claim " +
          std::to_string(need) + " bytes, the file holds at most " + std::to_string(room),
        path);
    }
  }
}

// Each appended array's bytes (its length header, and for compressed data its block table) must
// lie within the file: VTK read the missing bytes of a cut file as zeros.
void CheckAppended(const Scan& s, long long fileSize, const std::string& path)
{
  if (s.AppendStart < 0)
  {
    return;
  }
  std::ifstream in(path, std::ios::binary);
  const int h = s.HeaderType == "UInt64" ? 8 : 4;
  const bool big = s.ByteOrder == "BigEndian";
  if (s.Encoding == "base64")
  {
    CheckBase64Appended(s, in, h, big, fileSize, path);
    return;
  }
  for (const Appended& a : s.Arrays)
  {
    const long long at = s.AppendStart + a.Offset;
    bool ok = at + h <= fileSize;
    long long end = at + h;
    if (ok)
    {
      in.seekg(at);
      const unsigned long long first = ReadHeaderWord(in, h, big, ok);
      if (s.Compressor.empty())
      {
        end += static_cast<long long>(std::min<unsigned long long>(first, 1ULL << 62));
      }
      else
      {
        // Compressed: blocks, block size, last block size, then each block's compressed size.
        const unsigned long long blocks = first;
        ok = ok && blocks < (1ULL << 31) && at + h * (3 + static_cast<long long>(blocks)) <= fileSize;
        if (ok)
        {
          const unsigned long long blockSize = ReadHeaderWord(in, h, big, ok);
          const unsigned long long lastSize = ReadHeaderWord(in, h, big, ok);
          end = at + h * (3 + static_cast<long long>(blocks));
          for (unsigned long long b = 0; ok && b < blocks; ++b)
          {
            const unsigned long long packed = std::min<unsigned long long>(ReadHeaderWord(in, h, big, ok), 1ULL << 40);
            // zlib packs at most 1032 to 1: a block said to hold more (VTK allocated and zeroed
            // gigabytes for one) is damage.
            const unsigned long long unpacked = b + 1 == blocks && lastSize > 0 ? lastSize : blockSize;
            if (unpacked > 1032 * packed + 1024 || unpacked > (1ULL << 31))
            {
              throw Error("the compressed appended data of array '" + a.Name.substr(0, 40) + "' claim " +
                  std::to_string(unpacked) + " bytes from a block of " + std::to_string(packed),
                path);
            }
            end += static_cast<long long>(packed);
          }
        }
      }
    }
    if (!ok || end > fileSize)
    {
      throw Error("truncated: the appended data of array '" + a.Name.substr(0, 40) + "' " +
          (ok ? "end at byte " + std::to_string(end) + ", the file holds " + std::to_string(fileSize)
              : "start past the end of the file or have an unreadable length"),
        path);
    }
  }
}

// VTK's writers end every file with </VTKFile>; one cut short does not.
void CheckEnd(const std::string& path, long long fileSize)
{
  std::ifstream in(path, std::ios::binary);
  const long long n = std::min<long long>(fileSize, 4096);
  in.seekg(fileSize - n);
  std::string tail(static_cast<std::size_t>(n), '\0');
  in.read(&tail[0], n);
  while (!tail.empty() && (IsSpace(tail.back()) || tail.back() == '\0'))
  {
    tail.pop_back();
  }
  const std::string end = "</VTKFile>";
  if (tail.size() < end.size() || tail.compare(tail.size() - end.size(), end.size(), end) != 0)
  {
    throw Error("truncated: the file does not end with </VTKFile> (cut short, or not a VTK XML file)", path);
  }
}

XmlCounts CheckFile(const std::string& path, int level)
{
  RequireRegularFile(path);
  std::error_code ec;
  const long long size = static_cast<long long>(fs::file_size(path, ec));
  std::ifstream in(path, std::ios::binary);
  std::string text(static_cast<std::size_t>(std::min<long long>(size, static_cast<long long>(MaxXmlBytes))), '\0');
  in.read(&text[0], static_cast<std::streamsize>(text.size()));
  // Only the XML part: an appended file's binary data follow its <AppendedData> tag.
  const std::size_t appended = text.find("<AppendedData");
  if (appended != std::string::npos)
  {
    const std::size_t mark = text.find('_', text.find('>', appended));
    text.resize(mark == std::string::npos ? text.size() : mark + 1);
  }
  if (text.find("<VTKFile") == std::string::npos)
  {
    throw Error("not a VTK XML file (no <VTKFile> element)", path);
  }
  Scan s;
  ScanTags(text, s, path);
  CheckEnd(path, size);
  CheckAppended(s, size, path);
  XmlCounts counts = s.Counts;
  if (level < 2)
  {
    for (const std::string& f : s.Files)
    {
      const fs::path p = fs::path(f).is_absolute() ? fs::path(f) : fs::path(path).parent_path() / f;
      const std::string problem = RegularFileProblem(p.string());
      if (!problem.empty())
      {
        throw Error("the piece '" + f + "' it names: " + problem, path);
      }
      const XmlCounts c = CheckFile(p.string(), level + 1);
      counts.Points += c.Points;
      counts.Cells += c.Cells;
      counts.Polys += c.Polys;
      counts.Strips += c.Strips;
      counts.Lines += c.Lines;
      counts.Verts += c.Verts;
      counts.Complete = counts.Complete && c.Complete;
    }
  }
  return counts;
}
} // namespace

XmlCounts CheckVtkXml(const std::string& path)
{
  return CheckFile(path, 0);
}
} // namespace art
