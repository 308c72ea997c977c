#include "NrrdDirection.h"
#include "Error.h"

#include <cmath>
#include <fstream>
#include <vector>

namespace art
{
bool NrrdDirection(const std::string& path, double direction[9])
{
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::string value;
  // The header is "key: value" lines (and "#" comments) up to the first empty line.
  for (int n = 0; n < 500 && std::getline(in, line); ++n)
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    if (line.empty())
    {
      break;
    }
    const std::string key = "space directions:";
    if (line.compare(0, key.size(), key) == 0)
    {
      value = line.substr(key.size());
      break;
    }
  }
  // Vectors "(x,y,z)" for the spatial axes, "none" for a component axis.
  std::vector<std::vector<double>> axes;
  for (size_t p = value.find('('); p != std::string::npos; p = value.find('(', p + 1))
  {
    const size_t e = value.find(')', p);
    if (e == std::string::npos)
    {
      return false;
    }
    std::vector<double> v;
    std::string item;
    const std::string inside = value.substr(p + 1, e - p - 1) + ",";
    for (char c : inside)
    {
      if (c == ',')
      {
        char* end = nullptr;
        const double x = std::strtod(item.c_str(), &end);
        if (end == item.c_str())
        {
          return false;
        }
        v.push_back(x);
        item.clear();
      }
      else
      {
        item += c;
      }
    }
    axes.push_back(v);
  }
  if (axes.size() != 3)
  {
    return false;
  }
  bool identity = true;
  for (int c = 0; c < 3; ++c)
  {
    if (axes[c].size() != 3)
    {
      return false;
    }
    const double len = std::sqrt(axes[c][0] * axes[c][0] + axes[c][1] * axes[c][1] + axes[c][2] * axes[c][2]);
    if (!(len > 0) || !std::isfinite(len))
    {
      throw Error("a space direction has zero or non-finite length", path);
    }
    for (int r = 0; r < 3; ++r)
    {
      direction[3 * r + c] = axes[c][r] / len;
      identity = identity && std::abs(direction[3 * r + c] - (r == c ? 1.0 : 0.0)) < 1e-12;
    }
  }
  return !identity;
}
} // namespace art
