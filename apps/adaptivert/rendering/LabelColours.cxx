#include "rendering/LabelColours.h"

#include "DataTransferFunction.h"
#include "ScalarStatistics.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

namespace cli
{
bool ParseLabelColouring(const std::string& word, LabelColouring& mode)
{
  if (word == "values" || word == "flat" || word == "off")
  {
    mode = word == "values" ? LabelColouring::Values : word == "flat" ? LabelColouring::Flat : LabelColouring::Off;
    return true;
  }
  return false;
}

const char* LabelColouringHelp()
{
  return "how a label mesh (cell array 'label', as reduce --labels writes it) is coloured: values (the default: "
         "each label in its categorical colour, and when the mesh carries a volume's values (reduce --values) "
         "their brightness and opacity inside each label), flat (each label in its colour, the values left out), "
         "off (the labels ignored: the values as in any mesh)";
}

std::optional<art::LabelMesh> LabelMeshFor(
  vtkUnstructuredGrid* grid, const std::string& array, LabelColouring mode, bool valuesApply)
{
  if (mode == LabelColouring::Off || !art::LabelMesh::Has(grid))
  {
    return std::nullopt;
  }
  vtkDataArray* values = array.empty() ? grid->GetPointData()->GetScalars() : grid->GetPointData()->GetArray(array.c_str());
  if (values && values->GetNumberOfComponents() != 1)
  {
    values = nullptr;
  }
  const bool flat = array.empty() ? values == nullptr : array == "label" && values == nullptr;
  if (flat || (values && mode == LabelColouring::Flat))
  {
    return art::LabelMesh(grid, nullptr);
  }
  if (values && valuesApply)
  {
    return art::LabelMesh(grid, values);
  }
  return std::nullopt;
}

art::TransferFunction LabelValuesFunction(const art::LabelMesh& m, vtkUnstructuredGrid* source, const std::string& tf)
{
  const double lo = m.ValueLow(), hi = m.ValueHigh();
  if (tf == "auto")
  {
    const art::ScalarStatistics s = art::StatisticsFor(source, lo, hi);
    const double unit = art::TransferFunction::SampleSpacing(source);
    return m.Compose(
      [&](double label) { return art::LabelValueRamp(label, s.windowLow, s.windowHigh, unit); }, unit);
  }
  const art::TransferFunction base = art::TransferFunction::NamesFile(tf)
    ? art::TransferFunction::FromFile(tf)
    : art::TransferFunction::PresetFor(tf, source, lo, hi);
  return m.Compose([&](double label) { return art::TintedByLabel(base, label); }, base.UnitDistance());
}
} // namespace cli
