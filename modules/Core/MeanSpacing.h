// MeanSpacing: one length for a grid's sample spacing, the geometric mean over its non-flat axes
// (a 2-D slab is measured in its plane). A preset's opacity unit distance follows it.
#ifndef art_MeanSpacing_h
#define art_MeanSpacing_h

#include <cmath>

namespace art
{
/// (product of size[k] over the axes where it is > 0 / samples)^(1 / those axes): the mean
/// spacing of `samples` points spread over a box of extents `size`; an image's voxel spacing
/// with size = |spacing| over its axes of more than one voxel and samples = 1. 1 when undefined.
inline double MeanSpacing(const double size[3], double samples)
{
  double volume = 1.0;
  int axes = 0;
  for (int k = 0; k < 3; ++k)
  {
    if (size[k] > 0.0)
    {
      volume *= size[k];
      ++axes;
    }
  }
  const double h = axes > 0 && samples > 0 ? std::pow(volume / samples, 1.0 / axes) : 1.0;
  return h > 0.0 && std::isfinite(h) ? h : 1.0;
}

/// The geometric mean voxel spacing of an image of dims samples (axes of one voxel left out).
inline double MeanVoxelSpacing(const int dims[3], const double spacing[3])
{
  const double size[3] = { dims[0] > 1 ? std::fabs(spacing[0]) : 0.0, dims[1] > 1 ? std::fabs(spacing[1]) : 0.0,
    dims[2] > 1 ? std::fabs(spacing[2]) : 0.0 };
  return MeanSpacing(size, 1.0);
}
} // namespace art

#endif
