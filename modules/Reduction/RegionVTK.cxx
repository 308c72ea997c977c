#include "RegionVTK.h"

#include "ReducerVTK.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>

namespace art
{
vtkSmartPointer<vtkUnstructuredGrid> RegionToUnstructuredGrid(
  const RegionResult& r, const RegionOptions& o, bool doubleValues, const WholeBoxFigures* wholeBox)
{
  vtkSmartPointer<vtkUnstructuredGrid> grid = ToUnstructuredGrid(r.Mesh, doubleValues);
  vtkFieldData* fd = grid->GetFieldData();
  auto field = [&](const char* name, double v) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfTuples(1);
    a->SetValue(0, v);
    fd->AddArray(a);
  };
  if (o.Labels)
  {
    vtkNew<vtkIntArray> label;
    label->SetName("label");
    label->SetNumberOfTuples(static_cast<vtkIdType>(r.TetLabels.size()));
    for (size_t t = 0; t < r.TetLabels.size(); ++t)
    {
      label->SetValue(static_cast<vtkIdType>(t), static_cast<int>(r.TetLabels[t]));
    }
    grid->GetCellData()->AddArray(label);
    if (r.Mesh.Values.empty())
    {
      grid->GetCellData()->SetActiveScalars("label");
    }
    vtkNew<vtkDoubleArray> labels;
    labels->SetName("labels");
    for (long long l : r.Mask.Labels)
    {
      labels->InsertNextValue(static_cast<double>(l));
    }
    fd->AddArray(labels);
    field("background", static_cast<double>(o.Background));
  }
  else
  {
    field("region_low", o.Lo);
    field("region_high", o.Hi);
  }
  field("region_voxels", static_cast<double>(r.Mask.Voxels));
  field("covered_voxels", static_cast<double>(r.CoveredVoxels));
  field("region_pieces", static_cast<double>(r.Mask.Pieces));
  field("islands_dropped", static_cast<double>(r.Mask.IslandsDropped));
  field("island_voxels", static_cast<double>(r.Mask.IslandVoxels));
  field("min_island_voxels", static_cast<double>(r.Mask.MinIslandVoxels));
  field("meshings", static_cast<double>(r.Rounds.size()));
  if (wholeBox)
  {
    field("whole_box_tets", static_cast<double>(wholeBox->Tets));
    field("whole_box_reached", wholeBox->Reached ? 1.0 : 0.0);
  }
  return grid;
}
} // namespace art
