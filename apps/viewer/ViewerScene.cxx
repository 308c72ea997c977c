#include "ViewerScene.h"

#include "TetRayCaster.h"
#include "VisibleBounds.h"

#include "DataLoader.h"
#include "Error.h"
#include "TetMesh.h"
#include "rendering/LabelColours.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#ifndef ART_HAVE_Reduction
#include <vtkDataSetTriangleFilter.h>
#include <vtkNew.h>
#endif

#include <cstdio>
#include <optional>

namespace view
{
std::string Grouped(long long n)
{
  std::string s = std::to_string(n), o;
  for (std::size_t i = 0; i < s.size(); ++i)
  {
    o += s[i];
    if ((s.size() - 1 - i) % 3 == 0 && i + 1 < s.size() && s[i] != '-')
    {
      o += ',';
    }
  }
  return o;
}

void ViewerScene::AddLevel(vtkSmartPointer<vtkUnstructuredGrid> grid, long long tets, double rms)
{
  char buf[160];
  if (rms >= 0)
  {
    std::snprintf(buf, sizeof buf, "%s tets, RMS error %.3g", Grouped(tets).c_str(), rms);
  }
  else
  {
    std::snprintf(buf, sizeof buf, "%s tets", Grouped(tets).c_str());
  }
  Levels.push_back(std::move(grid));
  LevelLabels.push_back(buf);
}

ViewerScene LoadScene(
  const std::string& file, const std::string& tf, const art::LoadOptions& load, const std::string& labelColours)
{
  ViewerScene s;
  const std::string& array = load.Array;
  std::optional<art::TetMesh> mesh; // a mesh's used, merged points, for a preset's unit distance
  bool labels = false;              // a label mesh (cell array "label"), split per label
  std::optional<art::LabelMesh> labelMesh;
  vtkSmartPointer<vtkUnstructuredGrid> source; // a label mesh as read, before the split
  const art::DataKind kind = art::KindOf(file, load);
  vtkSmartPointer<vtkDataObject> data =
    kind == art::DataKind::Volume ? vtkSmartPointer<vtkDataObject>(art::LoadVolume(file, load)) : art::Load(file);
  if (kind == art::DataKind::Surface)
  {
    auto* pd = vtkPolyData::SafeDownCast(data);
    s.Surface = std::make_unique<SurfaceTraceView>(pd, file);
    s.Bounds = s.Object = s.Surface->Bounds();
    s.Note = s.Surface->Description();
    return s;
  }
  if (kind == art::DataKind::Volume)
  {
    s.Image = vtkImageData::SafeDownCast(data);
    art::RequireOneComponent(s.Image, file);
    // A vector's magnitude or component comes as scalars named "NAME:magnitude" or "NAME:N",
    // which the levels' grids keep.
    s.ArrayName = array.empty() ? "" : s.Image->GetPointData()->GetScalars()->GetName();
    s.Image->GetPointData()->GetScalars()->GetRange(s.Range);
    double b[6];
    s.Image->GetBounds(b);
    s.Bounds = art::Box3::FromBounds(b);
#ifndef ART_HAVE_Reduction
    // Without the Reduction module the only tets are the full-resolution ones.
    vtkNew<vtkDataSetTriangleFilter> tri;
    tri->SetInputData(s.Image);
    tri->Update();
    vtkSmartPointer<vtkUnstructuredGrid> full = tri->GetOutput();
    s.AddLevel(full, full->GetNumberOfCells(), -1);
#endif
  }
  else
  {
    vtkSmartPointer<vtkUnstructuredGrid> grid = vtkUnstructuredGrid::SafeDownCast(data);
    std::string note;
    s.ArrayName = art::AddComponentArray(grid, array, file); // NAME:magnitude, NAME:N
    // Each tet in its label's colour, and the values inside each label, as render draws them.
    cli::LabelColouring mode = cli::LabelColouring::Values;
    cli::ParseLabelColouring(labelColours, mode); // ParseOptions checked the word
    labelMesh = cli::LabelMeshFor(grid, s.ArrayName, mode);
    if (labelMesh)
    {
      source = grid;
      grid = labelMesh->Grid();
      s.ArrayName = labelMesh->HasValues() ? "label_values" : "label";
      labels = true;
    }
    s.ArrayOnCells = !s.ArrayName.empty() && !grid->GetPointData()->GetArray(s.ArrayName.c_str()) &&
      grid->GetCellData()->GetArray(s.ArrayName.c_str());
    mesh.emplace(art::TetMesh::FromVTK(grid, s.ArrayName, &note, file)); // checks scalars and cells
    s.Range[0] = mesh->ScalarRange(0);
    s.Range[1] = mesh->ScalarRange(1);
    s.Bounds = mesh->Bounds();
    s.AddLevel(grid, static_cast<long long>(mesh->NumberOfTets()), -1);
    s.Note = note;
  }
  // A preset's unit distance follows the data (1 mm on CT in HU of mm voxels, else its sample spacing), as in render.
  s.Transfer = labelMesh && labelMesh->HasValues() ? cli::LabelValuesFunction(*labelMesh, source, tf)
    : tf.find_first_of("./") != std::string::npos
    ? art::TransferFunction::FromFile(tf)
    : art::TransferFunction::PresetFor(labels && tf == "auto" ? "labels" : tf, vtkDataSet::SafeDownCast(data),
        s.Range[0], s.Range[1], mesh ? &*mesh : nullptr);
  art::RenderSettings shown;
  shown.tf = s.Transfer;
  s.Object = s.Image ? art::VisibleBounds(s.Image, shown) : art::VisibleBounds(*mesh, shown);
  return s;
}
} // namespace view
