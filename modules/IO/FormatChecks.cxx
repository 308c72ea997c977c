#include "FormatChecks.h"
#include "AtomicFile.h"
#include "Error.h"
#include "RegularFile.h"

#include <vtkImageReader.h>
#include <vtkNew.h>

#include <tiffio.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;

namespace art
{
namespace
{
long long FileSize(const std::string& path)
{
  std::error_code ec;
  return static_cast<long long>(fs::file_size(path, ec));
}

std::string Truncated(long long need, long long have)
{
  return "truncated: the header promises " + std::to_string(need) + " data bytes, the file holds " +
    std::to_string(std::max(0LL, have));
}

template <class T>
T Little(const unsigned char* b)
{
  T v;
  std::memcpy(&v, b, sizeof v);
  return v;
}

// The first `n` whole numbers of a text file's first lines that are not comments ('#').
std::vector<long long> LeadingCounts(const std::string& path, std::size_t n)
{
  std::ifstream in(path);
  std::vector<long long> v;
  std::string line;
  while (v.size() < n && std::getline(in, line))
  {
    if (line.empty() || line[0] == '#')
    {
      continue;
    }
    std::istringstream s(line);
    long long x;
    while (v.size() < n && s >> x)
    {
      v.push_back(x);
    }
    if (!s.eof() && v.size() < n)
    {
      break;
    }
  }
  return v;
}
} // namespace

namespace
{
// The SLC header: "11111 x y z bits sx sy sz unit origin modality compression", then the icon
// size "w h X" (its three planes follow the X directly). Returns the sizes and compression.
void ReadSlcHeader(std::istream& in, long long size[3], long long& compression, const std::string& path)
{
  long long magic = 0, bits = 0, unit = 0, origin = 0, modality = 0;
  double spacing[3] = { 0, 0, 0 };
  compression = -1;
  in >> magic >> size[0] >> size[1] >> size[2] >> bits >> spacing[0] >> spacing[1] >> spacing[2] >> unit >> origin >>
    modality >> compression;
  if (!in || magic != 11111)
  {
    throw Error("not an SLC file (no magic number 11111 and full header)", path);
  }
  for (int a = 0; a < 3; ++a)
  {
    if (size[a] < 1 || size[a] > 65535)
    {
      throw Error("SLC size " + std::to_string(size[a]) + " along " + "xyz"[a] + " is not 1..65535", path);
    }
    if (!(spacing[a] > 0) || !std::isfinite(spacing[a]))
    {
      throw Error(std::string("SLC spacing along ") + "xyz"[a] + " is not a positive number", path);
    }
  }
  if (bits != 8 || (compression != 0 && compression != 1))
  {
    throw Error("SLC file of " + std::to_string(bits) + "-bit voxels or compression " + std::to_string(compression) +
        ": VTK reads 8 bits, uncompressed (0) or run-length (1)",
      path);
  }
  in.ignore(1); // the line end after the header
  long long iconW = 0, iconH = 0;
  char x = 0; // "X" and then the bytes, with no blank between
  in >> iconW >> iconH >> x;
  if (!in || x != 'X' || iconW < 0 || iconH < 0 || iconW * iconH > (1LL << 30))
  {
    throw Error("SLC icon size is missing or malformed", path);
  }
  in.seekg(static_cast<std::streamoff>(in.tellg()) + 3 * iconW * iconH);
}

// Runs as vtkSLCReader decodes them: a count in the low 7 bits, then that many bytes (high bit
// set) or one byte repeated; a zero count ends the slice. They must fill it exactly (the reader
// wrote past the slice for a run too long).
void CheckSlcRuns(const std::vector<unsigned char>& packed, long long plane, long long z, const std::string& path)
{
  long long out = 0;
  std::size_t p = 0;
  for (;;)
  {
    if (p >= packed.size())
    {
      throw Error("SLC slice " + std::to_string(z) + "'s runs end without their closing zero", path);
    }
    const unsigned char c = packed[p++];
    const int n = c & 0x7F;
    if (n == 0)
    {
      break;
    }
    const std::size_t used = (c & 0x80) ? static_cast<std::size_t>(n) : 1;
    if (p + used > packed.size() || out + n > plane)
    {
      throw Error("SLC slice " + std::to_string(z) + "'s runs overrun the slice or its bytes", path);
    }
    p += used;
    out += n;
  }
  if (out != plane)
  {
    throw Error("SLC slice " + std::to_string(z) + " decodes to " + std::to_string(out) + " of its " +
        std::to_string(plane) + " voxels",
      path);
  }
}
} // namespace

void CheckSlc(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  long long size[3] = { 0, 0, 0 }, compression = -1;
  ReadSlcHeader(in, size, compression, path);
  const long long plane = size[0] * size[1];
  std::vector<unsigned char> packed;
  for (long long z = 0; z < size[2]; ++z)
  {
    long long bytes = plane;
    if (compression == 1)
    {
      char x = 0;
      bytes = -1;
      in >> bytes >> x;
      if (!in || x != 'X' || bytes < 0 || bytes > 2 * plane + 16)
      {
        throw Error("SLC slice " + std::to_string(z) + " has no valid compressed size", path);
      }
    }
    packed.resize(static_cast<std::size_t>(bytes));
    if (!in.read(reinterpret_cast<char*>(packed.data()), bytes))
    {
      throw Error("truncated: SLC slice " + std::to_string(z) + " of " + std::to_string(size[2]) + " is missing", path);
    }
    if (compression == 1)
    {
      CheckSlcRuns(packed, plane, z, path);
    }
  }
}

void CheckMrc(const std::string& path)
{
  unsigned char h[1024] = {};
  std::ifstream in(path, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(h), sizeof h))
  {
    throw Error("not an MRC file (shorter than its 1024-byte header)", path);
  }
  const std::int32_t n[3] = { Little<std::int32_t>(h), Little<std::int32_t>(h + 4), Little<std::int32_t>(h + 8) };
  const std::int32_t mode = Little<std::int32_t>(h + 12), extended = Little<std::int32_t>(h + 92);
  const int bytes = mode == 0 ? 1 : mode == 1 ? 2 : mode == 2 ? 4 : mode == 6 ? 2 : 0;
  if (bytes == 0)
  {
    throw Error("MRC mode " + std::to_string(mode) + " is not one VTK reads (0 int8, 1 int16, 2 float32, 6 uint16)", path);
  }
  long long voxels = 1;
  for (int a = 0; a < 3; ++a)
  {
    if (n[a] < 1 || n[a] > 1 << 20)
    {
      throw Error(std::string("MRC size along ") + "xyz"[a] + " is " + std::to_string(n[a]), path);
    }
    voxels *= n[a];
  }
  if (extended < 0)
  {
    throw Error("MRC extended header size is negative", path);
  }
  const long long need = voxels * bytes, have = FileSize(path) - 1024 - extended;
  if (have < need)
  {
    throw Error(Truncated(need, have), path);
  }
}

std::string CheckAnalyze(const std::string& path)
{
  const fs::path p(path);
  const std::string header = LowerExtension(path) == ".img" ? fs::path(p).replace_extension(".hdr").string() : path;
  const std::string image = fs::path(header).replace_extension(".img").string();
  for (const std::string& f : { header, image })
  {
    const std::string problem = RegularFileProblem(f);
    if (!problem.empty())
    {
      throw Error("the Analyze " + std::string(&f == &header ? "header" : "image") + " '" +
          fs::path(f).filename().string() + "': " + problem,
        path);
    }
  }
  unsigned char h[348] = {};
  std::ifstream in(header, std::ios::binary);
  in.read(reinterpret_cast<char*>(h), sizeof h);
  std::int32_t size = Little<std::int32_t>(h);
  const bool swap = size != 348;
  auto i16 = [&](int at) {
    unsigned char b[2] = { h[at], h[at + 1] };
    if (swap)
    {
      std::swap(b[0], b[1]);
    }
    return Little<std::int16_t>(b);
  };
  if (!in || (size != 348 && size != 0x5C010000))
  {
    throw Error("not an Analyze 7.5 header (sizeof_hdr is not 348)", header);
  }
  const int ndim = i16(40), bitpix = i16(72);
  if (ndim < 1 || ndim > 7 || bitpix <= 0 || bitpix % 8 != 0)
  {
    throw Error("Analyze header has " + std::to_string(ndim) + " dimensions of " + std::to_string(bitpix) + " bits", header);
  }
  long long voxels = 1;
  for (int d = 1; d <= std::min(ndim, 3); ++d)
  {
    const int n = i16(40 + 2 * d);
    if (n < 1)
    {
      throw Error("Analyze size of dimension " + std::to_string(d) + " is " + std::to_string(n), header);
    }
    voxels *= n;
  }
  const long long need = voxels * bitpix / 8, have = FileSize(image);
  if (have < need)
  {
    throw Error(Truncated(need, have), image);
  }
  return header;
}

void CheckAvsUcd(const std::string& path)
{
  // ASCII: "nodes cells node-data cell-data model-data" after the comments, a line per node
  // (id x y z) and per cell (id material type ids...), then the node data (components, labels,
  // a line per node). vtkAVSucdReader maps ids without a bound: a cell or data line naming a node
  // that is not there wrote past its tables. Binary files (a version byte first) are left to it.
  std::ifstream in(path, std::ios::binary);
  if (in.peek() == 7)
  {
    return;
  }
  std::string line;
  auto next = [&]() {
    while (std::getline(in, line))
    {
      if (!line.empty() && line[0] != '#')
      {
        return true;
      }
    }
    return false;
  };
  auto fail = [&](const std::string& what) { throw Error(what, path); };
  long long c[5] = { -1, -1, -1, -1, -1 };
  if (!next() || !(std::istringstream(line) >> c[0] >> c[1] >> c[2] >> c[3] >> c[4]) ||
    std::any_of(c, c + 5, [](long long x) { return x < 0; }))
  {
    fail("not an AVS UCD file (no line of five counts: nodes cells node-data cell-data model-data)");
  }
  if ((c[0] + c[1]) * 4 > FileSize(path))
  {
    fail(Truncated((c[0] + c[1]) * 4, FileSize(path)) + " (" + std::to_string(c[0]) + " nodes, " +
      std::to_string(c[1]) + " cells)");
  }
  std::set<long long> ids;
  for (long long i = 0; i < c[0]; ++i)
  {
    long long id;
    double x, y, z;
    if (!next() || !(std::istringstream(line) >> id >> x >> y >> z) || !ids.insert(id).second)
    {
      fail("node line " + std::to_string(i + 1) + " of " + std::to_string(c[0]) + " is missing, malformed or repeats an id");
    }
  }
  for (long long i = 0; i < c[1]; ++i)
  {
    std::istringstream cell(line);
    long long id, material, node;
    std::string type;
    if (!next() || !((cell = std::istringstream(line)) >> id >> material >> type))
    {
      fail("cell line " + std::to_string(i + 1) + " of " + std::to_string(c[1]) + " is missing or malformed");
    }
    static const std::set<std::string> types = { "pt", "line", "tri", "quad", "tet", "pyr", "prism", "hex" };
    if (!types.count(type))
    {
      fail("cell " + std::to_string(id) + " has type '" + type.substr(0, 20) + "', not one of pt line tri quad tet pyr prism hex");
    }
    while (cell >> node)
    {
      if (!ids.count(node))
      {
        fail("cell " + std::to_string(id) + " names node " + std::to_string(node) + ", which is not defined");
      }
    }
  }
  if (c[2] > 0)
  {
    // Node data: "n c1 c2 ..." components, n label lines, then a line per node.
    long long n = 0;
    if (!next() || !(std::istringstream(line) >> n) || n < 1 || n > 1000)
    {
      fail("the node data have no valid component line");
    }
    for (long long i = 0; i < n; ++i)
    {
      if (!next())
      {
        fail("truncated: the node data's labels are missing");
      }
    }
    for (long long i = 0; i < c[0]; ++i)
    {
      long long id;
      if (!next() || !(std::istringstream(line) >> id) || !ids.count(id))
      {
        fail("node data line " + std::to_string(i + 1) + " of " + std::to_string(c[0]) +
          " is missing or names a node that is not defined");
      }
    }
  }
}

void CheckTecplot(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string head(4096, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  std::string upper = head;
  std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
  if (head.rfind("#!TDV", 0) == 0)
  {
    throw Error("is a binary Tecplot file (.plt), which VTK does not read: save it as ASCII Tecplot", path);
  }
  const std::size_t variables = upper.find("VARIABLES"), zone = upper.find("\nZONE");
  if (zone == std::string::npos || variables == std::string::npos || variables > zone)
  {
    throw Error("not an ASCII Tecplot file (no VARIABLES line before a ZONE line)", path);
  }
  // Stray bytes in the header lines (a NUL in the variable names) sent the reader reading without end.
  for (std::size_t i = 0; i < std::min(head.size(), upper.find('\n', zone + 1)); ++i)
  {
    const auto c = static_cast<unsigned char>(head[i]);
    if ((c < 0x20 && c != '\n' && c != '\r' && c != '\t') || c >= 0x7F)
    {
      throw Error("the header holds a byte that is not ASCII text (" + std::to_string(c) + ") at byte " + std::to_string(i),
        path);
    }
  }
  // A zone must say how many points it has (N= or I=) and the file hold that many numbers after
  // it: vtkTecplotReader waited for them at the end of the file without end.
  {
    const std::size_t lineEnd = upper.find('\n', zone + 1);
    const std::string zoneLine = upper.substr(zone + 1, lineEnd == std::string::npos ? std::string::npos : lineEnd - zone - 1);
    long long points = -1;
    for (const char* key : { " N=", ",N=", " N =", " I=", ",I=" })
    {
      const std::size_t k = zoneLine.find(key);
      if (k != std::string::npos)
      {
        points = std::atoll(zoneLine.c_str() + k + std::strlen(key));
        break;
      }
    }
    if (points < 1)
    {
      throw Error("the first ZONE line gives no point count (N= or I=)", path);
    }
    std::ifstream data(path, std::ios::binary);
    data.seekg(static_cast<std::streamoff>(lineEnd == std::string::npos ? head.size() : lineEnd));
    long long numbers = 0;
    for (std::string w; numbers < points && data >> w;)
    {
      numbers += (std::isdigit(static_cast<unsigned char>(w[0])) || w[0] == '-' || w[0] == '.' || w[0] == '+') ? 1 : 0;
    }
    if (numbers < points)
    {
      throw Error("truncated: the first zone has " + std::to_string(points) + " points but " + std::to_string(numbers) +
          " numbers follow it",
        path);
    }
  }
  // An unclosed quote (in the variable names, in a ZONE line) sent vtkTecplotReader reading the
  // rest of the file as one word, without end.
  std::istringstream lines(head);
  int number = 0;
  for (std::string line; std::getline(lines, line);)
  {
    ++number;
    const bool cut = lines.eof() && head.size() == 4096; // the last line read may go on
    if (std::count(line.begin(), line.end(), '"') % 2 != 0 && !cut)
    {
      throw Error("line " + std::to_string(number) + " has an unclosed quote", path);
    }
  }
}

void CheckGambit(const std::string& path)
{
  // The counts line, then NODAL COORDINATES (a line per node), ELEMENTS/CELLS (id, type, node
  // count, nodes) and ELEMENT GROUPs naming elements. vtkGAMBITReader indexes its tables by what
  // these say without a bound (a group naming elements of a missing section read past them).
  std::ifstream in(path);
  std::string line;
  for (int i = 0; i < 6 && std::getline(in, line); ++i)
  {
  }
  long long numnp = -1, nelem = -1, ngrps = -1, nbsets = -1, ndfcd = -1, ndfvl = -1;
  in >> numnp >> nelem >> ngrps >> nbsets >> ndfcd >> ndfvl;
  if (!in || numnp < 0 || nelem < 0 || ngrps < 0 || nbsets < 0 || (ndfcd != 2 && ndfcd != 3))
  {
    throw Error("not a GAMBIT neutral file (no NUMNP NELEM NGRPS NBSETS NDFCD NDFVL counts)", path);
  }
  if ((numnp + nelem) * 4 > FileSize(path))
  {
    throw Error(Truncated((numnp + nelem) * 4, FileSize(path)), path);
  }
  auto section = [&](const char* name) {
    while (std::getline(in, line))
    {
      if (line.find(name) != std::string::npos)
      {
        return true;
      }
    }
    throw Error(std::string("has no ") + name + " section", path);
  };
  section("NODAL COORDINATES");
  for (long long i = 0; i < numnp; ++i)
  {
    long long id;
    double x[3];
    if (!(in >> id >> x[0] >> x[1]) || (ndfcd == 3 && !(in >> x[2])) || id != i + 1)
    {
      throw Error("node " + std::to_string(i + 1) + " of " + std::to_string(numnp) + " is missing or out of order", path);
    }
  }
  section("ELEMENTS/CELLS");
  for (long long i = 0; i < nelem; ++i)
  {
    long long id, type, n;
    if (!(in >> id >> type >> n) || id != i + 1 || n < 1 || n > 27)
    {
      throw Error("element " + std::to_string(i + 1) + " of " + std::to_string(nelem) + " is missing or malformed", path);
    }
    for (long long k = 0; k < n; ++k)
    {
      long long node;
      if (!(in >> node) || node < 1 || node > numnp)
      {
        throw Error("element " + std::to_string(i + 1) + " names a node outside 1.." + std::to_string(numnp), path);
      }
    }
  }
  for (long long g = 0; g < ngrps; ++g)
  {
    section("ELEMENT GROUP");
    long long group = 0, count = -1, material = 0, flags = -1;
    std::string w[4];
    if (!(in >> w[0] >> group >> w[1] >> count >> w[2] >> material >> w[3] >> flags) || count < 0 || count > nelem ||
      flags < 0 || flags > 100)
    {
      throw Error("element group " + std::to_string(g + 1) + " has no valid header", path);
    }
    std::string name;
    in >> name;
    for (long long k = 0; k < flags + count; ++k)
    {
      long long v;
      if (!(in >> v) || (k >= flags && (v < 1 || v > nelem)))
      {
        throw Error("element group " + std::to_string(g + 1) + " names an element outside 1.." + std::to_string(nelem), path);
      }
    }
  }
}

void CheckByu(const std::string& path)
{
  // Header "parts points polygons corners", the parts' first and last polygons, 3 coordinates
  // per point, then the corners: point numbers from 1, a polygon's last one negative. Read here
  // token by token: vtkBYUReader looped without end on a word where it wanted a number.
  std::ifstream in(path);
  long long parts = -1, points = -1, polygons = -1, corners = -1;
  in >> parts >> points >> polygons >> corners;
  if (!in || parts < 1 || points < 1 || polygons < 1 || corners < 3 || points > (1LL << 31) || corners > (1LL << 31))
  {
    throw Error("not a BYU file (no line of counts: parts points polygons corners)", path);
  }
  if ((points * 3 + corners) * 2 > FileSize(path))
  {
    throw Error(Truncated((points * 3 + corners) * 2, FileSize(path)) + " (" + std::to_string(points) + " points, " +
        std::to_string(corners) + " corners)",
      path);
  }
  for (long long i = 0; i < 2 * parts; ++i)
  {
    long long v;
    if (!(in >> v) || v < 1 || v > polygons)
    {
      throw Error("a part's polygon range is missing or outside 1.." + std::to_string(polygons), path);
    }
  }
  for (long long i = 0; i < 3 * points; ++i)
  {
    double x;
    if (!(in >> x) || !std::isfinite(x))
    {
      throw Error("coordinate " + std::to_string(i / 3 + 1) + " of " + std::to_string(points) +
          " points is missing or not a number",
        path);
    }
  }
  long long ends = 0;
  for (long long i = 0; i < corners; ++i)
  {
    long long v;
    if (!(in >> v) || v == 0 || std::llabs(v) > points)
    {
      throw Error("corner " + std::to_string(i + 1) + " of " + std::to_string(corners) +
          " is missing or names no point of 1.." + std::to_string(points),
        path);
    }
    ends += v < 0;
  }
  if (ends != polygons)
  {
    throw Error("the corners close " + std::to_string(ends) + " polygons; the header counts " +
        std::to_string(polygons),
      path);
  }
}

void CheckTiff(const std::string& path)
{
  // libtiff's own warnings and errors would reach the terminal; the check says what is wrong.
  TIFFSetWarningHandler(nullptr);
  TIFFSetErrorHandler(nullptr);
  TIFF* t = TIFFOpen(path.c_str(), "r");
  if (!t)
  {
    throw Error("is not a TIFF file libtiff opens", path);
  }
  std::string problem;
  int page = 0;
  const int directories = TIFFNumberOfDirectories(t); // what vtkTIFFReader reads as pages
  std::uint16_t pagesSaid = 0;
  std::uint32_t firstW = 0, firstH = 0;
  do
  {
    std::uint32_t w = 0, h = 0, rows = 0;
    std::uint16_t bits = 0, samples = 1, photometric = 0, sub[2] = { 1, 1 };
    TIFFGetField(t, TIFFTAG_IMAGEWIDTH, &w);
    TIFFGetField(t, TIFFTAG_IMAGELENGTH, &h);
    TIFFGetFieldDefaulted(t, TIFFTAG_BITSPERSAMPLE, &bits);
    TIFFGetFieldDefaulted(t, TIFFTAG_SAMPLESPERPIXEL, &samples);
    TIFFGetFieldDefaulted(t, TIFFTAG_PHOTOMETRIC, &photometric);
    const bool tiled = TIFFIsTiled(t);
    if (!tiled)
    {
      TIFFGetFieldDefaulted(t, TIFFTAG_ROWSPERSTRIP, &rows);
    }
    if (photometric == PHOTOMETRIC_YCBCR)
    {
      TIFFGetFieldDefaulted(t, TIFFTAG_YCBCRSUBSAMPLING, &sub[0], &sub[1]);
    }
    const auto goodSub = [](std::uint16_t v) { return v == 1 || v == 2 || v == 4; };
    // libtiff divided by a zero strip height or subsampling (a floating-point exception).
    if (w == 0 || h == 0 || (!tiled && rows == 0) || !(bits == 1 || bits == 8 || bits == 16 || bits == 32 || bits == 64) ||
      samples < 1 || samples > 4 || !goodSub(sub[0]) || !goodSub(sub[1]) || TIFFScanlineSize64(t) <= 0)
    {
      problem = "page " + std::to_string(page + 1) + " is " + std::to_string(w) + " x " + std::to_string(h) + " of " +
        std::to_string(samples) + " x " + std::to_string(bits) + "-bit samples in strips of " + std::to_string(rows) +
        " rows: not an image VTK's TIFF reader reads";
    }
    std::uint16_t number = 0, total = 0;
    if (TIFFGetField(t, TIFFTAG_PAGENUMBER, &number, &total))
    {
      pagesSaid = std::max(pagesSaid, total);
    }
    if (problem.empty() && page > 0 && (w != firstW || h != firstH))
    {
      problem = "page " + std::to_string(page + 1) + " is " + std::to_string(w) + " x " + std::to_string(h) +
        ", page 1 " + std::to_string(firstW) + " x " + std::to_string(firstH) + ": the pages of a volume share a size";
    }
    firstW = page == 0 ? w : firstW;
    firstH = page == 0 ? h : firstH;
    ++page;
  } while (problem.empty() && page < 100000 && TIFFReadDirectory(t));
  // The pages VTK reads as slices are the ones the PageNumber tag counts; fewer readable pages
  // had libtiff read a missing one (a floating-point exception).
  if (problem.empty() && directories > page)
  {
    problem = "it links " + std::to_string(directories) + " pages; " + std::to_string(page) +
      " can be read (damaged or cut short)";
  }
  if (problem.empty() && pagesSaid > page)
  {
    problem = "its PageNumber tags count " + std::to_string(pagesSaid) + " pages; " + std::to_string(page) +
      " can be read (damaged or cut short)";
  }
  TIFFClose(t);
  if (!problem.empty())
  {
    throw Error(problem, path);
  }
}

vtkSmartPointer<vtkAlgorithm> BioRadReader(const std::string& path)
{
  unsigned char h[76] = {};
  std::ifstream in(path, std::ios::binary);
  in.read(reinterpret_cast<char*>(h), sizeof h);
  const int nx = Little<std::uint16_t>(h), ny = Little<std::uint16_t>(h + 2), npic = Little<std::uint16_t>(h + 4);
  const int byteFormat = Little<std::int16_t>(h + 14), fileId = Little<std::int16_t>(h + 54);
  if (!in || fileId != 12345)
  {
    throw Error("not a BioRad .pic file (no file id 12345 at byte 54)", path);
  }
  if (nx < 1 || ny < 1 || npic < 1)
  {
    throw Error("BioRad sizes " + std::to_string(nx) + " x " + std::to_string(ny) + " x " + std::to_string(npic) +
        " are not positive",
      path);
  }
  const int bytes = byteFormat == 1 ? 1 : 2;
  const long long need = static_cast<long long>(nx) * ny * npic * bytes;
  if (FileSize(path) - 76 < need)
  {
    throw Error(Truncated(need, FileSize(path) - 76), path);
  }
  // Notes follow the voxels: 16-byte headers and 80 characters each; "AXIS_2 001 start step
  // microns" (x), AXIS_3 (y) and AXIS_4 (z) give the spacing.
  double spacing[3] = { 1, 1, 1 };
  in.seekg(76 + need);
  unsigned char note[96];
  for (int k = 0; k < 10000 && in.read(reinterpret_cast<char*>(note), sizeof note); ++k)
  {
    const std::string text(reinterpret_cast<char*>(note) + 16, strnlen(reinterpret_cast<char*>(note) + 16, 80));
    std::istringstream s(text);
    std::string axis, code;
    double start = 0, step = 0;
    if (s >> axis >> code >> start >> step && axis.rfind("AXIS_", 0) == 0 && code == "001")
    {
      const int a = std::atoi(axis.c_str() + 5) - 2;
      if (a >= 0 && a < 3 && step > 0 && std::isfinite(step))
      {
        spacing[a] = step;
      }
    }
    if (Little<std::int32_t>(note + 2) == 0)
    {
      break; // the last note
    }
  }
  vtkNew<vtkImageReader> r;
  r->SetFileName(path.c_str());
  r->SetFileDimensionality(3);
  r->SetHeaderSize(76);
  r->SetDataScalarType(bytes == 1 ? VTK_UNSIGNED_CHAR : VTK_UNSIGNED_SHORT);
  r->SetDataByteOrderToLittleEndian();
  r->SetDataExtent(0, nx - 1, 0, ny - 1, 0, npic - 1);
  r->SetDataSpacing(spacing);
  r->FileLowerLeftOn();
  r->SetScalarArrayName("BioRad");
  return vtkSmartPointer<vtkAlgorithm>(r.GetPointer());
}
} // namespace art
