// DefaultFrame: what the default camera frames: the visible part of the data under its transfer
// function (art::VisibleBounds). A mesh reduced from a volume carries the box the volume's own
// default frame fits ("source_visible_bounds", under the default transfer function), so that
// `render` of the mesh and of the volume frame alike: the mesh's coarse tets reach a little
// further into the clear background than the voxels do.
#ifndef adaptivert_DefaultFrame_h
#define adaptivert_DefaultFrame_h

#include "Box3.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkDataArray;
class vtkFieldData;
class vtkImageData;
class vtkUnstructuredGrid;

namespace art
{
class TetMesh;
struct RenderSettings;
}

namespace cli
{
/// "source_visible_bounds" (xmin xmax ymin ymax zmin zmax) of `image` under its "auto" transfer
/// function; none when nothing is visible.
vtkSmartPointer<vtkDataArray> SourceVisibleBounds(vtkImageData* image);
/// The box to frame: an image's visible voxels; a mesh's recorded source box when it is drawn
/// with the default function (`tf` "auto", no iso-surfaces, not MIP), else its visible tets.
art::Box3 ObjectBounds(vtkImageData* image, vtkUnstructuredGrid* grid, const art::TetMesh* mesh,
  const art::RenderSettings& s, const std::string& tf);
} // namespace cli

#endif
