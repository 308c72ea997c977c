// MapperLabels: vtkTetRayCastMapper's label colouring. A grid whose cells carry labels (a cell
// array, "label" as vtkAdaptiveTetReducer's SetLabels writes it) is split per label
// (art::LabelMesh); each label is drawn by its own functions of the selected point values, as
// VTK's label-map volume rendering takes them from vtkVolumeProperty (SetLabelColor,
// SetLabelScalarOpacity), else by the property's functions in the label's categorical hue.
#ifndef art_MapperLabels_h
#define art_MapperLabels_h

#include "LabelMesh.h"

#include <memory>
#include <string>

class vtkUnstructuredGrid;
class vtkVolumeProperty;

namespace art
{
namespace mapper
{
/// The label mesh of engineGrid (the selected scalars, as SelectedScalars gives them) with the
/// labels `name` of grid (ghost cells left out): values when the selected scalars are point
/// values, the labels alone when they are the labels themselves (on the cells), nullptr when
/// grid has no such labels or other cell scalars are selected; `flat` draws the labels alone.
std::unique_ptr<LabelMesh> SplitLabels(
  vtkUnstructuredGrid* engineGrid, vtkUnstructuredGrid* grid, const std::string& name, bool flat);
/// The function drawing m under p: with values, each label by p's label functions where it has
/// them (the main function standing in for a missing one), else p's functions tinted by the
/// label (art::TintedByLabel); without, each label in p's label colour at the label, else its
/// categorical colour, opaque as p's label opacity at the label, else art::LabelOpacity. The
/// opacities per p's unit distance.
TransferFunction LabelFunction(const LabelMesh& m, vtkVolumeProperty* p);
} // namespace mapper
} // namespace art

#endif
