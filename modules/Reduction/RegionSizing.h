// RegionSizing: the mesh size field a region reduction asks its mesher for, on a coarse grid of
// nodes over the volume. Adapted to a fit's error: a tet of size h whose voxels the linear fit
// misses by e (RMS) sees a second derivative of about H = e / h^2; the size that minimises the L2
// error for a number of tets N ~ k * integral(h^-3) is h = C H^(-2/7) (the isotropic case of
// Loseille & Alauzet's continuous mesh, L^2 norm). C is set by the budget, k is calibrated on
// each mesh made, and the field is graded (|grad h| <= Gradation) so that tets change size
// smoothly.
#ifndef art_RegionSizing_h
#define art_RegionSizing_h

#include "AdaptiveRTReductionModule.h"
#include "ImageDomain.h"
#include "VoxelVolume.h"

#include <array>
#include <cstdint>
#include <vector>

namespace art
{
class ADAPTIVERTREDUCTION_EXPORT RegionSizing
{
public:
  /// Nodes every `voxelsPerNode` voxels (along the smallest spacing) over the volume; `inside`
  /// (one per voxel) is the region whose volume the tet count is taken over. Sizes are in the
  /// scaled index space (index times |spacing|), between `hmin` and `hmax`.
  RegionSizing(const VoxelVolume& volume, const std::vector<uint8_t>& inside, double voxelsPerNode, double hmin,
    double hmax);

  /// A uniform size for about `tets` tets.
  SizeGrid Uniform(double tets) const;
  /// The L2-optimal size for about `tets` tets from a fitted mesh: `points` (scaled index space,
  /// x y z each), `tets` (4 ids each) and each tet's RMS error and voxel count.
  SizeGrid Adapted(double tets, const std::vector<double>& points, const std::vector<std::array<int, 4>>& tetIds,
    const std::vector<double>& tetRms, const std::vector<long long>& tetVoxels) const;
  /// The distance bound that goes with a size field: max(floor, fraction * size).
  static SizeGrid DistanceFor(const SizeGrid& size, double fraction, double floor);

  /// Learns tets per unit of integral(h^-3) from a mesh made with `size` that has `tets` tets.
  void Calibrate(const SizeGrid& size, long long tets);
  /// The tets `size` is expected to give.
  double ExpectedTets(const SizeGrid& size) const { return K * Density(size); }

  double Gradation = 0.3; ///< largest change of size per unit of distance

private:
  double Density(const SizeGrid& g) const; ///< integral over the region of h^-3
  SizeGrid Scaled(const std::vector<double>& shape, double tets) const;
  void Grade(std::vector<float>& h) const;

  int N[3] = { 1, 1, 1 };
  double Step = 1;
  double VoxelSize = 1; ///< volume of one voxel
  double Hmin = 1, Hmax = 1;
  std::vector<float> RegionVoxels; ///< per node: the region's voxels nearest to it
  double K = 6.0;                  ///< tets per unit of integral(h^-3), calibrated
};
} // namespace art

#endif
