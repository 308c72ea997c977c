#include "rendering/ReductionTargets.h"

#ifdef ART_HAVE_Reduction
#include "FullResolutionMesh.h"
#endif
#include "cli/Options.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace cli
{
long long ParseBudget(const std::string& s, long long voxels, const std::string& what)
{
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  const bool pct = end && *end == '%' && end[1] == 0;
  if (!IsDecimalNumber(pct ? s.substr(0, s.size() - 1) : s) || !end || end == s.c_str() || (*end && !pct) || !(v > 0) || !std::isfinite(v))
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
  if (!IsDecimalNumber(relative ? s.substr(0, s.size() - 1) : s) || end == s.c_str() || (end && *end && !(relative && end[1] == 0 && *end == '%')) || !(v >= 0) ||
    !std::isfinite(v))
  {
    throw UsageError("--max-error wants a number or a percentage, got '" + s + "'");
  }
  return relative ? v / 100.0 : v;
}

} // namespace cli

#ifdef ART_HAVE_Reduction
#include <algorithm>

namespace cli
{
art::ReducerOptions::Refinement ParseRefinement(const std::string& s, const std::string& what)
{
  using R = art::ReducerOptions::Refinement;
  if (s == "bisection")
  {
    return R::Bisection;
  }
  if (s == "edge")
  {
    return R::EdgeSplit;
  }
  if (s == "anisotropic")
  {
    return R::Anisotropic;
  }
  throw UsageError(what + " is bisection, edge or anisotropic, got '" + s + "'");
}

std::string UnreachedReason(const art::ReducedMesh& m, const art::VoxelVolume& v, bool errorBoundAlone)
{
  if (m.TargetReached)
  {
    return "";
  }
  if (m.TargetTets > 0 && m.Refinement == "anisotropic")
  {
    std::ostringstream s;
    s << "tet budget missed by " << std::lround(100.0 * std::fabs(double(m.NumberOfTets()) / m.TargetTets - 1.0))
      << "%: the remeshings ran out before MMG's count came within 5%";
    return s.str();
  }
  if (m.TargetTets > 0)
  {
    // A constant or linear volume is matched to round-off long before the voxels' resolution.
    const double range = v.Range[1] - v.Range[0];
    const double magnitude = std::max({ std::fabs(v.Range[0]), std::fabs(v.Range[1]), range, 1e-300 });
    return m.Max <= 1e-9 * magnitude ? "tet budget not reached: the fit is exact, no tet has an error left to refine"
                                     : "tet budget not reached: no finer tets than the voxels allow";
  }
  // An error bound alone refines up to one tet per voxel (TetReducer's cap), not to the finest
  // tets the voxels allow (5 per voxel cell).
  const long long finest = art::FullResolutionTetCount(v);
  return errorBoundAlone && m.NumberOfTets() >= v.NumberOfVoxels() && m.NumberOfTets() < finest
    ? "error bound not reached by one tet per voxel, where an error bound alone stops; --tets N lets it go on"
    : "error bound not reached: no finer tets than the voxels allow";
}

std::string CapToFullResolution(long long& tets, const art::VoxelVolume& v, const std::string& what)
{
  const long long finest = art::FullResolutionTetCount(v);
  if (tets < finest)
  {
    return "";
  }
  const std::string note = what + " " + std::to_string(tets) + " is at least the " + std::to_string(finest) +
    " tets of the full-resolution mesh (5 per voxel cell), the finest the voxels allow: that mesh is made, "
    "exact, without reducing";
  tets = finest;
  return note;
}
} // namespace cli
#endif
