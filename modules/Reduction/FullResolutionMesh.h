// FullResolutionMesh: the finest mesh a reduction can make, the voxels themselves: 5 tets per
// voxel cell (odd cells mirrored so shared face diagonals agree), each vertex a voxel with its
// value, so the fit is exact. A budget at or past its tet count asks for it, and it is built
// directly rather than refined towards by bisection (which took minutes to hours to get there).
#ifndef art_FullResolutionMesh_h
#define art_FullResolutionMesh_h

#include "AdaptiveRTReductionModule.h"
#include "TetReducer.h"
#include "VoxelVolume.h"

namespace art
{
/// Tets in 5 * (nx-1)(ny-1)(nz-1), positively oriented; throws art::Error naming the volume's file
/// when it has no cells (fewer than 2 voxels along an axis) or the mesh would not fit in memory.
ADAPTIVERTREDUCTION_EXPORT long long FullResolutionTetCount(const VoxelVolume& v);
ADAPTIVERTREDUCTION_EXPORT ReducedMesh FullResolutionMesh(const VoxelVolume& v);
} // namespace art

#endif
