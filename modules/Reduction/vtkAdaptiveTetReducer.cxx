#include "vtkAdaptiveTetReducer.h"
#include "ArrayChoice.h"
#include "CellVoxels.h"

#include "Error.h"
#include "PieceReduction.h"
#include "Progress.h"
#include "ReducerVTK.h"
#include "TetReducer.h"

#include <algorithm>

#include <vtkAbstractArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkDataSetAttributes.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkPiecewiseFunction.h>
#include <vtkPointData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnstructuredGrid.h>

#include <limits>

vtkStandardNewMacro(vtkAdaptiveTetReducer);

vtkAdaptiveTetReducer::vtkAdaptiveTetReducer()
{
  this->SetNumberOfInputPorts(2); // 1: the values a label map's mesh carries (SetValuesData)
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

vtkAdaptiveTetReducer::~vtkAdaptiveTetReducer()
{
  this->SetScalarOpacity(nullptr);
  this->SetController(nullptr);
}

vtkCxxSetObjectMacro(vtkAdaptiveTetReducer, ScalarOpacity, vtkPiecewiseFunction);
vtkCxxSetObjectMacro(vtkAdaptiveTetReducer, Controller, vtkMultiProcessController);

namespace
{
// The piece asked of the output port the request came from.
struct Piece
{
  int Index = 0, Count = 1;
};

Piece RequestedPiece(vtkInformation* request, vtkInformationVector* outputVector)
{
  const int port = request && request->Has(vtkExecutive::FROM_OUTPUT_PORT()) ? request->Get(vtkExecutive::FROM_OUTPUT_PORT()) : 0;
  vtkInformation* out = outputVector->GetInformationObject(port >= 0 && port < 2 ? port : 0);
  Piece p;
  if (out->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()))
  {
    p.Index = out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  }
  if (out->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()))
  {
    p.Count = std::max(1, out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
  }
  return p;
}

// This process's part (`image`, already cropped by art::OwnPart), reduced with every other
// process's part (art::PieceReduction). A part thinner than two voxels along an axis holds none;
// a null image (its arrays could not be chosen) is `failure`.
std::vector<art::ReducedMesh> ReduceOwnPiece(vtkImageData* image, std::string failure, bool holdsVoxels,
  vtkMultiProcessController* controller, const art::ReducerOptions& opt, art::Progress* pilot, art::Progress* progress,
  art::PieceFigures& figures, art::VoxelVolume& volume)
{
  try
  {
    if (!image)
    {
      throw art::Error(failure);
    }
    vtkDataArray* s = image->GetPointData()->GetScalars();
    volume.Name = s && s->GetName() ? s->GetName() : "scalars";
    volume.DoubleValues = s && art::ReducedAsDouble(s->GetDataType());
    if (holdsVoxels)
    {
      volume = art::VolumeFromImage(image);
    }
  }
  catch (const std::exception& e)
  {
    failure = e.what();
  }
  return art::PieceReduction(controller).Run(opt, failure.empty() ? &volume : nullptr, failure, pilot, progress, figures);
}

// The final mesh's figures are the whole volume's (its tets and vertices stay this piece's).
void SetWholeFigures(art::ReducedMesh& m, const art::PieceFigures& f)
{
  m.Rms = f.Rms;
  m.Max = f.Max;
  m.WeightedRms = f.WeightedRms;
  m.WeightedMax = f.WeightedMax;
  m.Range[0] = f.Range[0];
  m.Range[1] = f.Range[1];
  m.TargetTets = f.Budget;
  m.TargetError = f.Bound;
  m.TargetReached = f.Reached;
}

void AddPieceFields(vtkDataObject* out, int pieces, const art::PieceFigures& f)
{
  auto field = [out](const char* name, double v) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfTuples(1);
    a->SetValue(0, v);
    out->GetFieldData()->AddArray(a);
  };
  field("pieces", pieces);
  field("total_tets", static_cast<double>(f.Tets));
  field("piece_target_tets", static_cast<double>(f.TargetTets));
  field("piece_target_error", f.TargetError);
  field("piece_pilot_seconds", f.PilotSeconds);
  for (const auto& [name, e] : { std::make_pair("piece_extent", f.Extent), std::make_pair("input_extent", f.InputExtent) })
  {
    vtkNew<vtkIntArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(6);
    a->SetNumberOfTuples(1);
    for (int k = 0; k < 6; ++k)
    {
      a->SetComponent(0, k, e[k]);
    }
    out->GetFieldData()->AddArray(a);
  }
}
} // namespace

vtkMTimeType vtkAdaptiveTetReducer::GetMTime()
{
  const vtkMTimeType t = this->Superclass::GetMTime();
  return this->ScalarOpacity ? std::max(t, this->ScalarOpacity->GetMTime()) : t;
}

void vtkAdaptiveTetReducer::AddLevel(vtkIdType tets)
{
  this->Levels.push_back(tets);
  this->Modified();
}

void vtkAdaptiveTetReducer::RemoveAllLevels()
{
  if (!this->Levels.empty())
  {
    this->Levels.clear();
    this->Modified();
  }
}

void vtkAdaptiveTetReducer::AddIsoValue(double value)
{
  this->IsoValues.push_back(value);
  this->Modified();
}

void vtkAdaptiveTetReducer::RemoveAllIsoValues()
{
  if (!this->IsoValues.empty())
  {
    this->IsoValues.clear();
    this->Modified();
  }
}

double vtkAdaptiveTetReducer::GetIsoValue(int i) const
{
  return i >= 0 && i < static_cast<int>(this->IsoValues.size()) ? this->IsoValues[i] : 0.0;
}

vtkIdType vtkAdaptiveTetReducer::GetLevel(int i) const
{
  return i >= 0 && i < static_cast<int>(this->Levels.size()) ? this->Levels[i] : 0;
}

int vtkAdaptiveTetReducer::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

void vtkAdaptiveTetReducer::SetValuesConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkAdaptiveTetReducer::SetValuesData(vtkDataObject* values)
{
  this->SetInputData(1, values);
}

vtkDataObject* vtkAdaptiveTetReducer::GetValuesData()
{
  return this->GetNumberOfInputConnections(1) > 0 ? this->GetInputDataObject(1, 0) : nullptr;
}

int vtkAdaptiveTetReducer::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 0 ? "vtkUnstructuredGrid" : "vtkMultiBlockDataSet");
  return 1;
}

int vtkAdaptiveTetReducer::RequestUpdateExtent(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* in = inputVector[0]->GetInformationObject(0);
  const Piece piece = RequestedPiece(request, outputVector);
  if (art::OnePiecePerProcess(this->Controller, piece.Index, piece.Count) &&
    in->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    // One piece per process: asked as VTK's image pipelines ask, the whole extent as piece p of n.
    // A source that can read a part (VTK's XML readers, .vti and .pvti; image sources) then reads
    // this process's block of the extent, art::PieceExtent's; one that cannot gives piece 0 all of
    // it and the others nothing (asked for a part directly, vtkMetaImageReader wrote a compressed
    // .mha's whole volume past its buffer), and RequestData has piece 0 hand out the parts.
    in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), in->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
    in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), piece.Index);
    in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), piece.Count);
    in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    return 1;
  }
  // The values a label map's mesh carries: all of them, as one piece.
  if (vtkInformation* values = inputVector[1]->GetInformationObject(0))
  {
    if (values->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
    {
      values->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
        values->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
    }
    values->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    values->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    values->Set(vtkStreamingDemandDrivenPipeline::EXACT_EXTENT(), 1);
  }
  // Otherwise the fit needs every voxel: ask for the whole extent, as one piece. The piece request
  // copied from the output (a parallel writer) made an image source split its extent: each piece
  // was a reduction of one slab, with the whole budget.
  if (in->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
      in->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  }
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
  in->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  in->Set(vtkStreamingDemandDrivenPipeline::EXACT_EXTENT(), 1);
  return 1;
}

int vtkAdaptiveTetReducer::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkUnstructuredGrid* output = vtkUnstructuredGrid::GetData(outputVector, 0);
  vtkMultiBlockDataSet* levels = vtkMultiBlockDataSet::GetData(outputVector, 1);
  // A run that fails or is aborted leaves no figures of an earlier one behind.
  this->RMSError = this->MaxError = this->BuildSeconds = std::numeric_limits<double>::quiet_NaN();
  this->WeightedRMSError = this->WeightedMaxError = std::numeric_limits<double>::quiet_NaN();
  // One piece per process: each reduces its part. Otherwise one mesh for the whole volume: piece
  // 0 of a piece request holds it, the other pieces are empty (they held a copy each, or a
  // reduction of their slab), so the pieces add up to it.
  const Piece piece = RequestedPiece(request, outputVector);
  const bool distributed = art::OnePiecePerProcess(this->Controller, piece.Index, piece.Count);
  const bool emptyPiece = !distributed && piece.Index > 0;
  if (this->TargetTets <= 0 && this->TargetError < 0)
  {
    vtkErrorMacro("Set TargetTets or TargetError.");
    return 0;
  }
  // This process's part of the volume (read as a part, or handed out by piece 0).
  art::PieceFigures whole;
  bool holdsVoxels = true;
  vtkSmartPointer<vtkImageData> own;
  if (distributed)
  {
    const int* wholeExtent = inputVector[0]->GetInformationObject(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
    std::string failure;
    own = art::OwnPart(this->Controller, input, wholeExtent, piece.Index, piece.Count, whole.InputExtent, failure);
    if (!own)
    {
      vtkErrorMacro(<< failure); // on every process alike
      return 0;
    }
    art::PieceExtent(wholeExtent, piece.Index, piece.Count, whole.Extent);
    holdsVoxels = art::HoldsVoxels(wholeExtent, whole.Extent);
    input = own;
  }
  art::ReducerOptions opt;
  if (!this->MakeOptions(opt))
  {
    return 0;
  }
  // Progress is reported from the driver loop (this thread), never from worker threads. An
  // observer's SetAbortExecute(1) cancels the reduction at the next level, as VTK's filters stop.
  // With relocation the reduction reports its stages in turn (each 0 -> 1): the first half is
  // the refinement, the second the relocation; VTK's progress only rises.
  // A piece's pilot run (art::PieceReduction) takes the first tenth.
  double shown = 0.0;
  const double pilotPart = distributed && opt.TargetTets > 0 ? 0.1 : 0.0;
  auto report = [this, &shown](double g, art::Progress& p) {
    shown = std::max(shown, g);
    this->UpdateProgress(shown);
    if (this->GetAbortExecute())
    {
      p.Cancel();
    }
  };
  art::Progress pilot([&report, &pilot, pilotPart](double f, const std::string&) { report(pilotPart * f, pilot); });
  art::Progress progress([&report, &progress, &opt, pilotPart](double f, const std::string& stage) {
    // With relocation: reduce (to 95%) in [0, 0.475], relocate in [0.5, 0.95], the refit after it.
    const double g = !opt.RelocateVertices ? f
      : stage == "relocate"               ? 0.5 + 0.45 * f
      : stage == "refit"                  ? 0.95 + 0.05 * f
                                          : 0.5 * f;
    report(pilotPart + (1.0 - pilotPart) * g, progress);
  });
  try
  {
    bool onCells = false;
    std::string failure;
    vtkSmartPointer<vtkImageData> image = this->SelectVoxels(input, onCells, failure);
    if (!image && !distributed)
    {
      vtkErrorMacro(<< failure);
      return 0;
    }
    art::VoxelVolume volume;
    std::vector<art::ReducedMesh> meshes;
    if (distributed)
    {
      if (onCells)
      {
        vtkWarningMacro("Cell values reduced in parallel: each piece's mesh spans its own cells' centres, a cell's "
                        "width short of the next piece's.");
      }
      // Every process takes part, one without voxels to reduce too: the failure is said by all.
      meshes = ReduceOwnPiece(image, failure, holdsVoxels, this->Controller, opt, &pilot, &progress, whole, volume);
    }
    else
    {
      volume = art::VolumeFromImage(image);
    }
    // Double for the types VolumeFromImage reads as double (int32 and 64-bit too), as reduce writes
    // them: int32 values past 2^24 were rounded in a float array the figures knew nothing of.
    const bool asDouble = volume.DoubleValues;
    if (emptyPiece || (distributed && meshes.empty()))
    {
      // No tets, but the points and arrays of piece 0 (a parallel writer's summary is made from
      // the last piece it wrote: it found no points there).
      art::ReducedMesh none;
      none.ScalarName = volume.Name;
      output->ShallowCopy(art::ToUnstructuredGrid(none, asDouble));
      output->GetFieldData()->Initialize();
      levels->Initialize();
      return 1;
    }
    if (this->UseRegion || this->Labels)
    {
      this->RequestRegion(input, volume, vtkImageData::GetData(inputVector[1]), asDouble, output, levels, progress);
      return 1;
    }
    if (!distributed)
    {
      meshes = art::TetReducer(opt).Run(volume, &progress);
    }
    if (meshes.empty())
    {
      vtkErrorMacro("The reduction produced no mesh.");
      return 0;
    }
    if (distributed)
    {
      SetWholeFigures(meshes.back(), whole);
    }
    this->WriteMeshes(meshes, opt.Levels, input, asDouble, output, levels);
    if (distributed)
    {
      AddPieceFields(output, piece.Count, whole);
    }
  }
  catch (const art::Error& e)
  {
    if (progress.Cancelled() || pilot.Cancelled())
    {
      // Aborted: empty outputs, no error (a previous run's mesh must not pass for this one's).
      output->Initialize();
      levels->Initialize();
      return 1;
    }
    vtkErrorMacro(<< e.what());
    return 0;
  }
  return 1;
}

bool vtkAdaptiveTetReducer::MakeOptions(art::ReducerOptions& opt)
{
  opt.TargetTets = this->TargetTets;
  opt.TargetError = this->TargetError;
  opt.ErrorMetric = this->ErrorMetric == MAX ? art::ReducerOptions::Metric::Max : art::ReducerOptions::Metric::RMS;
  opt.ErrorRelative = this->ErrorRelative;
  opt.RefineFraction = this->RefineFraction;
  opt.ClampToVoxels = this->ClampToVoxels;
  opt.CapOpacity = this->CapOpacity;
  opt.RelocateVertices = this->RelocateVertices;
  opt.SolverTolerance = this->SolverTolerance;
  opt.Refine = this->Refinement == EDGE_SPLIT ? art::ReducerOptions::Refinement::EdgeSplit
    : this->Refinement == ANISOTROPIC          ? art::ReducerOptions::Refinement::Anisotropic
                                               : art::ReducerOptions::Refinement::Bisection;
  opt.ImportanceFloor = this->ImportanceFloor;
  opt.ImportanceRadius = this->ImportanceRadius;
  if (this->ScalarOpacity)
  {
    double node[4];
    for (int i = 0; i < this->ScalarOpacity->GetSize(); ++i)
    {
      this->ScalarOpacity->GetNodeValue(i, node);
      opt.ScalarOpacity.emplace_back(node[0], node[1]);
    }
    if (opt.ScalarOpacity.empty())
    {
      vtkErrorMacro("The scalar-opacity function has no nodes.");
      return false;
    }
    opt.IsoValues = this->IsoValues;
  }
  for (vtkIdType l : this->Levels)
  {
    if (l > 0 && (this->TargetTets <= 0 || l < this->TargetTets))
    {
      opt.Levels.push_back(l);
    }
    else if (l > 0)
    {
      // Port 1 would hold fewer blocks than levels added, without a word; reduce refuses it too.
      vtkWarningMacro("Level " << l << " is not below TargetTets " << this->TargetTets
                                << ": the final grid is that level; it is left out of the levels.");
    }
  }
  return true;
}

void vtkAdaptiveTetReducer::WriteMeshes(const std::vector<art::ReducedMesh>& meshes,
  const std::vector<long long>& levels, vtkImageData* input, bool asDouble, vtkUnstructuredGrid* output,
  vtkMultiBlockDataSet* blocks)
{
  const art::ReducedMesh& last = meshes.back();
  output->ShallowCopy(art::ToUnstructuredGrid(last, asDouble));
  this->RMSError = last.Rms;
  this->MaxError = last.Max;
  this->BuildSeconds = last.BuildSeconds;
  this->WeightedRMSError = last.WeightedRms;
  this->WeightedMaxError = last.WeightedMax;
  // The input's field data passes through, as VTK's dataset filters pass it, beside the
  // reduction's own figures (which win a clash of names).
  auto passFieldData = [input](vtkDataObject* out) {
    vtkFieldData* in = input->GetFieldData();
    for (int a = 0; in && a < in->GetNumberOfArrays(); ++a)
    {
      vtkAbstractArray* array = in->GetAbstractArray(a);
      if (array && array->GetName() && !out->GetFieldData()->HasArray(array->GetName()))
      {
        out->GetFieldData()->AddArray(array);
      }
    }
  };
  passFieldData(output);
  blocks->SetNumberOfBlocks(static_cast<unsigned int>(meshes.size()));
  for (unsigned int i = 0; i < meshes.size(); ++i)
  {
    vtkSmartPointer<vtkUnstructuredGrid> block = art::ToUnstructuredGrid(meshes[i], asDouble);
    passFieldData(block);
    blocks->SetBlock(i, block);
    blocks->GetMetaData(i)->Set(vtkCompositeDataSet::NAME(),
      ("tets_" + std::to_string(meshes[i].NumberOfTets())).c_str());
  }
  // A level an error target stopped short of is not among the blocks: say so, as reduce does.
  for (long long l : art::UnreachedLevels(levels, meshes))
  {
    vtkWarningMacro("Level " << l << " was not reached: the reduction stopped at " << last.NumberOfTets()
                              << " tets.");
  }
}

vtkSmartPointer<vtkImageData> vtkAdaptiveTetReducer::SelectVoxels(vtkImageData* input, bool& onCells, std::string& error)
{
  // The array chosen with SetInputArrayToProcess (default: the point scalars).
  vtkSmartPointer<vtkImageData> image = input;
  vtkDataArray* chosen = this->GetInputArrayToProcess(0, input);
  vtkInformation* asked = this->GetInputArrayInformation(0);
  const bool askedCells = asked && asked->Has(vtkDataObject::FIELD_ASSOCIATION()) &&
    asked->Get(vtkDataObject::FIELD_ASSOCIATION()) == vtkDataObject::FIELD_ASSOCIATION_CELLS;
  // An empty name (ParaView's Python before the input's arrays are known) asks for nothing.
  if (!chosen && asked && asked->Has(vtkDataObject::FIELD_NAME()) && *asked->Get(vtkDataObject::FIELD_NAME()))
  {
    // A named array that is not there: say so (it used to reduce the active scalars instead),
    // naming the association asked for (a missing cell array was 'no point array').
    vtkDataSetAttributes* where = askedCells ? static_cast<vtkDataSetAttributes*>(input->GetCellData())
                                             : static_cast<vtkDataSetAttributes*>(input->GetPointData());
    const char* kind = askedCells ? "cell" : "point";
    std::string names;
    for (int i = 0; i < where->GetNumberOfArrays(); ++i)
    {
      const char* n = where->GetArrayName(i);
      names += std::string(i ? ", " : "") + (n ? n : "(unnamed)");
    }
    error = std::string("The input has no ") + kind + " array '" + asked->Get(vtkDataObject::FIELD_NAME()) + "' (" +
      kind + " arrays: " + (names.empty() ? "none" : names) + ").";
    return nullptr;
  }
  vtkCellData* cd = input->GetCellData();
  onCells = false;
  for (int i = 0; chosen && i < cd->GetNumberOfArrays(); ++i)
  {
    onCells = onCells || cd->GetAbstractArray(i) == chosen;
  }
  if (!chosen && !askedCells)
  {
    // No active point scalars: the first one-component point array, as `reduce` takes it (the
    // cell fallback below reduced a cell array such as cell ids before the point data).
    chosen = art::ChooseArray(input->GetPointData(), "");
  }
  if (!chosen)
  {
    // Values on the cells only (labels, finite-volume output): they are the voxels.
    chosen = art::ChooseArray(cd, "");
    onCells = chosen != nullptr;
  }
  if (onCells)
  {
    // A cell array is one voxel per cell, at the cell's centre (it did not match the points:
    // 'the scalar array does not match the image dimensions').
    vtkNew<vtkCellData> one;
    one->SetScalars(chosen);
    image = art::CellVoxels(input, one);
  }
  else if (chosen && chosen != input->GetPointData()->GetScalars())
  {
    image = vtkSmartPointer<vtkImageData>::New();
    image->ShallowCopy(input);
    image->GetPointData()->SetScalars(chosen);
  }
  if (vtkDataArray* v = image->GetPointData()->GetScalars(); v && v->GetNumberOfComponents() > 1)
  {
    if (this->VectorMode == DISABLED)
    {
      error = std::string("The array '") + (v->GetName() ? v->GetName() : "") + "' has " +
        std::to_string(v->GetNumberOfComponents()) +
        " components; the reducer needs one (SetVectorMode(vtkAdaptiveTetReducer::MAGNITUDE), or COMPONENT with "
        "SetVectorComponent; or choose another with SetInputArrayToProcess).";
      return nullptr;
    }
    // Its magnitude or one component, as the mappers draw a vector (VectorMode).
    auto reduced = vtkSmartPointer<vtkImageData>::New();
    reduced->ShallowCopy(image);
    reduced->GetPointData()->SetScalars(
      art::TakeComponent(v, this->VectorMode == MAGNITUDE ? art::Magnitude : this->VectorComponent));
    image = reduced;
  }  return image;
}

void vtkAdaptiveTetReducer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TargetTets: " << this->TargetTets << "\n";
  os << indent << "TargetError: " << this->TargetError << "\n";
  os << indent << "ErrorMetric: " << (this->ErrorMetric == MAX ? "MAX" : "RMS") << "\n";
  os << indent << "ErrorRelative: " << this->ErrorRelative << "\n";
  os << indent << "RefineFraction: " << this->RefineFraction << "\n";
  os << indent << "ClampToVoxels: " << this->ClampToVoxels << "\n";
  os << indent << "CapOpacity: " << this->CapOpacity << "\n";
  os << indent << "RelocateVertices: " << this->RelocateVertices << "\n";
  os << indent << "SolverTolerance: " << this->SolverTolerance << "\n";
  os << indent << "VectorMode: " << this->VectorMode << " (component " << this->VectorComponent << ")\n";
  os << indent << "Refinement: "
     << (this->Refinement == EDGE_SPLIT ? "EDGE_SPLIT" : this->Refinement == ANISOTROPIC ? "ANISOTROPIC" : "BISECTION")
     << "\n";
  os << indent << "Levels: " << this->Levels.size() << "\n";
  os << indent << "IsoValues: " << this->IsoValues.size() << "\n";
  os << indent << "RMSError: " << this->RMSError << "\n";
  os << indent << "MaxError: " << this->MaxError << "\n";
  os << indent << "ScalarOpacity: " << this->ScalarOpacity << "\n";
  os << indent << "ImportanceFloor: " << this->ImportanceFloor << "\n";
  os << indent << "ImportanceRadius: " << this->ImportanceRadius << "\n";
  os << indent << "WeightedRMSError: " << this->WeightedRMSError << "\n";
  os << indent << "WeightedMaxError: " << this->WeightedMaxError << "\n";
  os << indent << "Region: " << (this->UseRegion ? "" : "off, ") << this->Region[0] << " .. " << this->Region[1] << "\n";
  os << indent << "Labels: " << this->Labels << " (background " << this->Background << ")\n";
  os << indent << "MinimumIslandVoxels: " << this->MinimumIslandVoxels << "\n";
  os << indent << "CompareWholeBox: " << this->CompareWholeBox << "\n";
}
