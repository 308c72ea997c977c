// ReducedLevel: a fitted mesh as one output level of the reducer, shared by every refinement:
// the values clamped or capped as the options ask, and the mesh in world coordinates with its
// errors against the voxels.
#ifndef art_ReducedLevel_h
#define art_ReducedLevel_h

#include "BisectionMesh.h"
#include "LeastSquaresFit.h"
#include "OpacityImportance.h"
#include "TetReducer.h"
#include "VoxelVolume.h"

#include <array>
#include <vector>

namespace art
{
/// The fitted values x as output: clamped to the range of the voxels under each vertex's tets,
/// all of them (`clamp`) or those more opaque than those voxels (`cap`, when given).
std::vector<double> OutputValues(const BisectionMesh& mesh, const LeastSquaresFit& fit, std::vector<double> x,
  bool clamp, const OpacityImportance* cap);

/// Writes tet `v` to `out` (4 ids) with its corners ordered so that its volume in the world
/// coordinates `points` (x y z per vertex) is positive, as VTK_TETRA wants: a direction matrix
/// that mirrors flips the lattice's orientation.
void WritePositiveTet(std::array<int, 4> v, const std::vector<double>& points, int* out);

/// The output values x of `mesh` and their errors e (LeastSquaresFit::VoxelErrors) as a level:
/// world coordinates, tets positively oriented (VTK_TETRA), the input's range and name.
ReducedMesh Snapshot(const VoxelVolume& vol, const BisectionMesh& mesh, const std::vector<double>& x,
  VoxelErrorReport e);
} // namespace art

#endif
