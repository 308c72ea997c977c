// VertexRelocator: moves the vertices of a fitted mesh off the bisection lattice to where their
// star fits the voxels better (feature-aligned vertices, as quadric decimation gets by placing
// them freely; cf. Garland & Zhou, "Quadric-based simplification in any dimension", 2005).
#ifndef art_VertexRelocator_h
#define art_VertexRelocator_h

#include "AdaptiveRTReductionModule.h"
#include "BisectionMesh.h"
#include "VoxelVolume.h"

#include <vector>

namespace art
{
class OpacityImportance;
class Progress;

struct RelocationOptions
{
  int Sweeps = 3;            ///< Gauss-Seidel sweeps over the vertices
  double QualityFloor = 0.2; ///< a moved tet keeps 6 sqrt(2) V / l_rms^3 >= min(this, its value before)
  int ScreenStride = 0;      ///< candidates screened on every s-th voxel per axis (0: automatic, up to 3)
  int ScreenVoxels = 64;     ///< the screening subsample keeps at least this many of a star's voxels
  int ExactCandidates = 1;   ///< the best screened candidates evaluated exactly
  bool MeasureSse = true;    ///< fill RelocationStats' Sse* (two more voxel passes; the reducer refits and measures anyway)
};

struct RelocationStats
{
  long long Visited = 0, Moved = 0; ///< vertex visits over all sweeps, and accepted moves
  double SseBefore = 0, SseAfter = 0; ///< sum of squared errors over every voxel, before / after the sweeps (no refit; with MeasureSse)
  int Sweeps = 0;
};

class ADAPTIVERTREDUCTION_EXPORT VertexRelocator
{
public:
  /// Relocates the vertices of `mesh` (the fit `x` on it is updated with it). Each visit tries
  /// moves of one vertex along the voxel gradient, the axes and toward its star's centroid, 0.3
  /// of the distance that would flatten a tet of its star, then half and 1.5 times the best of
  /// these; candidates are ranked on a subsample of the star's voxels in floating point
  /// (ScreenRaster) and the best is evaluated exactly (TetRaster; the star's error at the
  /// current place comes from per-tet voxel moments kept up to date when unweighted). It is
  /// kept when the star's squared error, with that vertex's value refitted (the others fixed), drops, no
  /// tet of the star flips or flattens (exact integer orientation on the lattice) and none gets
  /// worse than the quality floor. Box corners stay, vertices on a box edge or face move only
  /// within it, so the mesh stays a conforming tetrahedrisation of the box and the lattice
  /// raster still gives each voxel centre to exactly one tet. Vertices with no tet in common are
  /// relaxed in parallel (colour classes): the same result for any thread count. With an
  /// `importance` (prepared), errors are OpacityImportance's weighted ones, each voxel weighed
  /// at the fit relocated from (frozen: the star errors then come from weighted moments as the
  /// plain ones do: cheaper than reweighing each candidate, and the same images).
  /// Sse* are the weights at each fit.
  /// `progress` (optional) gets a stage "relocate" and may cancel it (art::Error "cancelled").
  static RelocationStats Relocate(BisectionMesh& mesh, const VoxelVolume& volume, std::vector<double>& x,
    const RelocationOptions& options = {}, const OpacityImportance* importance = nullptr,
    Progress* progress = nullptr);
};
} // namespace art

#endif
