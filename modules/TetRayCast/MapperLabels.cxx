#include "MapperLabels.h"

#include "DataTransferFunction.h"
#include "MapperGrid.h"

#include <vtkCellData.h>
#include <vtkColorTransferFunction.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkVolumeProperty.h>

#include <cmath>

namespace art
{
namespace mapper
{
namespace
{
// p's function for one label: its label functions where it has them, else its own.
TransferFunction OneLabel(vtkVolumeProperty* p, double label, const TransferFunction& tinted)
{
  const int l = static_cast<int>(std::lround(label));
  vtkColorTransferFunction* c = p->GetLabelColor(l);
  vtkPiecewiseFunction* o = p->GetLabelScalarOpacity(l);
  if (!c && !o)
  {
    return tinted;
  }
  vtkNew<vtkVolumeProperty> q;
  q->DeepCopy(p);
  if (c)
  {
    q->SetColor(c);
  }
  if (o)
  {
    q->SetScalarOpacity(o);
  }
  return TransferFunction::FromVTK(q);
}

// The labels alone: one constant function per label.
TransferFunction Flat(vtkVolumeProperty* p, double label, double unit)
{
  const int l = static_cast<int>(std::lround(label));
  const double* k = TransferFunction::CategoricalColour(static_cast<long long>(std::fabs(label)));
  double rgb[3] = { k[0], k[1], k[2] };
  double alpha = LabelOpacity;
  if (vtkColorTransferFunction* c = p->GetLabelColor(l))
  {
    c->GetColor(label, rgb);
  }
  if (vtkPiecewiseFunction* o = p->GetLabelScalarOpacity(l))
  {
    alpha = o->GetValue(label);
  }
  const TransferFunction::Node a{ label - 0.5, { rgb[0], rgb[1], rgb[2] }, alpha, 0 };
  TransferFunction::Node b = a;
  b.s = label + 0.5;
  return TransferFunction({ a, b }, unit);
}
} // namespace

std::unique_ptr<LabelMesh> SplitLabels(
  vtkUnstructuredGrid* engineGrid, vtkUnstructuredGrid* grid, const std::string& name, bool flat)
{
  if (!LabelMesh::Has(grid, name))
  {
    return nullptr;
  }
  vtkDataArray* values = engineGrid->GetPointData()->GetScalars();
  vtkDataArray* cells = engineGrid->GetCellData()->GetScalars();
  const bool labelsSelected = !values && cells &&
    (cells == grid->GetCellData()->GetArray(name.c_str()) || (cells->GetName() && name == cells->GetName()));
  if (!values && !labelsSelected)
  {
    return nullptr; // another cell array drawn: the labels do not colour it
  }
  if (values && values->GetNumberOfComponents() != 1)
  {
    return nullptr; // SelectedScalars refused it already
  }
  auto view = vtkSmartPointer<vtkUnstructuredGrid>::New();
  view->ShallowCopy(engineGrid);
  view->GetCellData()->AddArray(grid->GetCellData()->GetArray(name.c_str()));
  vtkSmartPointer<vtkUnstructuredGrid> kept = WithoutGhosts(view, grid);
  if (kept->GetNumberOfCells() == 0)
  {
    return nullptr;
  }
  vtkDataArray* keptValues = flat ? nullptr : kept->GetPointData()->GetScalars();
  return std::make_unique<LabelMesh>(kept, keptValues, name);
}

TransferFunction LabelFunction(const LabelMesh& m, vtkVolumeProperty* p)
{
  const double unit = p->GetScalarOpacityUnitDistance(0);
  if (!m.HasValues())
  {
    return m.Compose([&](double label) { return Flat(p, label, unit); }, unit);
  }
  const TransferFunction own = TransferFunction::FromVTK(p);
  return m.Compose([&](double label) { return OneLabel(p, label, TintedByLabel(own, label)); }, unit);
}
} // namespace mapper
} // namespace art
