// CellVoxels: an image whose values are on its cells (voxel-centred data: labels, finite-volume
// simulations) as an image of voxels at the cell centres, for tools that read point values.
#ifndef art_CellVoxels_h
#define art_CellVoxels_h

#include "AdaptiveRTCoreModule.h"

#include <vtkSmartPointer.h>

class vtkCellData;
class vtkImageData;

namespace art
{
/// One voxel per cell of `img` at the cell's centre (same spacing and direction; a flat axis keeps
/// its one layer), carrying `cells` (img's cell data, or part of it) as its point data.
ADAPTIVERTCORE_EXPORT vtkSmartPointer<vtkImageData> CellVoxels(vtkImageData* img, vtkCellData* cells);
} // namespace art

#endif
