// ValueMagnitude: values the renderers and the reducer can compute with. Least-squares fits and
// errors square the values (past 1e150 the squares overflow to inf, below 1e-150 they vanish), and
// transfer functions scale by the range's inverse (a denormal range gives inf, and a crash); and
// no voxel may be NaN or infinite.
#ifndef art_ValueMagnitude_h
#define art_ValueMagnitude_h

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace art
{
/// Throws art::Error naming `file` when the scalar range [lo, hi] (finite) reaches past 1e150 in
/// magnitude, or is not all zero and stays below 1e-150, with the way out (rescale the values).
inline void RequireComputableRange(double lo, double hi, const std::string& file)
{
  const double top = std::max(std::fabs(lo), std::fabs(hi));
  if (!(top > 1e150) && !(top > 0.0 && top < 1e-150))
  {
    return;
  }
  char msg[320];
  std::snprintf(msg, sizeof msg,
    "the scalars' range %.6g .. %.6g %s: rendering and reducing compute with squares of the values, "
    "which %s; rescale them first (e.g. vtkImageShiftScale, ParaView's Calculator, or numpy)",
    lo, hi, top > 1e150 ? "reaches beyond 1e150 in magnitude" : "lies below 1e-150 in magnitude",
    top > 1e150 ? "overflow to infinity" : "vanish to 0");
  throw Error(msg, file);
}

/// Throws art::Error naming `file` when any of the dims[0] x dims[1] x dims[2] voxel values (x
/// fastest) is NaN or infinite: how many, and the first one's index in the image's extent, whose
/// first voxel is `first` (i, j, k), with what to do.
inline void RequireFiniteVoxels(
  const std::vector<double>& v, const int dims[3], const int first[3], const std::string& file)
{
  const auto notFinite = [](double x) { return !std::isfinite(x); };
  const auto bad = std::find_if(v.begin(), v.end(), notFinite);
  if (bad == v.end())
  {
    return;
  }
  const long long id = bad - v.begin(), count = std::count_if(bad, v.end(), notFinite);
  const long long i = id % dims[0], j = (id / dims[0]) % dims[1], k = id / (static_cast<long long>(dims[0]) * dims[1]);
  throw Error(std::to_string(count) + " voxel" + (count > 1 ? "s hold" : " holds") +
      " NaN or infinite values (the first at i, j, k = " + std::to_string(first[0] + i) + ", " +
      std::to_string(first[1] + j) + ", " + std::to_string(first[2] + k) +
      "); rendering needs finite voxels: replace them first, e.g. with numpy.nan_to_num",
    file);
}
} // namespace art

#endif
