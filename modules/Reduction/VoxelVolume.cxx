#include "VoxelVolume.h"

#include "Error.h"
#include "ValueMagnitude.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace art
{
void VoxelVolume::Validate(const std::string& file)
{
  if (Dims[0] < 1 || Dims[1] < 1 || Dims[2] < 1 || NumberOfVoxels() == 0)
  {
    throw Error("the image is empty", file);
  }
  if (Dims[0] < 2 || Dims[1] < 2 || Dims[2] < 2)
  {
    const int flat = (Dims[0] < 2) + (Dims[1] < 2) + (Dims[2] < 2);
    throw Error(std::string(flat == 1 ? "a 2-D image (" : (flat == 2 ? "a 1-D image (" : "a single voxel (")) +
        std::to_string(Dims[0]) + " x " + std::to_string(Dims[1]) + " x " + std::to_string(Dims[2]) +
        ") cannot be reduced to tetrahedra; it needs at least 2 voxels along each axis",
      file);
  }
  if (Dims[0] > 16384 || Dims[1] > 16384 || Dims[2] > 16384)
  {
    throw Error("more than 16384 voxels along an axis is not supported", file);
  }
  const long long n = NumberOfVoxels();
  if ((DoubleValues ? static_cast<long long>(Double.size()) : static_cast<long long>(Float.size())) != n)
  {
    throw Error("the scalar array does not match the image dimensions", file);
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  bool whole = true;
  for (long long i = 0; i < n; ++i)
  {
    const double v = Value(i);
    if (!std::isfinite(v))
    {
      // Which voxel and how many, as render says it (a masked map's NaN outside the brain).
      long long count = 0;
      for (long long j = i; j < n; ++j)
      {
        count += std::isfinite(Value(j)) ? 0 : 1;
      }
      const double ijk[3] = { double(i % Dims[0]), double((i / Dims[0]) % Dims[1]),
        double(i / (static_cast<long long>(Dims[0]) * Dims[1])) };
      double w[3];
      IndexToWorld(ijk, w);
      char at[120];
      std::snprintf(at, sizeof at, "%.6g, %.6g, %.6g", w[0], w[1], w[2]);
      throw Error("the scalars hold NaN or infinite values: " + std::to_string(count) + " voxel" + (count > 1 ? "s" : "") +
          ", the first at x, y, z = " + at + " (replace them first, e.g. with numpy.nan_to_num)",
        file);
    }
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    whole = whole && v == std::floor(v);
  }
  RequireComputableRange(lo, hi, file); // squares of 1e300 were inf: 'RMS inf' and a coarse mesh
  Range[0] = lo;
  Range[1] = hi;
  WithSamples([&](const auto* v) { Statistics = Summarize(n, [v](long long i) { return double(v[i]); }, whole); });
}
} // namespace art
