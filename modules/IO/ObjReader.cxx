#include "ObjReader.h"
#include "Error.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

namespace art
{
namespace
{
enum Field
{
  V,
  T,
  N
};
const char* const FieldName[3] = { "vertex", "texture coordinate", "normal" };

// One corner of a face, line or point: 0-based indices, -1 where the file gives none.
using Corner = std::array<std::int32_t, 3>;

struct CornerHash
{
  std::size_t operator()(const Corner& c) const
  {
    std::uint64_t h = static_cast<std::uint32_t>(c[0]);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(c[1]);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(c[2]);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

struct Cell
{
  char kind; // 'f', 'l' or 'p'
  std::size_t first, count; // into Obj::Corners
  int material;             // into Obj::Materials, -1 before any usemtl
};

struct Obj
{
  std::vector<double> Coords[3]; // v (3 per vertex), vt (2 per coordinate), vn (3 per normal)
  std::size_t Count[3] = { 0, 0, 0 };
  std::vector<Corner> Corners;
  std::vector<Cell> Cells;
  std::vector<double> Colors; // r g b per vertex of "v x y z r g b" (photogrammetry exports)
  std::size_t Colored = 0;
  std::vector<std::string> Libraries, Materials; // mtllib files; usemtl names in order of use
  int Material = -1;
};

bool IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

const char* SkipSpace(const char* p)
{
  while (IsSpace(*p))
  {
    ++p;
  }
  return p;
}

// Reads up to `want` numbers after the keyword; `need` of them must be there.
void ReadNumbers(const char* p, int need, int want, std::vector<double>& out, long long line, const std::string& path)
{
  int got = 0;
  for (; got < want; ++got)
  {
    p = SkipSpace(p);
    char* end = nullptr;
    const double x = std::strtod(p, &end);
    if (end == p)
    {
      break;
    }
    out.push_back(x);
    p = end;
  }
  if (got < need)
  {
    throw Error("line " + std::to_string(line) + ": expected " + std::to_string(need) + " numbers, found " +
        std::to_string(got),
      path);
  }
  for (; got < want; ++got)
  {
    out.push_back(0.0); // an optional v of "vt u"
  }
}

// Up to `most` numbers after the keyword into `out`; returns how many there were.
int ParseUpTo(const char* p, double* out, int most)
{
  int n = 0;
  for (; n < most; ++n)
  {
    p = SkipSpace(p);
    char* end = nullptr;
    out[n] = std::strtod(p, &end);
    if (end == p)
    {
      break;
    }
    p = end;
  }
  return n;
}

// "v", "v/vt", "v//vn" or "v/vt/vn": 1-based or negative (counted back from the last defined).
Corner ReadCorner(const std::string& item, const Obj& obj, long long line, const char* element, const std::string& path)
{
  Corner c = { -1, -1, -1 };
  std::size_t a = 0;
  for (int field = V; field <= N && a <= item.size(); ++field)
  {
    const std::size_t b = std::min(item.find('/', a), item.size());
    if (b > a)
    {
      const std::string text = item.substr(a, b - a);
      char* end = nullptr;
      errno = 0;
      const long long i = std::strtoll(text.c_str(), &end, 10);
      const long long n = static_cast<long long>(obj.Count[field]);
      const long long at = i > 0 ? i - 1 : n + i;
      if (*end != '\0' || errno || i == 0 || at < 0 || at >= n)
      {
        throw Error("line " + std::to_string(line) + ": " + element + " refers to " + FieldName[field] + " " + text +
            " of " + std::to_string(n) + " defined",
          path);
      }
      c[field] = static_cast<std::int32_t>(at);
    }
    else if (field == V)
    {
      throw Error("line " + std::to_string(line) + ": " + element + " corner '" + item + "' has no vertex", path);
    }
    a = b + 1;
  }
  return c;
}

void ReadCell(char kind, const char* p, Obj& obj, long long line, const std::string& path)
{
  const char* element = kind == 'f' ? "a face" : kind == 'l' ? "a line" : "a point";
  Cell cell{ kind, obj.Corners.size(), 0, obj.Material };
  for (p = SkipSpace(p); *p; p = SkipSpace(p))
  {
    const char* e = p;
    while (*e && !IsSpace(*e))
    {
      ++e;
    }
    obj.Corners.push_back(ReadCorner(std::string(p, e), obj, line, element, path));
    p = e;
  }
  cell.count = obj.Corners.size() - cell.first;
  const std::size_t least = kind == 'f' ? 3 : kind == 'l' ? 2 : 1;
  if (cell.count < least)
  {
    throw Error("line " + std::to_string(line) + ": " + element + " needs at least " + std::to_string(least) +
        " corners, it has " + std::to_string(cell.count),
      path);
  }
  obj.Cells.push_back(cell);
}

Obj Parse(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw Error("cannot open file", path);
  }
  Obj obj;
  std::string line, more;
  long long number = 0;
  // A physical line without its comment and trailing blanks (a "\" inside a comment continues nothing).
  auto next = [&in, &number](std::string& s) {
    if (!std::getline(in, s))
    {
      return false;
    }
    ++number;
    if (number == 1 && s.rfind("\xEF\xBB\xBF", 0) == 0)
    {
      s.erase(0, 3); // a UTF-8 byte-order mark (some Windows exporters): its first vertex was lost
    }
    if (const std::size_t hash = s.find('#'); hash != std::string::npos)
    {
      s.resize(hash);
    }
    while (!s.empty() && IsSpace(s.back()))
    {
      s.pop_back();
    }
    return true;
  };
  while (next(line))
  {
    const long long start = number;
    // A "\" at the end of a line continues the statement on the next one.
    while (!line.empty() && line.back() == '\\' && next(more))
    {
      line.back() = ' ';
      line += more;
    }
    const char* p = SkipSpace(line.c_str());
    const char* k = p;
    while (*p && !IsSpace(*p))
    {
      ++p;
    }
    const std::string key(k, p);
    if (key == "v")
    {
      double v[7];
      const int got = ParseUpTo(p, v, 7);
      if (got < 3)
      {
        throw Error("line " + std::to_string(start) + ": expected 3 numbers, found " + std::to_string(got), path);
      }
      obj.Coords[V].insert(obj.Coords[V].end(), v, v + 3);
      // Exactly six numbers: x y z r g b (four: x y z w).
      const bool rgb = got == 6;
      obj.Colors.insert(obj.Colors.end(), { rgb ? v[3] : 0.0, rgb ? v[4] : 0.0, rgb ? v[5] : 0.0 });
      obj.Colored += rgb;
      ++obj.Count[V];
    }
    else if (key == "vt")
    {
      ReadNumbers(p, 1, 2, obj.Coords[T], start, path);
      ++obj.Count[T];
    }
    else if (key == "vn")
    {
      ReadNumbers(p, 3, 3, obj.Coords[N], start, path);
      ++obj.Count[N];
    }
    else if (key == "f" || key == "l" || key == "p")
    {
      ReadCell(key[0], p, obj, start, path);
    }
    else if (key == "mtllib" || key == "usemtl")
    {
      const std::string name = SkipSpace(p);
      if (key == "mtllib")
      {
        obj.Libraries.push_back(name);
      }
      else
      {
        const auto at = std::find(obj.Materials.begin(), obj.Materials.end(), name);
        obj.Material = static_cast<int>(at - obj.Materials.begin());
        if (at == obj.Materials.end())
        {
          obj.Materials.push_back(name);
        }
      }
    }
    if (obj.Count[V] > std::numeric_limits<std::int32_t>::max() || obj.Corners.size() > (std::size_t(1) << 40))
    {
      throw Error("more than 2^31 vertices", path);
    }
  }
  if (in.bad())
  {
    throw Error("read error", path);
  }
  return obj;
}

// The diffuse colour (Kd) of each material the faces use, from the .mtl libraries beside the file
// (SketchUp, Blender and CAD exports colour faces this way); a missing library or colour leaves
// that material without one.
std::vector<std::array<double, 3>> DiffuseColours(const Obj& obj, const std::string& path)
{
  std::vector<std::array<double, 3>> kd(obj.Materials.size(), { -1, -1, -1 });
  const std::size_t slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
  auto beside = [&](const std::string& name) { return !name.empty() && name[0] == '/' ? name : dir + name; };
  std::vector<std::string> files;
  for (const std::string& names : obj.Libraries)
  {
    // One library, or several separated by blanks ("mtllib a.mtl b.mtl").
    std::ifstream whole(beside(names));
    std::istringstream split(names);
    std::string one;
    while (!whole && split >> one)
    {
      files.push_back(one);
    }
    if (whole)
    {
      files.push_back(names);
    }
  }
  for (const std::string& lib : files)
  {
    std::ifstream in(beside(lib));
    std::string line;
    int current = -1;
    for (bool first = true; std::getline(in, line); first = false)
    {
      if (first && line.rfind("\xEF\xBB\xBF", 0) == 0)
      {
        line.erase(0, 3); // a UTF-8 byte-order mark
      }
      const char* p = SkipSpace(line.c_str());
      const char* k = p;
      while (*p && !IsSpace(*p))
      {
        ++p;
      }
      const std::string key(k, p);
      if (key == "newmtl")
      {
        std::string name = SkipSpace(p);
        while (!name.empty() && IsSpace(name.back()))
        {
          name.pop_back();
        }
        const auto at = std::find(obj.Materials.begin(), obj.Materials.end(), name);
        current = at == obj.Materials.end() ? -1 : static_cast<int>(at - obj.Materials.begin());
      }
      else if (key == "Kd" && current >= 0)
      {
        double v[3];
        if (ParseUpTo(p, v, 3) == 3)
        {
          kd[current] = { std::clamp(v[0], 0.0, 1.0), std::clamp(v[1], 0.0, 1.0), std::clamp(v[2], 0.0, 1.0) };
        }
      }
    }
  }
  return kd;
}

vtkSmartPointer<vtkDataArray> Attribute(int field, const char* name)
{
  vtkSmartPointer<vtkDataArray> a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(field == T ? 2 : 3);
  return a;
}
} // namespace

namespace
{
// An attribute is kept only when every face corner has one: a normal for some corners only would
// leave the others' points without one. `sameAsVertex`: every kept index equals the vertex index,
// so no point need be split.
void ChooseAttributes(const Obj& obj, bool keep[3], bool& sameAsVertex)
{
  keep[V] = true;
  keep[T] = obj.Count[T] > 0;
  keep[N] = obj.Count[N] > 0;
  for (const Cell& cell : obj.Cells)
  {
    for (std::size_t i = cell.first; cell.kind == 'f' && i < cell.first + cell.count; ++i)
    {
      keep[T] = keep[T] && obj.Corners[i][T] >= 0;
      keep[N] = keep[N] && obj.Corners[i][N] >= 0;
    }
  }
  sameAsVertex = true;
  for (const Corner& c : obj.Corners)
  {
    sameAsVertex = sameAsVertex && (!keep[T] || c[T] < 0 || c[T] == c[V]) && (!keep[N] || c[N] < 0 || c[N] == c[V]);
  }
}

// The points of the surface with their attributes, and each corner's point.
struct PointSet
{
  vtkNew<vtkPoints> Points;
  vtkSmartPointer<vtkDataArray> Attr[3];
  vtkSmartPointer<vtkUnsignedCharArray> Rgb; ///< vertex colours, when every vertex has one
  double ColorScale = 255.0;                 ///< 0..1 colours are scaled to 8 bits
  std::vector<vtkIdType> Ids;                ///< per corner

  vtkIdType Add(const Obj& obj, const Corner& c)
  {
    const vtkIdType id = Points->InsertNextPoint(&obj.Coords[V][3 * std::size_t(c[V])]);
    if (Rgb)
    {
      unsigned char value[3];
      for (int k = 0; k < 3; ++k)
      {
        value[k] =
          static_cast<unsigned char>(std::clamp(obj.Colors[3 * std::size_t(c[V]) + k] * ColorScale + 0.5, 0.0, 255.0));
      }
      Rgb->InsertNextTypedTuple(value);
    }
    for (int f : { T, N })
    {
      if (Attr[f])
      {
        const int nc = f == T ? 2 : 3;
        double value[3] = { 0, 0, 0 };
        for (int k = 0; c[f] >= 0 && k < nc; ++k)
        {
          value[k] = obj.Coords[f][nc * std::size_t(c[f]) + k];
        }
        Attr[f]->InsertNextTuple(value);
      }
    }
    return id;
  }
};

void BuildPoints(const Obj& obj, PointSet& ps)
{
  bool keep[3], sameAsVertex;
  ChooseAttributes(obj, keep, sameAsVertex);
  ps.Points->SetDataTypeToDouble(); // survey and CAD coordinates need more than a float's 7 digits
  ps.Attr[T] = keep[T] ? Attribute(T, "TCoords") : nullptr;
  ps.Attr[N] = keep[N] ? Attribute(N, "Normals") : nullptr;
  ps.Ids.resize(obj.Corners.size());
  if (obj.Count[V] > 0 && obj.Colored == obj.Count[V])
  {
    ps.Rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
    ps.Rgb->SetName("RGB");
    ps.Rgb->SetNumberOfComponents(3);
    ps.ColorScale = *std::max_element(obj.Colors.begin(), obj.Colors.end()) > 1.0 ? 1.0 : 255.0;
  }
  if (sameAsVertex)
  {
    // Every vertex is a point, in file order, with the attribute of the same index (if any).
    for (std::size_t v = 0; v < obj.Count[V]; ++v)
    {
      const auto i = static_cast<std::int32_t>(v);
      ps.Add(obj, { i, keep[T] && v < obj.Count[T] ? i : -1, keep[N] && v < obj.Count[N] ? i : -1 });
    }
    for (std::size_t i = 0; i < obj.Corners.size(); ++i)
    {
      ps.Ids[i] = obj.Corners[i][V];
    }
    return;
  }
  // One point per distinct (vertex, kept attributes) triple, in order of first use.
  std::unordered_map<Corner, vtkIdType, CornerHash> index;
  index.reserve(obj.Count[V]);
  for (std::size_t i = 0; i < obj.Corners.size(); ++i)
  {
    Corner c = obj.Corners[i];
    c[T] = keep[T] ? c[T] : -1;
    c[N] = keep[N] ? c[N] : -1;
    auto [it, added] = index.try_emplace(c, 0);
    if (added)
    {
      it->second = ps.Add(obj, c);
    }
    ps.Ids[i] = it->second;
  }
}

// Material colours on the cells (in vtkPolyData's order: verts, lines, polys) when every face has
// a material with a diffuse colour, as vertex colours are kept only when every vertex has one.
vtkSmartPointer<vtkUnsignedCharArray> FaceColours(const Obj& obj, vtkIdType faces, const std::string& path)
{
  if (obj.Materials.empty() || faces == 0)
  {
    return nullptr;
  }
  const auto kd = DiffuseColours(obj, path);
  for (const Cell& cell : obj.Cells)
  {
    if (cell.kind == 'f' && !(cell.material >= 0 && kd[cell.material][0] >= 0))
    {
      return nullptr;
    }
  }
  auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  for (char kind : { 'p', 'l', 'f' })
  {
    for (const Cell& cell : obj.Cells)
    {
      if (cell.kind == kind)
      {
        const std::array<double, 3> c =
          cell.material >= 0 && kd[cell.material][0] >= 0 ? kd[cell.material] : std::array<double, 3>{ 0, 0, 0 };
        rgb->InsertNextTuple3(std::round(255 * c[0]), std::round(255 * c[1]), std::round(255 * c[2]));
      }
    }
  }
  return rgb;
}
} // namespace

vtkSmartPointer<vtkPolyData> ReadObj(const std::string& path)
{
  const Obj obj = Parse(path);
  PointSet ps;
  BuildPoints(obj, ps);
  vtkNew<vtkCellArray> cells[3]; // verts, lines, polys
  for (const Cell& cell : obj.Cells)
  {
    vtkCellArray* ca = cells[cell.kind == 'p' ? 0 : cell.kind == 'l' ? 1 : 2];
    ca->InsertNextCell(static_cast<vtkIdType>(cell.count), &ps.Ids[cell.first]);
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(ps.Points);
  pd->SetVerts(cells[0]);
  pd->SetLines(cells[1]);
  pd->SetPolys(cells[2]);
  if (ps.Attr[T])
  {
    pd->GetPointData()->SetTCoords(ps.Attr[T]);
  }
  if (ps.Attr[N])
  {
    pd->GetPointData()->SetNormals(ps.Attr[N]);
  }
  if (ps.Rgb)
  {
    pd->GetPointData()->SetScalars(ps.Rgb);
  }
  if (auto faceRgb = FaceColours(obj, cells[2]->GetNumberOfCells(), path))
  {
    pd->GetCellData()->SetScalars(faceRgb);
  }
  return pd;
}
} // namespace art
