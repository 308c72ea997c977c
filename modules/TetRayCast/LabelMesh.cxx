#include "LabelMesh.h"

#include "DataTransferFunction.h"
#include "Error.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace art
{
namespace
{
using Node = TransferFunction::Node;

// The distinct labels of the cells, ascending.
std::vector<double> DistinctLabels(vtkDataArray* label)
{
  std::vector<double> l;
  for (vtkIdType c = 0; c < label->GetNumberOfTuples(); ++c)
  {
    l.push_back(label->GetTuple1(c));
  }
  std::sort(l.begin(), l.end());
  l.erase(std::unique(l.begin(), l.end()), l.end());
  return l;
}

// Colour and opacity per unitDistance of f at s, the extinction kept.
Node NodeAt(const TransferFunction& f, double at, double s, double unitDistance)
{
  Node n{ at, { 0, 0, 0 }, 0, 0 };
  double tau = 0;
  f.Evaluate(s, n.rgb, tau);
  n.alpha = 1.0 - std::exp(-tau * unitDistance);
  return n;
}
} // namespace

bool LabelMesh::Has(vtkUnstructuredGrid* grid, const std::string& labels)
{
  vtkDataArray* a = grid ? grid->GetCellData()->GetArray(labels.c_str()) : nullptr;
  return a && a->GetNumberOfComponents() == 1;
}

LabelMesh::LabelMesh(vtkUnstructuredGrid* grid, vtkDataArray* values, const std::string& labels)
{
  if (!Has(grid, labels))
  {
    throw Error("the mesh has no one-component cell array '" + labels + "' of labels");
  }
  vtkDataArray* label = grid->GetCellData()->GetArray(labels.c_str());
  L = DistinctLabels(label);
  Values = values != nullptr;
  if (Values)
  {
    double r[2];
    values->GetRange(r, 0); // NaN-free range; TetMesh::FromVTK names a NaN
    Lo = r[0];
    Hi = r[1] > r[0] ? r[1] : r[0] + 1.0;
  }
  std::map<double, double> band; // label -> 2 i
  for (std::size_t i = 0; i < L.size(); ++i)
  {
    band[L[i]] = 2.0 * static_cast<double>(i);
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName(Values ? "label_values" : "label");
  Split = vtkSmartPointer<vtkUnstructuredGrid>::New();
  Split->Allocate(grid->GetNumberOfCells());
  std::map<std::pair<vtkIdType, double>, vtkIdType> copy; // (point, label) -> its copy
  vtkNew<vtkIdList> ids, split;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
  {
    const double l = label->GetTuple1(c);
    grid->GetCellPoints(c, ids);
    split->SetNumberOfIds(ids->GetNumberOfIds());
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      const vtkIdType p = ids->GetId(k);
      auto it = copy.find({ p, l });
      if (it == copy.end())
      {
        it = copy.emplace(std::make_pair(p, l), points->InsertNextPoint(grid->GetPoint(p))).first;
        scalars->InsertNextValue(Values ? band[l] + (values->GetComponent(p, 0) - Lo) / (Hi - Lo) : l);
      }
      split->SetId(k, it->second);
    }
    Split->InsertNextCell(grid->GetCellType(c), split);
  }
  Split->SetPoints(points);
  Split->GetPointData()->SetScalars(scalars);
  Split->GetCellData()->AddArray(label);
  Split->GetFieldData()->ShallowCopy(grid->GetFieldData());
  // The values' range and statistics describe the values, not the split's labels or bands (a
  // preset laid over the values' range drew every label in one colour).
  for (const char* name : { "scalar_range_min", "scalar_range_max", "source_window", "source_background_top",
         "source_label_values" })
  {
    Split->GetFieldData()->RemoveArray(name);
  }
}

TransferFunction LabelMesh::Compose(const std::function<TransferFunction(double)>& perLabel, double unitDistance) const
{
  std::vector<Node> n;
  for (std::size_t i = 0; i < L.size(); ++i)
  {
    const TransferFunction f = perLabel(L[i]);
    const double base = 2.0 * static_cast<double>(i);
    if (!Values) // the labels alone (the scalars are the labels): constant over each label
    {
      const double gap = std::min(i > 0 ? L[i] - L[i - 1] : 1.0, i + 1 < L.size() ? L[i + 1] - L[i] : 1.0);
      n.push_back(NodeAt(f, L[i] - 0.25 * gap, L[i], unitDistance));
      n.push_back(NodeAt(f, L[i] + 0.25 * gap, L[i], unitDistance));
      continue;
    }
    n.push_back(NodeAt(f, base, Lo, unitDistance));
    for (const Node& k : f.Nodes())
    {
      if (k.s > Lo && k.s < Hi)
      {
        n.push_back(NodeAt(f, base + (k.s - Lo) / (Hi - Lo), k.s, unitDistance));
      }
    }
    n.push_back(NodeAt(f, base + 1.0, Hi, unitDistance));
  }
  return TransferFunction(std::move(n), unitDistance);
}

TransferFunction TintedByLabel(const TransferFunction& f, double label)
{
  const double* c = TransferFunction::CategoricalColour(static_cast<long long>(std::fabs(label)));
  std::vector<Node> n = f.Nodes();
  for (Node& k : n)
  {
    const double y = 0.2126 * k.rgb[0] + 0.7152 * k.rgb[1] + 0.0722 * k.rgb[2];
    for (int a = 0; a < 3; ++a)
    {
      k.rgb[a] = std::min(1.0, y * c[a]);
    }
  }
  return TransferFunction(std::move(n), f.UnitDistance());
}

TransferFunction LabelValueRamp(double label, double lo, double hi, double unitDistance)
{
  hi = hi > lo ? hi : lo + std::max(1.0, std::fabs(lo)) * 1e-3;
  const TransferFunction grey(
    { { lo, { 0.3, 0.3, 0.3 }, 0.2 * LabelOpacity, 0 }, { hi, { 1, 1, 1 }, LabelOpacity, 0 } }, unitDistance);
  return TintedByLabel(grey, label);
}
} // namespace art
