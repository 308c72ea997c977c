// LabelMesh: a label mesh (each tet's label in a cell array, as `reduce --labels` writes "label")
// made ready for the caster, drawn in its labels' categorical colours or with a volume's values
// inside each label. Each point is repeated once per label around it, so every tet shows its own
// label right up to the interface (averaging the cells to the points would blend two labels
// there); the interfaces become coincident boundary faces, which the multi-entry walk crosses.
// Without values the copies carry their label (the "labels" preset draws it). With values, the
// copies of label i carry 2 i + t, t the value scaled to [0, 1] over the values' range: one
// scalar, linear in each tet as the value is, whose bands one piecewise-linear function maps
// through each label's own function of the value (Compose), so the exact segment integral of
// the emission-absorption model (Max 1995) holds inside every label.
#ifndef art_LabelMesh_h
#define art_LabelMesh_h

#include "AdaptiveRTTetRayCastModule.h"
#include "TransferFunction.h"

#include <vtkSmartPointer.h>

#include <functional>
#include <string>
#include <vector>

class vtkDataArray;
class vtkUnstructuredGrid;

namespace art
{
class ADAPTIVERTTETRAYCAST_EXPORT LabelMesh
{
public:
  /// True when `grid` has a one-component cell array named `labels`.
  static bool Has(vtkUnstructuredGrid* grid, const std::string& labels = "label");
  /// `grid` split per label (its cell array `labels`); `values`, a one-component point array of
  /// `grid` or nullptr, is drawn inside each label. Throws art::Error when the labels are missing.
  LabelMesh(vtkUnstructuredGrid* grid, vtkDataArray* values, const std::string& labels = "label");

  /// The split grid: point scalars "label" (no values) or "label_values" (the bands), the cell
  /// array of labels and the field data kept but for the values' range and statistics.
  vtkUnstructuredGrid* Grid() const { return Split; }
  const std::vector<double>& Labels() const { return L; }
  bool HasValues() const { return Values; }
  /// The values' range, which each band's [0, 1] spans.
  double ValueLow() const { return Lo; }
  double ValueHigh() const { return Hi; }

  /// The function drawing each label's tets by perLabel(label), a function of the values: exact
  /// between the values' range ends (perLabel's nodes inside it kept, its ends evaluated).
  /// Extinction is kept as it is at each node; opacities are restated per unitDistance.
  TransferFunction Compose(const std::function<TransferFunction(double label)>& perLabel, double unitDistance) const;

private:
  vtkSmartPointer<vtkUnstructuredGrid> Split;
  std::vector<double> L;
  bool Values = false;
  double Lo = 0, Hi = 1;
};

/// `f` in the hue of `label`: each node's colour is its luminance (Rec. 709) times the label's
/// categorical colour (TransferFunction::CategoricalColour(|label|), as the "labels" preset
/// colours it); opacities unchanged.
ADAPTIVERTTETRAYCAST_EXPORT TransferFunction TintedByLabel(const TransferFunction& f, double label);

/// The default inside a label: brightness from 0.3 to 1 and opacity from a fifth of LabelOpacity
/// to LabelOpacity per unitDistance over the values' window [lo, hi] (clamped outside it), tinted
/// by TintedByLabel.
ADAPTIVERTTETRAYCAST_EXPORT TransferFunction LabelValueRamp(double label, double lo, double hi, double unitDistance);
} // namespace art

#endif
