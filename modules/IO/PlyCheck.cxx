#include "PlyCheck.h"
#include "Error.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

namespace art
{
namespace
{
int TypeSize(const std::string& t)
{
  static const std::map<std::string, int> sizes = { { "char", 1 }, { "uchar", 1 }, { "int8", 1 },
    { "uint8", 1 }, { "short", 2 }, { "ushort", 2 }, { "int16", 2 }, { "uint16", 2 },
    { "int", 4 }, { "uint", 4 }, { "int32", 4 }, { "uint32", 4 }, { "float", 4 },
    { "float32", 4 }, { "double", 8 }, { "float64", 8 } };
  const auto it = sizes.find(t);
  return it == sizes.end() ? 0 : it->second;
}

// A binary value's size and how to read it, looked up once per property.
struct Type
{
  int size = 0;
  bool isFloat = false, isSigned = false;
};

struct Property
{
  std::string name, type, countType; ///< countType is empty unless a list
  Type item, count;
};

struct Element
{
  std::string name;
  long long count = 0;
  std::vector<Property> props;
};

bool IsFloat(const std::string& t)
{
  return t == "float" || t == "float32" || t == "double" || t == "float64";
}

// A value of binary type t at p as a double (list counts and vertex indices are whole numbers).
Type TypeOf(const std::string& t)
{
  Type r;
  r.size = TypeSize(t);
  r.isFloat = IsFloat(t);
  r.isSigned = t == "char" || t == "int8" || t == "short" || t == "int16" || t == "int" || t == "int32";
  return r;
}

double Decode(const unsigned char* p, const Type& t, bool bigEndian)
{
  const int n = t.size;
  unsigned char b[8];
  std::memcpy(b, p, n);
  if (bigEndian)
  {
    std::reverse(b, b + n);
  }
  if (t.isFloat)
  {
    if (n == 4)
    {
      float f;
      std::memcpy(&f, b, 4);
      return f;
    }
    double d;
    std::memcpy(&d, b, 8);
    return d;
  }
  unsigned long long u = 0;
  for (int i = n - 1; i >= 0; --i)
  {
    u = (u << 8) | b[i];
  }
  if (t.isSigned && (b[n - 1] & 0x80))
  {
    return static_cast<double>(static_cast<long long>(u) - (1LL << (8 * n)));
  }
  return static_cast<double>(u);
}

// Buffered reads of n bytes from a binary body.
class Bytes
{
public:
  explicit Bytes(std::istream& in)
    : In(in)
  {
  }
  const unsigned char* Get(size_t n)
  {
    if (End - Pos < n)
    {
      std::memmove(Buf.data(), Buf.data() + Pos, End - Pos);
      End -= Pos;
      Pos = 0;
      In.read(reinterpret_cast<char*>(Buf.data()) + End, static_cast<std::streamsize>(Buf.size() - End));
      End += static_cast<size_t>(In.gcount());
      if (End < n)
      {
        return nullptr;
      }
    }
    const unsigned char* p = Buf.data() + Pos;
    Pos += n;
    return p;
  }

private:
  std::istream& In;
  std::vector<unsigned char> Buf = std::vector<unsigned char>(1 << 20);
  size_t Pos = 0, End = 0;
};

// Where a vertex element keeps double x, y, z and floating-point red, green, blue: vtkPLYReader
// stores floats, which lose survey coordinates (a 1 m triangle 2.5e7 m out collapsed to a point),
// and casts float colours to 8 bits (1.0 became 1/255). Channel a (0..5: x y z r g b) of property
// k is Axis[k]; At and Types give its byte offset in a fixed-size row and its type.
struct KeptChannels
{
  int Axis[16];
  std::size_t At[6] = { 0, 0, 0, 0, 0, 0 };
  Type Types[6];
  std::size_t Row = 0; ///< bytes per instance when no property is a list, else size_t(-1)
  bool Xyz = false, Rgb = false;
  bool Keeps(int a) const { return a >= 0 && (a < 3 ? Xyz : Rgb); }
};

KeptChannels FindKeptChannels(const Element& e, bool wantXyz, bool wantRgb)
{
  KeptChannels k;
  std::fill(k.Axis, k.Axis + 16, -1);
  const std::size_t variable = static_cast<std::size_t>(-1);
  int found = 0; // bit a: channel a is there in a type worth keeping
  for (std::size_t i = 0; i < e.props.size(); ++i)
  {
    const Property& p = e.props[i];
    const bool isDouble = p.type == "double" || p.type == "float64";
    int a = -1;
    if (e.name == "vertex" && p.countType.empty() && i < 16)
    {
      a = (wantXyz && isDouble) ? (p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1) : -1;
      if (a < 0 && wantRgb && p.item.isFloat)
      {
        a = p.name == "red" ? 3 : p.name == "green" ? 4 : p.name == "blue" ? 5 : -1;
      }
    }
    if (a >= 0 && k.Row != variable)
    {
      k.Axis[i] = a;
      k.At[a] = k.Row;
      k.Types[a] = p.item;
      found |= 1 << a;
    }
    k.Row = (k.Row == variable || !p.countType.empty()) ? variable : k.Row + p.item.size;
  }
  k.Xyz = (found & 7) == 7;
  k.Rgb = (found & 56) == 56;
  return k;
}

// The kept channels' values, three per instance, into xyz (a < 3) or rgb.
struct Store
{
  std::vector<double>* Xyz;
  std::vector<double>* Rgb;
  void operator()(long long i, int a, double v) const
  {
    (a < 3 ? *Xyz : *Rgb)[3 * static_cast<std::size_t>(i) + static_cast<std::size_t>(a % 3)] = v;
  }
};

// Binary instances of a fixed size: each must be there.
void ReadFixedRows(Bytes& bytes, const Element& e, const KeptChannels& k, bool bigEndian, const Store& store,
  const std::string& path)
{
  for (long long i = 0; i < e.count; ++i)
  {
    const unsigned char* r = k.Row ? bytes.Get(k.Row) : nullptr;
    if (k.Row && !r)
    {
      throw Error("truncated: " + e.name + " " + std::to_string(i) + " of " + std::to_string(e.count) + " is missing",
        path);
    }
    for (int a = 0; a < 6; ++a)
    {
      if (k.Keeps(a))
      {
        store(i, a, Decode(r + k.At[a], k.Types[a], bigEndian));
      }
    }
  }
}

// The values of one instance in turn: binary from `bytes`, ASCII from one line of text.
class ValueCursor
{
public:
  ValueCursor(Bytes& bytes, bool binary, bool bigEndian)
    : Source(bytes)
    , Binary(binary)
    , BigEndian(bigEndian)
  {
  }
  void SetLine(const char* line) { Cursor = line; }
  // The next value; only counts, indices and kept channels are parsed as numbers.
  bool Next(const Type& type, bool parse, double& v)
  {
    if (Binary)
    {
      const unsigned char* p = Source.Get(static_cast<size_t>(type.size));
      if (p && parse)
      {
        v = Decode(p, type, BigEndian);
      }
      return p != nullptr;
    }
    while (*Cursor == ' ' || *Cursor == '\t' || *Cursor == '\r')
    {
      ++Cursor;
    }
    if (!*Cursor)
    {
      return false;
    }
    const char* start = Cursor;
    while (*Cursor && *Cursor != ' ' && *Cursor != '\t' && *Cursor != '\r')
    {
      ++Cursor;
    }
    if (parse)
    {
      char* end = nullptr;
      v = std::strtod(start, &end);
      return end == Cursor;
    }
    return true;
  }

private:
  Bytes& Source;
  bool Binary, BigEndian;
  const char* Cursor = "";
};

// One list property of instance i: its count, then that many items; a face's vertex indices
// must name vertices that exist (VTK 9.1 crashed on one past the vertex count).
void ReadList(ValueCursor& values, const Element& e, const Property& p, long long i, long long vertices,
  const std::string& path)
{
  double v = 0;
  if (!values.Next(p.count, true, v) || !(v >= 0 && v <= 1e6))
  {
    throw Error("truncated or malformed: " + e.name + " " + std::to_string(i) + " has no valid '" + p.name + "' count",
      path);
  }
  const long long n = static_cast<long long>(v);
  const bool indices = e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index");
  for (long long k = 0; k < n; ++k)
  {
    if (!values.Next(p.item, indices, v))
    {
      throw Error("truncated or malformed: " + e.name + " " + std::to_string(i) + " lists " + std::to_string(n) +
          " '" + p.name + "' but fewer are there",
        path);
    }
    if (indices && vertices >= 0 && !(v >= 0 && v < static_cast<double>(vertices)))
    {
      throw Error("face " + std::to_string(i) + " refers to vertex " + std::to_string(static_cast<long long>(v)) +
          " of " + std::to_string(vertices),
        path);
    }
  }
}

// Instances read value by value: ASCII (one instance per line; VTK 9.1 crashed on a short line)
// or binary with lists.
void ReadRows(std::istream& in, ValueCursor& values, const Element& e, const KeptChannels& k, bool binary,
  long long vertices, const Store& store, const std::string& path)
{
  std::string line;
  for (long long i = 0; i < e.count; ++i)
  {
    if (!binary)
    {
      if (!std::getline(in, line))
      {
        throw Error("truncated: " + e.name + " " + std::to_string(i) + " of " + std::to_string(e.count) + " is missing",
          path);
      }
      values.SetLine(line.c_str());
    }
    for (size_t j = 0; j < e.props.size(); ++j)
    {
      const Property& p = e.props[j];
      if (!p.countType.empty())
      {
        ReadList(values, e, p, i, vertices, path);
        continue;
      }
      const int a = j < 16 && k.Keeps(k.Axis[j]) ? k.Axis[j] : -1;
      double v = 0;
      if (!values.Next(p.item, a >= 0, v))
      {
        throw Error("truncated or malformed: " + e.name + " " + std::to_string(i) + " lacks '" + p.name + "'", path);
      }
      if (a >= 0)
      {
        store(i, a, v);
      }
    }
  }
}

// Reads every element of the body as vtkPLYReader will and checks that nothing is missing and
// that faces name vertices that exist.
void CheckBody(std::istream& in, const std::vector<Element>& elements, bool binary, bool bigEndian,
  const std::string& path, std::vector<double>* xyz, std::vector<double>* rgb)
{
  long long vertices = -1;
  for (const Element& e : elements)
  {
    vertices = e.name == "vertex" ? e.count : vertices;
  }
  Bytes bytes(in);
  ValueCursor values(bytes, binary, bigEndian);
  const Store store{ xyz, rgb };
  for (const Element& e : elements)
  {
    const KeptChannels k = FindKeptChannels(e, xyz != nullptr, rgb != nullptr);
    if (k.Xyz)
    {
      xyz->assign(3 * static_cast<size_t>(e.count), 0.0);
    }
    if (k.Rgb)
    {
      rgb->assign(3 * static_cast<size_t>(e.count), 0.0);
    }
    if (binary && k.Row != static_cast<size_t>(-1))
    {
      ReadFixedRows(bytes, e, k, bigEndian, store, path);
    }
    else
    {
      ReadRows(in, values, e, k, binary, vertices, store, path);
    }
  }
}
} // namespace

namespace
{
struct PlyHeader
{
  bool binary = false, bigEndian = false;
  std::vector<Element> layout;
  long long minBody = 0; ///< the fewest body bytes the elements take (each list at least its count)
};

// vtkPLYReader looks up the "vertex" element and its x, y, z without checking they are there (a
// file naming it "veztex" crashed it).
void RequireVertices(const std::vector<Element>& layout, const std::string& path)
{
  for (const Element& e : layout)
  {
    // vtkPLYReader reads a face's corners from vertex_indices (or vertex_index) unchecked.
    if (e.name == "face" && std::none_of(e.props.begin(), e.props.end(), [](const Property& p) {
          return !p.countType.empty() && (p.name == "vertex_indices" || p.name == "vertex_index");
        }))
    {
      throw Error("the face element has no vertex_indices list", path);
    }
  }
  for (const Element& e : layout)
  {
    if (e.name != "vertex")
    {
      continue;
    }
    for (const char* axis : { "x", "y", "z" })
    {
      if (std::none_of(e.props.begin(), e.props.end(), [axis](const Property& p) { return p.name == axis && p.countType.empty(); }))
      {
        throw Error(std::string("the vertex element has no '") + axis + "' property", path);
      }
    }
    return;
  }
  throw Error("has no 'vertex' element", path);
}

// The header's lines after "ply" up to end_header: format, elements and their properties.
PlyHeader ReadPlyHeader(std::istream& in, const std::string& path)
{
  PlyHeader h;
  std::string line;
  bool haveFormat = false, ended = false;
  long long elements = 0, curCount = 0;
  bool& binary = h.binary;
  bool& bigEndian = h.bigEndian;
  std::vector<Element>& layout = h.layout;
  long long& minBody = h.minBody;
  for (int n = 0; n < 10000 && std::getline(in, line); ++n)
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    if (std::any_of(line.begin(), line.end(), [](char c) { return (c >= 0 && c < 0x20 && c != '\t') || c == 0x7F; }))
    {
      throw Error("header line " + std::to_string(n + 2) + " holds control bytes", path); // VTK cut names at a NUL
    }
    std::istringstream ls(line);
    std::string word;
    ls >> word;
    if (word == "format")
    {
      std::string f;
      ls >> f;
      if (f != "ascii" && f != "binary_little_endian" && f != "binary_big_endian")
      {
        throw Error("unknown PLY format '" + f + "'", path);
      }
      binary = f != "ascii";
      bigEndian = f == "binary_big_endian";
      haveFormat = true;
    }
    else if (word == "element")
    {
      std::string name;
      ls >> name >> curCount;
      if (!ls || curCount < 0)
      {
        throw Error("bad element line '" + line + "'", path);
      }
      ++elements;
      layout.push_back({ name, curCount, {} });
    }
    else if (word == "property")
    {
      std::string t;
      ls >> t;
      if (t == "list")
      {
        std::string countType, itemType;
        ls >> countType >> itemType;
        if (!TypeSize(countType) || !TypeSize(itemType))
        {
          throw Error("bad property line '" + line + "'", path);
        }
        minBody += curCount * TypeSize(countType); // each list holds at least its count
        std::string pname;
        ls >> pname;
        if (!layout.empty())
        {
          layout.back().props.push_back({ pname, itemType, countType, TypeOf(itemType), TypeOf(countType) });
        }
      }
      else
      {
        if (!TypeSize(t))
        {
          throw Error("bad property line '" + line + "'", path);
        }
        minBody += curCount * TypeSize(t);
        std::string pname;
        ls >> pname;
        if (!layout.empty())
        {
          layout.back().props.push_back({ pname, t, {}, TypeOf(t), {} });
        }
      }
    }
    else if (word == "end_header")
    {
      ended = true;
      break;
    }
    else if (word != "comment" && word != "obj_info" && !word.empty())
    {
      throw Error("unexpected header line '" + line.substr(0, 40) + "'", path);
    }
  }
  if (!ended || !haveFormat || elements == 0)
  {
    throw Error("incomplete PLY header (no format, element or end_header)", path);
  }
  return h;
}
} // namespace

void CheckPly(const std::string& path, std::vector<double>* xyz, std::vector<double>* rgb)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw Error("cannot open file", path);
  }
  std::string line;
  if (std::getline(in, line) && line.rfind("\xEF\xBB\xBFply", 0) == 0)
  {
    throw Error("starts with a UTF-8 byte-order mark before 'ply', which VTK's PLY reader does not take: "
                "save it without one",
      path);
  }
  if (!in || line.rfind("ply", 0) != 0)
  {
    throw Error("not a PLY file (no 'ply' magic line)", path);
  }
  const PlyHeader h = ReadPlyHeader(in, path);
  RequireVertices(h.layout, path);
  const long long bodyStart = static_cast<long long>(in.tellg());
  std::error_code ec;
  const long long size = static_cast<long long>(std::filesystem::file_size(path, ec));
  if (h.binary && size - bodyStart < h.minBody)
  {
    throw Error("truncated: header needs at least " + std::to_string(h.minBody) +
        " body bytes, file holds " + std::to_string(size - bodyStart),
      path);
  }
  if (xyz)
  {
    xyz->clear();
  }
  if (rgb)
  {
    rgb->clear();
  }
  CheckBody(in, h.layout, h.binary, h.bigEndian, path, xyz, rgb);
}
} // namespace art
