// RegionReducer: the least-squares reducer on a region of a volume, or on a label map: tets only
// where the object is ("model no more than the scene needs"). The region (RegionMask) is meshed by
// an image-domain mesher (vtkImageDomainMesher: CGAL's Mesh_3), so the mesh's boundary lies on
// the region's surface and a label map's interfaces are shared faces; the voxels inside are
// fitted in the least-squares sense (LeastSquaresFit with the region as its mask, Grosso, Luerig
// & Ertl, Vis '97, section 3) and the region is meshed again to a size field adapted to the fit's
// error (RegionSizing), calibrated to the budget, until the budget or the error bound is met.
// Levels are remeshed, not nested.
#ifndef art_RegionReducer_h
#define art_RegionReducer_h

#include "AdaptiveRTReductionModule.h"
#include "ImageDomain.h"
#include "RegionMask.h"
#include "TetReducer.h"
#include "VoxelVolume.h"

#include <functional>
#include <string>
#include <vector>

namespace art
{
class Progress;

struct RegionOptions
{
  bool Labels = false;          ///< the volume is a label map (else a region by value)
  double Lo = 0, Hi = 0;        ///< the region's value range (inclusive)
  long long Background = 0;     ///< the label that is not meshed
  long long MinIslandVoxels = -1; ///< pieces below this are dropped (< 0: DefaultMinIslandVoxels)
  /// A label map's values to fit (same dimensions; null: the label mesh carries no values).
  const VoxelVolume* Values = nullptr;
  long long TargetTets = 0;     ///< stop near this many tets (0: not set)
  double TargetError = -1;      ///< RMS inside the region, data units (< 0: not set)
  double BudgetTolerance = 0.1; ///< a meshing within this fraction of TargetTets meets it
  int Rounds = 4;               ///< meshings for a budget: the first uniform, then adapted
  int MaxRounds = 8;            ///< meshings for an error bound alone
  double MinEdgeVoxels = 1.0;   ///< smallest size asked for, in voxels
  double FacetDistance = 0.3;   ///< least boundary distance bound, in voxels
  double DistanceFraction = 0.1; ///< the boundary distance bound as a fraction of the local size
  double NodeVoxels = 4;        ///< the size field's node spacing, in voxels
  bool SmoothLabels = true;     ///< weights for smooth label surfaces (else voxel steps)
  double SolverTolerance = 1e-8;
  double Regularization = 0.5;
};

/// One meshing of the run, for the figures.
struct RegionRound
{
  long long Tets = 0, Vertices = 0;
  double ExpectedTets = 0;
  double Rms = 0;          ///< inside the region (NaN without values)
  double MeshSeconds = 0, FitSeconds = 0;
};

struct RegionResult
{
  ReducedMesh Mesh;                ///< values empty for a label map without values
  std::vector<long long> TetLabels; ///< per tet: its label (labels), or 1
  RegionMask Mask;                 ///< the voxels meshed (Inside kept, Slot released) and the islands
  long long CoveredVoxels = 0;     ///< region voxels inside the mesh (the fit and errors use these)
  std::vector<RegionRound> Rounds;
  int ChosenRound = 0;
};

/// The mesher: an image-domain request to its mesh (vtkImageDomainMesher::Mesh).
using DomainMesher = std::function<ImageDomainMesh(const ImageDomainRequest&)>;

/// Runs the region reduction. Throws art::Error for bad options or input (naming volume.File),
/// when the mesher fails, or when `progress` is cancelled.
ADAPTIVERTREDUCTION_EXPORT RegionResult ReduceRegion(
  const VoxelVolume& volume, const RegionOptions& options, const DomainMesher& mesher, Progress* progress = nullptr);

/// Bytes a region run needs beyond the voxels: about 40 a voxel (the mask, the mesher's image
/// and the fit's tables) and 1,500 a tet of the mesher's triangulation.
ADAPTIVERTREDUCTION_EXPORT double RegionMemoryNeeded(long long voxels, long long tets);
} // namespace art

#endif
