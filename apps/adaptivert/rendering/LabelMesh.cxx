#include "rendering/LabelMesh.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <map>
#include <utility>

namespace cli
{
bool IsLabelMesh(vtkUnstructuredGrid* grid, const std::string& array)
{
  vtkDataArray* label = grid->GetCellData()->GetArray("label");
  if (!label || label->GetNumberOfComponents() != 1)
  {
    return false;
  }
  if (!array.empty())
  {
    return array == "label" && !grid->GetPointData()->GetArray("label");
  }
  return grid->GetPointData()->GetScalars() == nullptr;
}

vtkSmartPointer<vtkUnstructuredGrid> SplitByLabel(vtkUnstructuredGrid* grid)
{
  vtkDataArray* label = grid->GetCellData()->GetArray("label");
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> values;
  values->SetName("label");
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->Allocate(grid->GetNumberOfCells());
  std::map<std::pair<vtkIdType, double>, vtkIdType> copy; // (point, label) -> its copy
  vtkNew<vtkIdList> ids, split;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const double l = label->GetTuple1(c);
    grid->GetCellPoints(c, ids);
    split->SetNumberOfIds(ids->GetNumberOfIds());
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      auto it = copy.find({ ids->GetId(k), l });
      if (it == copy.end())
      {
        it = copy.emplace(std::make_pair(ids->GetId(k), l), points->InsertNextPoint(grid->GetPoint(ids->GetId(k)))).first;
        values->InsertNextValue(l);
      }
      split->SetId(k, it->second);
    }
    out->InsertNextCell(grid->GetCellType(c), split);
  }
  out->SetPoints(points);
  out->GetPointData()->SetScalars(values);
  out->GetCellData()->AddArray(label);
  out->GetFieldData()->ShallowCopy(grid->GetFieldData());
  return out;
}
} // namespace cli
