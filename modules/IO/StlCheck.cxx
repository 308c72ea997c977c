#include "StlCheck.h"
#include "Error.h"

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>

namespace art
{
void CheckStl(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw Error("cannot open file", path);
  }
  std::error_code ec;
  const auto size = static_cast<unsigned long long>(std::filesystem::file_size(path, ec));
  unsigned char head[256] = {};
  in.read(reinterpret_cast<char*>(head), sizeof head);
  const auto got = static_cast<size_t>(in.gcount());

  // Text as VTK (vtksys::DetectFileType) sees it: few bytes outside printable ASCII and whitespace.
  size_t odd = 0;
  for (size_t i = 0; i < got; ++i)
  {
    odd += !(std::isprint(head[i]) || std::isspace(head[i]));
  }
  if (odd * 20 <= got) // at most 5%
  {
    if (got >= 3 && head[0] == 0xEF && head[1] == 0xBB && head[2] == 0xBF)
    {
      throw Error("starts with a UTF-8 byte-order mark, which VTK's STL reader does not take: save it without one",
        path);
    }
    // Text that is no ASCII STL sent vtkSTLReader looking for its keywords without end.
    std::size_t i = 0;
    while (i < got && std::isspace(head[i]))
    {
      ++i;
    }
    if (got - i < 5 || std::string(reinterpret_cast<const char*>(head) + i, 5) != "solid")
    {
      throw Error("is text but not an ASCII STL (it does not start with 'solid')", path);
    }
    return;
  }
  if (got < 84)
  {
    throw Error("truncated: a binary STL needs an 84-byte header, file holds " + std::to_string(size) + " bytes", path);
  }
  // Little-endian triangle count after the 80-byte header; 50 bytes per triangle.
  const std::uint32_t count = std::uint32_t(head[80]) | std::uint32_t(head[81]) << 8 |
    std::uint32_t(head[82]) << 16 | std::uint32_t(head[83]) << 24;
  const unsigned long long need = 84ULL + 50ULL * count;
  if (size < need)
  {
    throw Error("truncated or not an STL: the header counts " + std::to_string(count) + " triangles (" +
        std::to_string(need) + " bytes), file holds " + std::to_string(size) + " bytes",
      path);
  }
}
} // namespace art
