#include "vtkSurfaceTetrahedralizer.h"

#include "Error.h"
#include "Progress.h"
#include "ReducerVTK.h"
#include "SurfaceTetrahedralizer.h"
#include "TriangleSurfaceVTK.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <memory>

vtkStandardNewMacro(vtkSurfaceTetrahedralizer);

namespace
{
void AddField(vtkUnstructuredGrid* g, const char* name, double v)
{
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfTuples(1);
  a->SetValue(0, v);
  g->GetFieldData()->AddArray(a);
}
} // namespace

vtkSurfaceTetrahedralizer::vtkSurfaceTetrahedralizer()
{
  this->SetNumberOfInputPorts(2);
  this->SetInputArrayToProcess(0, 1, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

int vtkSurfaceTetrahedralizer::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkPolyData" : "vtkImageData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkSurfaceTetrahedralizer::RequestData(vtkInformation*, vtkInformationVector** in, vtkInformationVector* out)
{
  vtkPolyData* poly = vtkPolyData::GetData(in[0]);
  vtkImageData* image = in[1]->GetNumberOfInformationObjects() > 0 ? vtkImageData::GetData(in[1]) : nullptr;
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(out);
  this->SurfaceVolume = this->MeshVolume = this->RMSError = std::nan("");
  if (!poly)
  {
    vtkErrorMacro("No input surface.");
    return 0;
  }
  art::Progress progress([this, &progress](double f, const std::string&) {
    this->UpdateProgress(f);
    if (this->GetAbortExecute())
    {
      progress.Cancel();
    }
  });
  try
  {
    art::SurfaceMeshOptions o;
    o.TargetTets = this->TargetTets;
    o.MaxVolume = this->MaxVolume;
    o.TetGen.RadiusEdge = this->RadiusEdgeRatio;
    o.TetGen.MinDihedral = this->MinDihedral;
    std::unique_ptr<art::VoxelVolume> volume;
    if (image)
    {
      vtkNew<vtkImageData> selected;
      selected->ShallowCopy(image);
      if (vtkDataArray* a = this->GetInputArrayToProcess(0, in))
      {
        selected->GetPointData()->SetScalars(a);
      }
      volume = std::make_unique<art::VoxelVolume>(art::VolumeFromImage(selected));
      o.Volume = volume.get();
    }
    if (o.TargetTets <= 0 && o.MaxVolume <= 0 && !o.Volume)
    {
      vtkErrorMacro("Set TargetTets or MaxVolume.");
      return 0;
    }
    const art::SurfaceMeshResult r = art::TetrahedralizeSurface(art::TriangleSurfaceFromVTK(poly), o, "", &progress);
    output->ShallowCopy(art::ToUnstructuredGrid(r.Mesh, volume && volume->DoubleValues));
    this->SurfaceVolume = r.Surface.Volume;
    this->MeshVolume = r.MeshVolume;
    this->RMSError = volume ? r.Mesh.Rms : std::nan("");
    AddField(output, "surface_volume", r.Surface.Volume);
    AddField(output, "mesh_volume", r.MeshVolume);
    AddField(output, "tetgen_runs", static_cast<double>(r.Rounds.size()));
    if (volume)
    {
      AddField(output, "covered_voxels", static_cast<double>(r.CoveredVoxels));
    }
  }
  catch (const art::Error& e)
  {
    if (progress.Cancelled())
    {
      output->Initialize();
      return 1;
    }
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

void vtkSurfaceTetrahedralizer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetTets: " << this->TargetTets << "\n";
  os << indent << "MaxVolume: " << this->MaxVolume << "\n";
  os << indent << "RadiusEdgeRatio: " << this->RadiusEdgeRatio << "\n";
  os << indent << "MinDihedral: " << this->MinDihedral << "\n";
  os << indent << "SurfaceVolume: " << this->SurfaceVolume << "\n";
  os << indent << "MeshVolume: " << this->MeshVolume << "\n";
}
