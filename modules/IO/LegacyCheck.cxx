#include "LegacyCheck.h"
#include "Error.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace art
{
namespace
{
// Bytes per value of each legacy type (0: not sized here, e.g. strings), as vtkDataReader takes them.
const std::map<std::string, int>& TypeSizes()
{
  static const std::map<std::string, int> t = { { "bit", 0 }, { "unsigned_char", 1 }, { "char", 1 },
    { "signed_char", 1 }, { "unsigned_short", 2 }, { "short", 2 }, { "unsigned_int", 4 }, { "int", 4 },
    { "unsigned_long", 8 }, { "long", 8 }, { "float", 4 }, { "double", 8 }, { "vtkidtype", 4 },
    { "vtktypeint64", 8 }, { "vtktypeuint64", 8 }, { "vtktypeint32", 4 }, { "vtktypeuint32", 4 },
    { "vtktypeint8", 1 }, { "vtktypeuint8", 1 }, { "vtktypeint16", 2 }, { "vtktypeuint16", 2 },
    { "vtktypefloat32", 4 }, { "vtktypefloat64", 8 }, { "string", 0 }, { "utf8_string", 0 }, { "variant", 0 } };
  return t;
}

std::string Lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool Count(const std::string& w, long long& n)
{
  char* end = nullptr;
  n = std::strtoll(w.c_str(), &end, 10);
  return !w.empty() && *end == '\0' && n >= 0 && n < (1LL << 40);
}

void RequireType(const std::string& type, const std::string& line, int number, const std::string& path)
{
  if (!TypeSizes().count(Lower(type)))
  {
    throw Error("line " + std::to_string(number) + ": unknown data type '" + type.substr(0, 30) + "' in '" +
        line.substr(0, 60) + "'",
      path);
  }
}

// The position of the data type among a keyword line's words ("SCALARS name type", "POINTS n
// type"), and of the counts to check; -1 where the line has none.
struct KeywordLayout
{
  int Type, Counts[2];
};
const std::map<std::string, KeywordLayout>& Keywords()
{
  static const std::map<std::string, KeywordLayout> k = { { "POINTS", { 2, { 1, -1 } } },
    { "X_COORDINATES", { 2, { 1, -1 } } }, { "Y_COORDINATES", { 2, { 1, -1 } } },
    { "Z_COORDINATES", { 2, { 1, -1 } } }, { "SCALARS", { 2, { -1, -1 } } }, { "VECTORS", { 2, { -1, -1 } } },
    { "NORMALS", { 2, { -1, -1 } } }, { "TENSORS", { 2, { -1, -1 } } }, { "TEXTURE_COORDINATES", { 3, { 2, -1 } } },
    { "CELLS", { -1, { 1, 2 } } }, { "POLYGONS", { -1, { 1, 2 } } }, { "LINES", { -1, { 1, 2 } } },
    { "VERTICES", { -1, { 1, 2 } } }, { "TRIANGLE_STRIPS", { -1, { 1, 2 } } }, { "CELL_TYPES", { -1, { 1, -1 } } },
    { "POINT_DATA", { -1, { 1, -1 } } }, { "CELL_DATA", { -1, { 1, -1 } } }, { "OFFSETS", { 1, { -1, -1 } } },
    { "CONNECTIVITY", { 1, { -1, -1 } } } };
  return k;
}
} // namespace

void CheckLegacyVtk(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  long long fieldArrays = 0; // array header lines still to come in a FIELD block
  bool firstArray = false;   // the next line is a FIELD block's first array header
  std::string dataset;       // DATASET's type
  bool dimensions = false;   // a DIMENSIONS line of three sizes >= 1
  // Structured data sets need DIMENSIONS before their data (a file without it crashed
  // vtkStructuredPointsReader).
  auto requireDimensions = [&](int number) {
    const bool structured = dataset == "STRUCTURED_POINTS" || dataset == "STRUCTURED_GRID" || dataset == "RECTILINEAR_GRID";
    if (structured && !dimensions)
    {
      throw Error(std::string(number < 1000000 ? "line " + std::to_string(number) + ": " : "") + "a " + dataset +
          " without a DIMENSIONS line before its data",
        path);
    }
  };
  for (int number = 1; number < 1000000 && std::getline(in, line); ++number)
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    std::istringstream s(line);
    std::vector<std::string> w;
    for (std::string word; w.size() < 6 && s >> word;)
    {
      w.push_back(word);
    }
    if (w.empty() || number <= 2)
    {
      continue; // the version line and the title
    }
    const std::string key = w[0];
    if (key == "DATASET" && w.size() >= 2)
    {
      if (!dataset.empty())
      {
        throw Error("line " + std::to_string(number) + ": a second DATASET (two files joined into one?)", path);
      }
      dataset = w[1];
      continue;
    }
    if (key == "DIMENSIONS")
    {
      long long n[3];
      if (w.size() < 4 || !Count(w[1], n[0]) || !Count(w[2], n[1]) || !Count(w[3], n[2]) || !n[0] || !n[1] || !n[2])
      {
        throw Error("line " + std::to_string(number) + ": DIMENSIONS needs three sizes of at least 1", path);
      }
      dimensions = true;
      continue;
    }
    const auto k = Keywords().find(key);
    if (k != Keywords().end())
    {
      if (key == "POINTS" || key == "POINT_DATA" || key == "CELL_DATA" || key == "X_COORDINATES")
      {
        requireDimensions(number);
      }
      if (k->second.Type >= 0)
      {
        if (static_cast<int>(w.size()) <= k->second.Type)
        {
          throw Error("line " + std::to_string(number) + ": '" + line.substr(0, 60) + "' lacks its data type", path);
        }
        RequireType(w[k->second.Type], line, number, path);
      }
      for (int c : k->second.Counts)
      {
        long long n;
        if (c >= 0 && (static_cast<int>(w.size()) <= c || !Count(w[c], n)))
        {
          throw Error("line " + std::to_string(number) + ": '" + line.substr(0, 60) + "' has no valid count", path);
        }
      }
      fieldArrays = 0;
      continue;
    }
    if (key == "FIELD")
    {
      if (w.size() < 3 || !Count(w[2], fieldArrays))
      {
        throw Error("line " + std::to_string(number) + ": '" + line.substr(0, 60) + "' has no valid array count", path);
      }
      firstArray = fieldArrays > 0;
      continue;
    }
    if (firstArray)
    {
      // The line after FIELD is its first array's header, whatever it looks like.
      long long a, b;
      if (w.size() < 4 || !Count(w[1], a) || !Count(w[2], b))
      {
        throw Error("line " + std::to_string(number) + ": '" + line.substr(0, 60) +
            "' is not a FIELD array header (name components tuples type)",
          path);
      }
      RequireType(w[3], line, number, path);
      --fieldArrays;
      firstArray = false;
      continue;
    }
    // A FIELD array's header: "name components tuples type".
    long long a, b;
    // VTK takes the first four words, whatever follows.
    const bool numeric = w.size() >= 4 && w[3].find_first_not_of("0123456789+-.eE") == std::string::npos;
    if (fieldArrays > 0 && w.size() >= 4 && !numeric && Count(w[1], a) && Count(w[2], b))
    {
      RequireType(w[3], line, number, path);
      --fieldArrays;
    }
  }
  requireDimensions(1000000);
}
} // namespace art
