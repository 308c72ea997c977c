// vtkAdaptiveTetReducer's region path (SetRegion, SetLabels): the region reducer with the
// image-domain mesher the object factory gives (CGAL's Mesh_3 when AdaptiveRT::Meshing is loaded).
#include "vtkAdaptiveTetReducer.h"

#include "Error.h"
#include "FullResolutionMesh.h"
#include "Progress.h"
#include "RegionReducer.h"
#include "ReducerVTK.h"
#include "RegionVTK.h"
#include "WholeBoxComparison.h"
#include "vtkImageDomainMesher.h"

#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>

void vtkAdaptiveTetReducer::SetRegion(double lo, double hi)
{
  if (!this->UseRegion || this->Region[0] != lo || this->Region[1] != hi)
  {
    this->Region[0] = lo;
    this->Region[1] = hi;
    this->UseRegion = true;
    this->Modified();
  }
}

void vtkAdaptiveTetReducer::SetRegionRange(double lo, double hi)
{
  if (this->Region[0] != lo || this->Region[1] != hi)
  {
    this->Region[0] = lo;
    this->Region[1] = hi;
    this->Modified();
  }
}

void vtkAdaptiveTetReducer::SetUseRegion(bool use)
{
  if (this->UseRegion != use)
  {
    this->UseRegion = use;
    this->Modified();
  }
}

void vtkAdaptiveTetReducer::RemoveRegion()
{
  if (this->UseRegion)
  {
    this->UseRegion = false;
    this->Modified();
  }
}

void vtkAdaptiveTetReducer::RequestRegion(vtkImageData* input, const art::VoxelVolume& volume, vtkImageData* values,
  bool asDouble, vtkUnstructuredGrid* output, vtkMultiBlockDataSet* levels, art::Progress& progress)
{
  if (this->UseRegion && this->Labels)
  {
    throw art::Error("SetRegion and SetLabels exclude each other: a label map is meshed by its labels");
  }
  if (values && !this->Labels)
  {
    throw art::Error("the values input (port 1, SetValuesData) goes with SetLabels: a region's values are the input's own");
  }
  if (this->TargetError >= 0 && this->ErrorMetric == MAX)
  {
    throw art::Error("a region is reduced to an RMS error bound (ErrorMetric RMS), not a maximum");
  }
  if (!this->Levels.empty())
  {
    vtkWarningMacro("Levels do not apply to a region (each meshing is made anew): only the final grid is made.");
  }
  art::RegionOptions ro;
  ro.Labels = this->Labels;
  ro.Lo = this->Region[0];
  ro.Hi = this->Region[1];
  ro.Background = this->Background;
  ro.MinIslandVoxels = this->MinimumIslandVoxels;
  ro.TargetTets = this->TargetTets;
  ro.TargetError = this->TargetError < 0 ? -1.0
                                         : this->TargetError * (this->ErrorRelative ? volume.Range[1] - volume.Range[0] : 1.0);
  ro.SolverTolerance = this->SolverTolerance;
  art::VoxelVolume fitted;
  if (values)
  {
    vtkDataArray* a = values->GetPointData()->GetScalars();
    if (!a || a->GetNumberOfComponents() != 1)
    {
      throw art::Error("the values input (port 1) needs one-component point scalars");
    }
    fitted = art::VolumeFromImage(values);
    ro.Values = &fitted;
  }
  vtkSmartPointer<vtkImageDomainMesher> mesher = vtkSmartPointer<vtkImageDomainMesher>::New();
  const art::RegionResult r = art::ReduceRegion(
    volume, ro, [&mesher](const art::ImageDomainRequest& q) { return mesher->Mesh(q); }, &progress);
  art::WholeBoxFigures box;
  if (this->CompareWholeBox && !this->Labels)
  {
    const long long cap = std::min<long long>(art::FullResolutionTetCount(volume), 64 * r.Mesh.NumberOfTets());
    box = art::WholeBoxForRegionError(volume, r.Mask.Inside, r.Mesh.Rms, r.Mesh.NumberOfTets(), cap, &progress);
  }
  vtkSmartPointer<vtkUnstructuredGrid> grid =
    art::RegionToUnstructuredGrid(r, ro, values ? fitted.DoubleValues : asDouble, this->CompareWholeBox && !this->Labels ? &box : nullptr);
  vtkFieldData* in = input->GetFieldData();
  for (int a = 0; in && a < in->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = in->GetAbstractArray(a);
    if (array && array->GetName() && !grid->GetFieldData()->HasArray(array->GetName()))
    {
      grid->GetFieldData()->AddArray(array);
    }
  }
  output->ShallowCopy(grid);
  levels->SetNumberOfBlocks(1);
  levels->SetBlock(0, grid);
  levels->GetMetaData(0u)->Set(vtkCompositeDataSet::NAME(), ("tets_" + std::to_string(r.Mesh.NumberOfTets())).c_str());
  this->RMSError = r.Mesh.Rms;
  this->MaxError = r.Mesh.Max;
  this->WeightedRMSError = r.Mesh.Rms;
  this->WeightedMaxError = r.Mesh.Max;
  this->BuildSeconds = r.Mesh.BuildSeconds;
  this->RegionVoxels = r.Mask.Voxels;
  this->IslandsDropped = r.Mask.IslandsDropped;
  this->WholeBoxTets = box.Tets;
}
