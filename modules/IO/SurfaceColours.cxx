#include "SurfaceColours.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <cmath>

namespace art
{
namespace
{
// A colour array: three or more components, one tuple per element.
bool IsColours(vtkDataArray* a, vtkIdType n)
{
  return a && a->GetNumberOfComponents() >= 3 && a->GetNumberOfTuples() == n;
}
}

vtkSmartPointer<vtkPolyData> WithColoursOnPoints(vtkPolyData* pd)
{
  vtkDataArray* fc = pd->GetCellData()->GetScalars();
  if (IsColours(pd->GetPointData()->GetScalars(), pd->GetNumberOfPoints()) || !IsColours(fc, pd->GetNumberOfCells()))
  {
    return pd;
  }
  vtkNew<vtkTriangleFilter> tri; // carries each polygon's and strip's colour to its triangles
  tri->SetInputData(pd);
  tri->PassVertsOff();
  tri->PassLinesOff();
  tri->Update();
  vtkPolyData* t = tri->GetOutput();
  vtkDataArray* tc = t->GetCellData()->GetScalars();
  if (!IsColours(tc, t->GetNumberOfCells()))
  {
    return pd;
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(t->GetPoints()->GetDataType()); // double coordinates stay double
  auto colours = vtk::TakeSmartPointer(tc->NewInstance());
  colours->SetName(tc->GetName());
  colours->SetNumberOfComponents(tc->GetNumberOfComponents());
  vtkNew<vtkCellArray> polys;
  vtkIdType n;
  const vtkIdType* ids;
  for (vtkIdType c = 0; c < t->GetNumberOfCells(); ++c)
  {
    t->GetCellPoints(c, n, ids);
    if (n != 3)
    {
      continue;
    }
    const vtkIdType corners[3] = { points->InsertNextPoint(t->GetPoint(ids[0])),
      points->InsertNextPoint(t->GetPoint(ids[1])), points->InsertNextPoint(t->GetPoint(ids[2])) };
    for (int k = 0; k < 3; ++k)
    {
      colours->InsertNextTuple(tc->GetTuple(c));
    }
    polys->InsertNextCell(3, corners);
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  out->SetPolys(polys);
  out->GetPointData()->SetScalars(colours);
  return out;
}

std::vector<std::array<float, 3>> PointColours(vtkPolyData* pd)
{
  std::vector<std::array<float, 3>> colours;
  vtkDataArray* sc = pd->GetPointData()->GetScalars();
  if (!IsColours(sc, pd->GetNumberOfPoints()))
  {
    return colours;
  }
  // 8-bit colours are 0..255 and 16-bit ones (LAS point clouds through PDAL) 0..65535; floating
  // colours are 0..1, or 0..255 when any exceeds 1 (they were drawn white).
  double hi = 0;
  for (int k = 0; k < 3; ++k)
  {
    hi = std::max(hi, sc->GetRange(k)[1]);
  }
  const int type = sc->GetDataType();
  const double scale = type == VTK_UNSIGNED_CHAR ? 1.0 / 255.0
    : type == VTK_UNSIGNED_SHORT                 ? 1.0 / 65535.0
    : hi > 1                                     ? 1.0 / 255.0
                                                 : 1.0;
  colours.resize(static_cast<std::size_t>(sc->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < sc->GetNumberOfTuples(); ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      const double v = sc->GetComponent(i, k) * scale;
      colours[i][k] = std::isfinite(v) ? static_cast<float>(std::clamp(v, 0.0, 1.0)) : 0.f; // NaN: black
    }
  }
  return colours;
}
} // namespace art
