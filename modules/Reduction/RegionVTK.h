// RegionVTK: a region reduction's VTK edge: RegionResult -> vtkUnstructuredGrid of VTK_TETRA as
// ToUnstructuredGrid makes it, plus the cell array "label" of a label map's mesh (its active
// cell scalars when it carries no values) and the region's figures as field data: region_low /
// region_high (or the labels and background), region_voxels, covered_voxels, region_pieces,
// islands_dropped, island_voxels, min_island_voxels, meshings, and whole_box_tets when compared.
#ifndef art_RegionVTK_h
#define art_RegionVTK_h

#include "AdaptiveRTReductionModule.h"
#include "RegionReducer.h"
#include "WholeBoxComparison.h"

#include <vtkSmartPointer.h>

class vtkUnstructuredGrid;

namespace art
{
ADAPTIVERTREDUCTION_EXPORT vtkSmartPointer<vtkUnstructuredGrid> RegionToUnstructuredGrid(const RegionResult& r,
  const RegionOptions& options, bool doubleValues, const WholeBoxFigures* wholeBox = nullptr);
} // namespace art

#endif
