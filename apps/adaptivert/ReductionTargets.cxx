#include "ReductionTargets.h"
#include "Options.h"

#include <cmath>
#include <cstdlib>

namespace cli
{
long long ParseBudget(const std::string& s, long long voxels, const std::string& what)
{
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  const bool pct = end && *end == '%' && end[1] == 0;
  if (s.empty() || !end || end == s.c_str() || (*end && !pct) || !(v > 0) || !std::isfinite(v))
  {
    throw UsageError(what + " wants a positive number or a percentage, got '" + s + "'");
  }
  const double n = pct ? v / 100.0 * voxels : v;
  if (!(n >= 0.5 && n < 1e15))
  {
    throw UsageError(what + " '" + s + "' is " + (n < 0.5 ? "less than one tet" : "beyond any mesh") +
      " (a count from 6 to 1e15, or a percentage of the voxel count)");
  }
  return std::llround(n);
}

double ParseMaxError(const std::string& s, bool& relative)
{
  relative = !s.empty() && s.back() == '%';
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || end == s.c_str() || (end && *end && !(relative && end[1] == 0 && *end == '%')) || !(v >= 0) ||
    !std::isfinite(v))
  {
    throw UsageError("--max-error wants a number or a percentage, got '" + s + "'");
  }
  return relative ? v / 100.0 : v;
}

bool ParseEdgeRefinement(const std::string& s, const std::string& what)
{
  if (s != "bisection" && s != "edge")
  {
    throw UsageError(what + " is bisection or edge, got '" + s + "'");
  }
  return s == "edge";
}
} // namespace cli
