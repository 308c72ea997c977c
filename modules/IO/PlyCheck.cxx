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

// Reads every element of the body as vtkPLYReader will (ASCII: one instance per line) and checks
// that nothing is missing and that faces name vertices that exist: VTK 9.1 crashes on a short
// ASCII line and on a face index past the vertex count.
void CheckBody(std::istream& in, const std::vector<Element>& elements, bool binary, bool bigEndian,
  const std::string& path, std::vector<double>* xyz, std::vector<double>* rgb)
{
  long long vertices = -1;
  for (const Element& e : elements)
  {
    if (e.name == "vertex")
    {
      vertices = e.count;
    }
  }
  Bytes bytes(in);
  std::string line;
  for (const Element& e : elements)
  {
    const bool isFace = e.name == "face";
    size_t row = 0; // bytes per instance when no property is a list
    // Double x, y, z of the vertices are kept: vtkPLYReader stores floats, which lose survey
    // coordinates (a 1 m triangle 2.5e7 m out collapsed to a point). Floating-point red, green,
    // blue (channels 3..5) are kept too: vtkPLYReader casts them to 8 bits, so 1.0 became 1/255.
    int axis[16];
    std::fill(axis, axis + 16, -1);
    size_t at[6] = { 0, 0, 0, 0, 0, 0 };
    Type type[6];
    int found = 0; // bit a: channel a is there in a type worth keeping
    for (size_t k = 0; k < e.props.size(); ++k)
    {
      const Property& p = e.props[k];
      const bool isDouble = p.type == "double" || p.type == "float64";
      int a = -1;
      if (e.name == "vertex" && p.countType.empty() && k < 16)
      {
        a = (xyz && isDouble) ? (p.name == "x" ? 0 : p.name == "y" ? 1 : p.name == "z" ? 2 : -1) : -1;
        if (a < 0 && rgb && p.item.isFloat)
        {
          a = p.name == "red" ? 3 : p.name == "green" ? 4 : p.name == "blue" ? 5 : -1;
        }
      }
      if (a >= 0 && row != static_cast<size_t>(-1))
      {
        axis[k] = a;
        at[a] = row;
        type[a] = p.item;
        found |= 1 << a;
      }
      row = (row == static_cast<size_t>(-1) || !p.countType.empty()) ? static_cast<size_t>(-1) : row + p.item.size;
    }
    const bool keep = (found & 7) == 7, keepRgb = (found & 56) == 56;
    if (keep)
    {
      xyz->assign(3 * static_cast<size_t>(e.count), 0.0);
    }
    if (keepRgb)
    {
      rgb->assign(3 * static_cast<size_t>(e.count), 0.0);
    }
    auto store = [&](long long i, int a, double v) {
      (a < 3 ? *xyz : *rgb)[3 * static_cast<size_t>(i) + static_cast<size_t>(a % 3)] = v;
    };
    if (binary && row != static_cast<size_t>(-1))
    {
      for (long long i = 0; i < e.count; ++i)
      {
        const unsigned char* r = row ? bytes.Get(row) : nullptr;
        if (row && !r)
        {
          throw Error("truncated: " + e.name + " " + std::to_string(i) + " of " + std::to_string(e.count) +
              " is missing",
            path);
        }
        for (int a = 0; a < 6; ++a)
        {
          if (a < 3 ? keep : keepRgb)
          {
            store(i, a, Decode(r + at[a], type[a], bigEndian));
          }
        }
      }
      continue;
    }
    for (long long i = 0; i < e.count; ++i)
    {
      const char* cursor = nullptr;
      if (!binary)
      {
        if (!std::getline(in, line))
        {
          throw Error("truncated: " + e.name + " " + std::to_string(i) + " of " + std::to_string(e.count) +
              " is missing",
            path);
        }
        cursor = line.c_str();
      }
      // The next value; only counts and indices are parsed as numbers.
      auto next = [&](const Type& type, bool parse, double& v) {
        if (binary)
        {
          const unsigned char* p = bytes.Get(static_cast<size_t>(type.size));
          if (p && parse)
          {
            v = Decode(p, type, bigEndian);
          }
          return p != nullptr;
        }
        while (*cursor == ' ' || *cursor == '\t' || *cursor == '\r')
        {
          ++cursor;
        }
        if (!*cursor)
        {
          return false;
        }
        const char* start = cursor;
        while (*cursor && *cursor != ' ' && *cursor != '\t' && *cursor != '\r')
        {
          ++cursor;
        }
        if (parse)
        {
          char* end = nullptr;
          v = std::strtod(start, &end);
          return end == cursor;
        }
        return true;
      };
      for (size_t k = 0; k < e.props.size(); ++k)
      {
        const Property& p = e.props[k];
        double v = 0;
        if (p.countType.empty())
        {
          const int a = k < 16 && axis[k] >= 0 && (axis[k] < 3 ? keep : keepRgb) ? axis[k] : -1;
          if (!next(p.item, a >= 0, v))
          {
            throw Error("truncated or malformed: " + e.name + " " + std::to_string(i) + " lacks '" + p.name + "'", path);
          }
          if (a >= 0)
          {
            store(i, a, v);
          }
          continue;
        }
        if (!next(p.count, true, v) || !(v >= 0 && v <= 1e6))
        {
          throw Error("truncated or malformed: " + e.name + " " + std::to_string(i) + " has no valid '" + p.name +
              "' count",
            path);
        }
        const long long n = static_cast<long long>(v);
        const bool indices = isFace && (p.name == "vertex_indices" || p.name == "vertex_index");
        for (long long k = 0; k < n; ++k)
        {
          if (!next(p.item, indices, v))
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
    }
  }
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
  bool binary = false, bigEndian = false, haveFormat = false, ended = false;
  std::vector<Element> layout;
  long long minBody = 0, elements = 0, curCount = 0;
  for (int n = 0; n < 10000 && std::getline(in, line); ++n)
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
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
  const long long bodyStart = static_cast<long long>(in.tellg());
  std::error_code ec;
  const long long size = static_cast<long long>(std::filesystem::file_size(path, ec));
  if (binary && size - bodyStart < minBody)
  {
    throw Error("truncated: header needs at least " + std::to_string(minBody) +
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
  CheckBody(in, layout, binary, bigEndian, path, xyz, rgb);
}
} // namespace art
