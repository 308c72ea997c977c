// LabelColours: how render and the viewer draw a label mesh (the cell array "label" that reduce
// --labels writes): by default each label's tets in its categorical colour, and, when the mesh
// also carries a volume's values (reduce --labels --values), those values inside each label:
// the label's hue, its brightness and opacity from the values (art::LabelMesh).
// --label-colours flat goes back to the labels alone, off draws the values as any mesh's.
#ifndef adaptivert_LabelColours_h
#define adaptivert_LabelColours_h

#include "LabelMesh.h"
#include "TransferFunction.h"

#include <optional>
#include <string>

class vtkUnstructuredGrid;

namespace cli
{
enum class LabelColouring
{
  Values, ///< the values inside each label when there are values, else Flat
  Flat,   ///< each label in its colour
  Off     ///< the labels ignored
};
/// --label-colours' words (values, flat, off); false for any other.
bool ParseLabelColouring(const std::string& word, LabelColouring& mode);
/// The help text of --label-colours.
const char* LabelColouringHelp();

/// The label mesh to draw for `grid` and the array chosen (`array`, empty for the active
/// scalars): flat when that array is the cell array "label" or there are no point values,
/// values inside the labels when it is a point array (unless `mode` says flat), none when the
/// grid has no labels, `mode` is Off, or `valuesApply` is false (maximum intensity, iso-surfaces:
/// they follow the values alone).
std::optional<art::LabelMesh> LabelMeshFor(
  vtkUnstructuredGrid* grid, const std::string& array, LabelColouring mode, bool valuesApply = true);

/// The function of a label mesh with values, `source` the grid it was split from: each label in
/// its hue over `tf` ("auto": art::LabelValueRamp over the values' robust window, which the
/// mesh's field data records; a preset or file: that function over the values, tinted by each
/// label), its opacities per the data's sample spacing unless the file states a unit distance.
art::TransferFunction LabelValuesFunction(const art::LabelMesh& m, vtkUnstructuredGrid* source, const std::string& tf);
} // namespace cli

#endif
