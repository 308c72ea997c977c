#include "PlyCheck.h"
#include "Error.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

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
} // namespace

void CheckPly(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw Error("cannot open file", path);
  }
  std::string line;
  if (!std::getline(in, line) || line.rfind("ply", 0) != 0)
  {
    throw Error("not a PLY file (no 'ply' magic line)", path);
  }
  bool binary = false, haveFormat = false, ended = false;
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
      }
      else
      {
        if (!TypeSize(t))
        {
          throw Error("bad property line '" + line + "'", path);
        }
        minBody += curCount * TypeSize(t);
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
}
} // namespace art
