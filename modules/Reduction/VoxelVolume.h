// VoxelVolume: the scalar samples the reducer fits, kept as float (or double for double input)
// in VTK's x-fastest order, with the geometry that maps voxel indices to world coordinates.
#ifndef art_VoxelVolume_h
#define art_VoxelVolume_h

#include "ScalarStatistics.h"

#include <string>
#include <vector>

namespace art
{
struct VoxelVolume
{
  int Dims[3] = { 0, 0, 0 };
  double Origin[3] = { 0, 0, 0 };
  double Spacing[3] = { 1, 1, 1 };
  double Direction[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  std::vector<float> Float;   ///< the samples, unless DoubleValues
  std::vector<double> Double; ///< the samples of double (or 64-bit integer) input
  bool DoubleValues = false;
  std::string Name = "scalars";
  std::string File; ///< where the samples came from, for errors (may be empty)
  double Range[2] = { 0, 0 };
  /// Background, robust window and labels of the samples (Validate fills it), recorded in a
  /// reduced mesh so that its default transfer function is the volume's.
  ScalarStatistics Statistics;

  long long NumberOfVoxels() const { return static_cast<long long>(Dims[0]) * Dims[1] * Dims[2]; }
  double Value(long long i) const { return DoubleValues ? Double[i] : Float[i]; }
  /// Calls f with a pointer to the samples in their own type (float or double): voxel passes
  /// index it directly, without Value's branch per voxel.
  template <class F>
  void WithSamples(F&& f) const
  {
    if (DoubleValues)
    {
      f(Double.data());
    }
    else
    {
      f(Float.data());
    }
  }
  /// World position of continuous voxel index coordinates (i, j, k).
  void IndexToWorld(const double ijk[3], double w[3]) const
  {
    const double s[3] = { ijk[0] * Spacing[0], ijk[1] * Spacing[1], ijk[2] * Spacing[2] };
    for (int r = 0; r < 3; ++r)
    {
      w[r] = Origin[r] + Direction[3 * r] * s[0] + Direction[3 * r + 1] * s[1] + Direction[3 * r + 2] * s[2];
    }
  }
  /// Continuous voxel index coordinates of world position w (IndexToWorld's inverse).
  void WorldToIndex(const double w[3], double ijk[3]) const
  {
    const double* d = Direction;
    const double m[9] = { d[4] * d[8] - d[5] * d[7], d[2] * d[7] - d[1] * d[8], d[1] * d[5] - d[2] * d[4],
      d[5] * d[6] - d[3] * d[8], d[0] * d[8] - d[2] * d[6], d[2] * d[3] - d[0] * d[5], d[3] * d[7] - d[4] * d[6],
      d[1] * d[6] - d[0] * d[7], d[0] * d[4] - d[1] * d[3] };
    const double det = d[0] * m[0] + d[1] * m[3] + d[2] * m[6];
    const double r[3] = { w[0] - Origin[0], w[1] - Origin[1], w[2] - Origin[2] };
    for (int a = 0; a < 3; ++a)
    {
      ijk[a] = (m[3 * a] * r[0] + m[3 * a + 1] * r[1] + m[3 * a + 2] * r[2]) / det / Spacing[a];
    }
  }
  /// Fills Range and Statistics from the samples; throws art::Error on an empty volume or a 2-D image.
  void Validate(const std::string& file = {});
};
} // namespace art

#endif
