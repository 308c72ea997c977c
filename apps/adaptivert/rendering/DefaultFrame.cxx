#include "rendering/DefaultFrame.h"

#include "TetMesh.h"
#include "TetRayCaster.h"
#include "TransferFunction.h"
#include "VisibleBounds.h"

#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <cmath>

namespace cli
{
vtkSmartPointer<vtkDataArray> SourceVisibleBounds(vtkImageData* image)
{
  vtkDataArray* a = image->GetPointData()->GetScalars();
  if (!a)
  {
    return nullptr;
  }
  double r[2];
  a->GetRange(r, 0);
  art::RenderSettings s;
  s.tf = art::TransferFunction::PresetFor("auto", image, r[0], r[1]);
  const art::Box3 box = art::VisibleBounds(image, s);
  if (box.Empty())
  {
    return nullptr;
  }
  auto b = vtkSmartPointer<vtkDoubleArray>::New();
  b->SetName("source_visible_bounds");
  b->SetNumberOfComponents(6);
  const double v[6] = { box.lo.x, box.hi.x, box.lo.y, box.hi.y, box.lo.z, box.hi.z };
  b->InsertNextTuple(v);
  return b;
}

art::Box3 ObjectBounds(vtkImageData* image, vtkUnstructuredGrid* grid, const art::TetMesh* mesh,
  const art::RenderSettings& s, const std::string& tf)
{
  if (image)
  {
    return art::VisibleBounds(image, s);
  }
  vtkDataArray* b = grid && grid->GetFieldData() ? grid->GetFieldData()->GetArray("source_visible_bounds") : nullptr;
  if (b && b->GetNumberOfComponents() == 6 && b->GetNumberOfTuples() == 1 && tf == "auto" && s.isos.empty() &&
    s.mode != art::RenderSettings::Mode::MaxIntensity)
  {
    double v[6];
    b->GetTuple(0, v);
    bool finite = true;
    for (double x : v)
    {
      finite = finite && std::isfinite(x);
    }
    if (finite && v[0] <= v[1] && v[2] <= v[3] && v[4] <= v[5])
    {
      return art::Box3({ v[0], v[2], v[4] }, { v[1], v[3], v[5] });
    }
  }
  return mesh ? art::VisibleBounds(*mesh, s) : art::Box3{};
}
} // namespace cli
