// ReducerVTK: the reducer's VTK edges. vtkImageData -> VoxelVolume (with the checks a user
// mistake needs), ReducedMesh -> vtkUnstructuredGrid of VTK_TETRA with point scalars named like
// the input, per-tet "approximation_error" and "max_error", and the run's figures as field data
// (among them "refinement", a string, and "levels_nested", 1 or 0).
#ifndef art_ReducerVTK_h
#define art_ReducerVTK_h

#include "AdaptiveRTReductionModule.h"
#include "MeshQuality.h"
#include "TetReducer.h"
#include "VoxelVolume.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkImageData;
class vtkUnstructuredGrid;

namespace art
{
/// Copies the active point scalars (any type, one component). Throws art::Error naming `file`
/// for an empty or 2-D image, several components, no scalars, or NaN values.
ADAPTIVERTREDUCTION_EXPORT VoxelVolume VolumeFromImage(vtkImageData* image, const std::string& file = {});

/// Are samples of this VTK type kept (and written) as double? float and smaller types are not.
ADAPTIVERTREDUCTION_EXPORT bool ReducedAsDouble(int vtkType);

/// The output grid; `doubleValues` selects double rather than float point scalars. `quality`:
/// MeasureQuality of `mesh` when already known (it takes a while on tens of millions of tets).
ADAPTIVERTREDUCTION_EXPORT vtkSmartPointer<vtkUnstructuredGrid> ToUnstructuredGrid(
  const ReducedMesh& mesh, bool doubleValues = false, const QualityReport* quality = nullptr);

/// MeasureQuality on a grid of VTK_TETRA cells (other cell types are counted as inverted).
ADAPTIVERTREDUCTION_EXPORT QualityReport MeasureQuality(vtkUnstructuredGrid* grid);
} // namespace art

#endif
