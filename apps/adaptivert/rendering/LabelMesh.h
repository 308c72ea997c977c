// LabelMesh: a label map's tet mesh (the cell array "label" that reduce --labels writes) made
// ready for the caster: each point is repeated once per label around it, carrying that label as
// its point scalar, so every tet shows its own label's colour right up to the interface
// (averaging the cell values to the points would blend two labels' colours there). The
// interfaces become coincident boundary faces, which the non-convex (multi-entry) path walks
// through from one label's tets into the next.
#ifndef adaptivert_LabelMesh_h
#define adaptivert_LabelMesh_h

#include <vtkSmartPointer.h>

#include <string>

class vtkUnstructuredGrid;

namespace cli
{
/// True when the array to render is the cell array "label": named so by `array`, or, with
/// `array` empty, the grid has no point scalars and a cell array "label".
bool IsLabelMesh(vtkUnstructuredGrid* grid, const std::string& array);

/// The grid with its points split per label and the point scalars "label" (cells unchanged).
vtkSmartPointer<vtkUnstructuredGrid> SplitByLabel(vtkUnstructuredGrid* grid);
} // namespace cli

#endif
