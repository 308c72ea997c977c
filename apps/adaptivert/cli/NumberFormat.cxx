#include "cli/NumberFormat.h"

namespace cli
{
std::string Grouped(long long n)
{
  std::string s = std::to_string(n < 0 ? -n : n), o;
  for (size_t i = 0; i < s.size(); ++i)
  {
    o += s[i];
    if ((s.size() - 1 - i) % 3 == 0 && i + 1 < s.size())
    {
      o += ',';
    }
  }
  return (n < 0 ? "-" : "") + o;
}
} // namespace cli
