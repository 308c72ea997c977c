// RegionMask: the voxels a region reduction meshes. By value range: the voxels whose value lies in
// [lo, hi] (the bone of a CT, the brain of an MRI); by labels: every voxel of a label map whose
// label is not the background, each with its label. Connected pieces (26-neighbours, so pieces
// that touch only at a corner of the trilinear interpolant are one) of fewer voxels than a
// threshold are dropped as segmentation noise: an island of a label inside another label takes
// the label around it, an island in the background leaves the region.
#ifndef art_RegionMask_h
#define art_RegionMask_h

#include "AdaptiveRTReductionModule.h"
#include "VoxelVolume.h"

#include <cstdint>
#include <vector>

namespace art
{
struct RegionMask
{
  std::vector<uint8_t> Inside; ///< 1 for a voxel that is meshed (VoxelVolume order)
  /// Labels: each voxel's subdomain, 0 outside, else 1 + its label's index in Labels (empty for
  /// a value range).
  std::vector<int32_t> Slot;
  std::vector<long long> Labels;     ///< the labels meshed, ascending (labels only)
  std::vector<long long> LabelVoxels; ///< voxels of each, after the islands (labels only)
  long long Voxels = 0;           ///< voxels meshed, after the islands
  long long Pieces = 0;           ///< connected pieces kept (per label for labels)
  long long IslandsDropped = 0;   ///< pieces below the threshold
  long long IslandVoxels = 0;     ///< their voxels
  long long MinIslandVoxels = 0;  ///< the threshold used
};

/// The default island threshold for a region of `voxels` voxels: 27 (a 3 x 3 x 3 block) or
/// 0.01% of the region, whichever is larger.
ADAPTIVERTREDUCTION_EXPORT long long DefaultMinIslandVoxels(long long voxels);

/// The voxels in [lo, hi] (inclusive). `minIsland` < 0 takes DefaultMinIslandVoxels. Throws
/// art::Error naming volume.File when lo > hi or no voxel lies in the range.
ADAPTIVERTREDUCTION_EXPORT RegionMask MaskByRange(const VoxelVolume& volume, double lo, double hi, long long minIsland = -1);

/// A label map: its values must be integers; `background` is not meshed. Throws art::Error naming
/// volume.File for values that are not integers, or when no voxel holds another label.
ADAPTIVERTREDUCTION_EXPORT RegionMask MaskByLabels(const VoxelVolume& volume, long long background, long long minIsland = -1);
} // namespace art

#endif
