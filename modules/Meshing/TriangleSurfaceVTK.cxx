#include "TriangleSurfaceVTK.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

namespace art
{
TriangleSurface TriangleSurfaceFromVTK(vtkPolyData* poly)
{
  vtkNew<vtkTriangleFilter> tri;
  tri->SetInputData(poly);
  tri->PassVertsOff();
  tri->PassLinesOff();
  tri->Update();
  vtkPolyData* t = tri->GetOutput();
  TriangleSurface s;
  s.Points.resize(3 * static_cast<size_t>(t->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < t->GetNumberOfPoints(); ++i)
  {
    t->GetPoint(i, &s.Points[3 * i]);
  }
  vtkCellArray* polys = t->GetPolys();
  vtkIdType n;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    if (n == 3)
    {
      s.Triangles.push_back({ static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
    }
  }
  return s;
}
} // namespace art
