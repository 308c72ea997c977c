#include "ObjCheck.h"
#include "Error.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace art
{
namespace
{
// A face corner's index as OBJ counts it: 1-based, or negative counting back from the last one
// defined so far. Returns false when it names nothing.
bool InRange(long long index, long long defined)
{
  return (index >= 1 && index <= defined) || (index < 0 && -index <= defined);
}
} // namespace

void CheckObj(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw Error("cannot open file", path);
  }
  long long count[3] = { 0, 0, 0 }; // v, vt, vn defined so far
  const char* what[3] = { "vertex", "texture coordinate", "normal" };
  std::string line;
  for (long long n = 1; std::getline(in, line); ++n)
  {
    std::istringstream s(line);
    std::string key;
    s >> key;
    if (key == "v")
    {
      ++count[0];
    }
    else if (key == "vt")
    {
      ++count[1];
    }
    else if (key == "vn")
    {
      ++count[2];
    }
    else if (key == "f" || key == "l" || key == "p")
    {
      std::string corner;
      while (s >> corner)
      {
        // v, v/vt, v//vn or v/vt/vn; an empty field is absent.
        size_t a = 0;
        for (int field = 0; field < 3 && a <= corner.size(); ++field)
        {
          const size_t b = std::min(corner.find('/', a), corner.size());
          if (b > a)
          {
            const std::string item = corner.substr(a, b - a);
            char* end = nullptr;
            const long long index = std::strtoll(item.c_str(), &end, 10);
            if (*end != '\0' || !InRange(index, count[field]))
            {
              throw Error("line " + std::to_string(n) + ": a face refers to " + what[field] + " " + item +
                  " of " + std::to_string(count[field]) + " defined",
                path);
            }
          }
          a = b + 1;
        }
      }
    }
  }
}
} // namespace art
