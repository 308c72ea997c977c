#include "MapperGrid.h"

#include "ArrayChoice.h"
#include "Error.h"

#include <vtkAbstractMapper.h> // VTK_SCALAR_MODE_*
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSetAttributes.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPlane.h>
#include <vtkPlaneCollection.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace art
{
namespace mapper
{
// The scale of `m` when its linear part is a rotation or mirror times one scale (orthogonal
// columns of one length), else 0.
double SimilarityScale(vtkMatrix4x4* m)
{
  double c[3][3], len2[3];
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      c[j][i] = m->GetElement(i, j);
    }
    len2[j] = c[j][0] * c[j][0] + c[j][1] * c[j][1] + c[j][2] * c[j][2];
  }
  const double lo = std::min(len2[0], std::min(len2[1], len2[2])), hi = std::max(len2[0], std::max(len2[1], len2[2]));
  if (!(lo > 0) || hi > lo * (1 + 2e-6))
  {
    return 0.0;
  }
  for (int a = 0; a < 3; ++a)
  {
    const int b = (a + 1) % 3;
    if (std::fabs(c[a][0] * c[b][0] + c[a][1] * c[b][1] + c[a][2] * c[b][2]) > 1e-6 * hi)
    {
      return 0.0;
    }
  }
  return std::sqrt(std::cbrt(len2[0] * len2[1] * len2[2]));
}

// grid with its points taken through `m` (the volume's matrix, or a mirror's divided by its scale),
// into the coordinates the engine casts in.
vtkSmartPointer<vtkUnstructuredGrid> Transformed(vtkUnstructuredGrid* grid, vtkMatrix4x4* m)
{
  auto pts = vtkSmartPointer<vtkPoints>::New();
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(grid->GetNumberOfPoints());
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i)
  {
    double p[4] = { 0, 0, 0, 1 }, q[4];
    grid->GetPoint(i, p);
    m->MultiplyPoint(p, q);
    pts->SetPoint(i, q[0] / q[3], q[1] / q[3], q[2] / q[3]);
  }
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->CopyStructure(grid);
  out->SetPoints(pts);
  out->GetPointData()->PassData(grid->GetPointData());
  out->GetCellData()->PassData(grid->GetCellData());
  return out;
}

// The grid as the engine should see it under the mapper's ScalarMode: sharing grid's points and
// cells, with only the array the mode selects (TetMesh::FromVTK takes the point scalars, else
// averages the cell scalars to the points). VTK_SCALAR_MODE_DEFAULT passes grid as it is. `key`
// names the choice (a change rebuilds the mesh); nullptr, with `error` set, when there is none.
vtkSmartPointer<vtkUnstructuredGrid> SelectedScalars(vtkUnstructuredGrid* grid, int mode, const char* name, int id,
  int component, std::string& key, std::string& error)
{
  vtkDataArray* a = nullptr;
  bool onCells = false;
  switch (mode)
  {
    case VTK_SCALAR_MODE_USE_POINT_DATA:
      a = grid->GetPointData()->GetScalars();
      error = a ? "" : "ScalarMode is UsePointData but the input has no point scalars";
      break;
    case VTK_SCALAR_MODE_USE_CELL_DATA:
      a = grid->GetCellData()->GetScalars();
      onCells = true;
      error = a ? "" : "ScalarMode is UseCellData but the input has no cell scalars";
      break;
    case VTK_SCALAR_MODE_USE_POINT_FIELD_DATA:
    case VTK_SCALAR_MODE_USE_CELL_FIELD_DATA:
    {
      onCells = mode == VTK_SCALAR_MODE_USE_CELL_FIELD_DATA;
      vtkFieldData* fd = onCells ? static_cast<vtkFieldData*>(grid->GetCellData())
                                 : static_cast<vtkFieldData*>(grid->GetPointData());
      a = name ? fd->GetArray(name) : fd->GetArray(id);
      if (!a)
      {
        const std::string what = name ? "'" + std::string(name) + "'" : "number " + std::to_string(id);
        error = std::string("the input has no ") + (onCells ? "cell" : "point") + " array " + what +
          " (SelectScalarArray; its arrays: " + art::ArrayNames({ grid->GetPointData(), grid->GetCellData() }) + ")";
      }
      break;
    }
    default:
      // The engine takes the point scalars, else the cell scalars: as they are unless a vector.
      a = grid->GetPointData()->GetScalars();
      onCells = !a;
      a = a ? a : grid->GetCellData()->GetScalars();
      if (!a || a->GetNumberOfComponents() == 1)
      {
        key = "default";
        return grid;
      }
      break;
  }
  if (!a)
  {
    return nullptr;
  }
  if (a->GetNumberOfComponents() != 1 && component == WholeArray)
  {
    error = std::string(onCells ? "cell" : "point") + " array '" + (a->GetName() ? a->GetName() : "") + "' has " +
      std::to_string(a->GetNumberOfComponents()) +
      " components; the mapper renders one (SetVectorMode(vtkTetRayCastMapper::MAGNITUDE), or COMPONENT with "
      "SetVectorComponent; or select another array with SelectScalarArray)";
    return nullptr;
  }
  vtkSmartPointer<vtkDataArray> named = a;
  if (component != WholeArray)
  {
    try
    {
      // A one-component array's component 0 is itself (VTK's mappers ignore VectorMode there).
      named = a->GetNumberOfComponents() == 1 ? vtkSmartPointer<vtkDataArray>(a) : TakeComponent(a, component);
    }
    catch (const Error& e)
    {
      error = e.problem() + " (SetVectorComponent)";
      return nullptr;
    }
  }
  if (!a->GetName() || !*a->GetName())
  {
    // FromVTK averages cell arrays to the points by name.
    named.TakeReference(a->NewInstance());
    named->ShallowCopy(a);
    named->SetName("scalars");
  }
  auto view = vtkSmartPointer<vtkUnstructuredGrid>::New();
  view->CopyStructure(grid);
  (onCells ? static_cast<vtkDataSetAttributes*>(view->GetCellData()) : view->GetPointData())->SetScalars(named);
  key = std::to_string(mode) + ":" + std::to_string(reinterpret_cast<std::uintptr_t>(a)) + ":" +
    std::to_string(a->GetNumberOfComponents() == 1 ? WholeArray : component);
  return view;
}

// engineGrid (grid, or a view sharing its cells) without the cells grid marks as ghosts
// (DUPLICATECELL in vtkGhostType: a parallel piece's copies of its neighbours' cells, drawn by
// their own piece, as VTK's mappers skip them) and without the marks (never taken as scalars).
vtkSmartPointer<vtkUnstructuredGrid> WithoutGhosts(vtkUnstructuredGrid* engineGrid, vtkUnstructuredGrid* grid)
{
  vtkDataArray* marks = grid->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName());
  if (!marks)
  {
    return engineGrid;
  }
  auto out = vtkSmartPointer<vtkUnstructuredGrid>::New();
  out->ShallowCopy(engineGrid);
  out->GetCellData()->AddArray(marks);
  out->RemoveGhostCells();
  out->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  return out;
}

// The mapper's clipping planes (world coordinates, keeping the side their normal points to, as
// VTK's mappers do) in the data's coordinates: (a, b, c, d) with a x + b y + c z + d >= 0 kept.
std::vector<std::array<double, 4>> PlanesInData(vtkPlaneCollection* planes, vtkMatrix4x4* toWorld)
{
  std::vector<std::array<double, 4>> out;
  if (!planes)
  {
    return out;
  }
  for (int i = 0; i < planes->GetNumberOfItems(); ++i)
  {
    vtkPlane* p = planes->GetItem(i);
    double n[3], o[3];
    p->GetNormal(n);
    p->GetOrigin(o);
    // n . (M x - o) = (M^T n) . x - n . o
    std::array<double, 4> q{};
    for (int c = 0; c < 3; ++c)
    {
      q[c] = n[0] * toWorld->GetElement(0, c) + n[1] * toWorld->GetElement(1, c) + n[2] * toWorld->GetElement(2, c);
    }
    double t[3] = { toWorld->GetElement(0, 3), toWorld->GetElement(1, 3), toWorld->GetElement(2, 3) };
    q[3] = n[0] * (t[0] - o[0]) + n[1] * (t[1] - o[1]) + n[2] * (t[2] - o[2]);
    out.push_back(q);
  }
  return out;
}
} // namespace mapper
} // namespace art
