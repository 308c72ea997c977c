#include "CellVoxels.h"

#include <vtkCellData.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <algorithm>

namespace art
{
vtkSmartPointer<vtkImageData> CellVoxels(vtkImageData* img, vtkCellData* cells)
{
  int e[6];
  img->GetExtent(e);
  int n[3];
  double centre[3];
  for (int a = 0; a < 3; ++a)
  {
    const int points = e[2 * a + 1] - e[2 * a] + 1;
    n[a] = std::max(points - 1, 1); // a flat axis keeps its one layer of cells
    centre[a] = e[2 * a] + (points > 1 ? 0.5 : 0.0);
  }
  double o[3];
  img->TransformContinuousIndexToPhysicalPoint(centre, o);
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetDimensions(n);
  out->SetSpacing(img->GetSpacing());
  out->SetOrigin(o);
  out->SetDirectionMatrix(img->GetDirectionMatrix());
  out->GetPointData()->PassData(cells);
  return out;
}
} // namespace art
