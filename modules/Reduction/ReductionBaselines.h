// ReductionBaselines: what the reducer is measured against, at equal size. VTK's quadric
// decimation of the volume's full tetrahedrisation (Vo et al., TVCG 2007; Garland-Heckbert
// quadrics with the scalar as a 4th coordinate), plain uniform downsampling with trilinear
// reconstruction, and an independent error check that probes any grid at the voxel centres.
#ifndef art_ReductionBaselines_h
#define art_ReductionBaselines_h

#include "AdaptiveRTReductionModule.h"
#include "VoxelVolume.h"

#include <vtkSmartPointer.h>

#include <vector>

class vtkImageData;
class vtkUnstructuredGrid;

namespace art
{
struct BaselineError
{
  double Rms = 0, Max = 0;   ///< over every voxel centre, data units
  long long Uncovered = 0;   ///< voxel centres outside the grid (counted with the fit value 0)
  double CoveredRms = 0;     ///< RMS over the voxel centres inside the grid only
  long long Vertices = 0, Tets = 0;
};

/// The volume's voxel cells split into tets by vtkDataSetTriangleFilter (the decimation input).
ADAPTIVERTREDUCTION_EXPORT vtkSmartPointer<vtkUnstructuredGrid> TetrahedralizeVolume(vtkImageData* image);

/// vtkUnstructuredGridQuadricDecimation of `grid` down to about `tets` tetrahedra.
ADAPTIVERTREDUCTION_EXPORT vtkSmartPointer<vtkUnstructuredGrid> QuadricDecimate(
  vtkUnstructuredGrid* grid, long long tets, const char* scalars);

/// Probes `grid` (its point scalars named `scalars`) at every voxel centre of `image` with
/// vtkProbeFilter and compares with the voxels. `covered` (when given) receives which voxel
/// centres the grid covers; with `only`, Rms and Max are taken over those voxels alone.
ADAPTIVERTREDUCTION_EXPORT BaselineError ProbeError(vtkImageData* image, vtkUnstructuredGrid* grid, const char* scalars,
  std::vector<char>* covered = nullptr, const std::vector<char>* only = nullptr);

/// Samples the volume on a uniform grid of about `vertices` nodes spanning the same box (shaped
/// to the volume's aspect, trilinear sampling, no pre-filter) and reconstructs every voxel from
/// it trilinearly. Tets reports 6 per grid cell (its Kuhn split), for comparison.
ADAPTIVERTREDUCTION_EXPORT BaselineError UniformDownsampleError(const VoxelVolume& volume, long long vertices);
} // namespace art

#endif
