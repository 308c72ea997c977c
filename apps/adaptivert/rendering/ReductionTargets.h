// ReductionTargets: the reducer's stopping targets as the command line spells them, shared by
// `reduce` and `render`: --tets N or P% (of the voxel count), --max-error E or P% (of the range),
// and how it refines, --refinement bisection|edge|anisotropic.
#ifndef adaptivert_ReductionTargets_h
#define adaptivert_ReductionTargets_h

#include <string>

namespace cli
{
/// "N" or "P%" -> tets; throws UsageError naming `what` otherwise.
long long ParseBudget(const std::string& s, long long voxels, const std::string& what);
/// "E" or "P%" -> the error bound and whether it is a fraction of the scalar range (P / 100).
double ParseMaxError(const std::string& s, bool& relative);
}

#ifdef ART_HAVE_Reduction
#include "TetReducer.h"
#include "VoxelVolume.h"

namespace cli
{
/// "bisection", "edge" (error-driven edge splits) or "anisotropic" (MMG3D); throws UsageError
/// naming `what` (the option) otherwise.
art::ReducerOptions::Refinement ParseRefinement(const std::string& s, const std::string& what);

/// Why the reduction of `v` stopped short of level m's target ("" when it reached it): the fit is
/// exact, the voxels allow no finer tets, or an error bound alone (no --tets) stops at one tet
/// per voxel.
std::string UnreachedReason(const art::ReducedMesh& m, const art::VoxelVolume& v, bool errorBoundAlone);

/// Caps `tets` (a budget of `what`, "--tets") at art::FullResolutionTetCount(v), before any
/// work starts (a budget of 60M on 8.7M voxels ran for half an hour refining towards it);
/// returns the note saying the full-resolution mesh is made instead, or "" below it.
std::string CapToFullResolution(long long& tets, const art::VoxelVolume& v, const std::string& what);
}
#endif

#endif
