#include "vtkTetRayCastVolumeRepresentation.h"

#include <vtkColorTransferFunction.h>
#include <vtkCommunicator.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMultiProcessController.h>
#include <vtkObjectFactory.h>
#include <vtkPVRenderView.h>
#include <vtkTetRayCastMapper.h>
#include <vtkVolumeProperty.h>

vtkStandardNewMacro(vtkTetRayCastVolumeRepresentation);

namespace
{
// `adaptivert render --iso`'s colours, in turn, so both draw the same iso-surfaces.
const double IsoColours[4][3] = { { 1, 0.85, 0.7 }, { 0.6, 0.8, 1 }, { 1, 0.5, 0.4 }, { 0.6, 1, 0.6 } };
const char* const MapperName = "Tet Ray Cast";

// Does every rank hold a piece of one parallel reduction (its "pieces" field is the number of
// ranks), or nothing? Collective: every rank calls it.
bool HoldsReducerPieces(vtkDataObject* input)
{
  vtkMultiProcessController* c = vtkMultiProcessController::GetGlobalController();
  const int ranks = c ? c->GetNumberOfProcesses() : 1;
  if (ranks < 2)
  {
    return false;
  }
  int mine = 0;
  if (vtkDataSet* ds = vtkDataSet::SafeDownCast(input))
  {
    vtkDataArray* pieces = ds->GetFieldData() ? ds->GetFieldData()->GetArray("pieces") : nullptr;
    mine = ds->GetNumberOfCells() == 0 ||
      (pieces && pieces->GetNumberOfTuples() == 1 && pieces->GetTuple1(0) == ranks);
  }
  int all = 0;
  c->AllReduce(&mine, &all, 1, vtkCommunicator::MIN_OP);
  return all == 1;
}
}

vtkTetRayCastVolumeRepresentation::vtkTetRayCastVolumeRepresentation()
{
  this->Mapper = vtkTetRayCastMapper::New();
  this->AddVolumeMapper(MapperName, this->Mapper);
  this->SetActiveVolumeMapper(MapperName);
}

vtkTetRayCastVolumeRepresentation::~vtkTetRayCastVolumeRepresentation()
{
  this->Mapper->Delete();
}

vtkTetRayCastMapper* vtkTetRayCastVolumeRepresentation::GetTetRayCastMapper()
{
  return this->Mapper;
}

void vtkTetRayCastVolumeRepresentation::SetEarlyRayTermination(double opacity)
{
  this->Mapper->SetEarlyRayTermination(opacity);
  this->MarkModified();
}

double vtkTetRayCastVolumeRepresentation::GetEarlyRayTermination()
{
  return this->Mapper->GetEarlyRayTermination();
}

void vtkTetRayCastVolumeRepresentation::SetImageSampleDistance(double pixels)
{
  this->Mapper->SetImageSampleDistance(static_cast<float>(pixels));
  this->MarkModified();
}

void vtkTetRayCastVolumeRepresentation::SetAutoAdjustSampleDistances(int on)
{
  this->Mapper->SetAutoAdjustSampleDistances(on);
  this->MarkModified();
}

void vtkTetRayCastVolumeRepresentation::SetMinimumImageSampleDistance(double pixels)
{
  this->Mapper->SetMinimumImageSampleDistance(static_cast<float>(pixels));
  this->MarkModified();
}

void vtkTetRayCastVolumeRepresentation::SetMaximumImageSampleDistance(double pixels)
{
  this->Mapper->SetMaximumImageSampleDistance(static_cast<float>(pixels));
  this->MarkModified();
}

void vtkTetRayCastVolumeRepresentation::SetIntermixIntersectingGeometry(int on)
{
  this->Mapper->SetIntermixIntersectingGeometry(on);
  this->MarkModified();
}

void vtkTetRayCastVolumeRepresentation::SetIntegrator(int rule)
{
  this->Mapper->SetTrapezoidRule(rule == TRAPEZOID ? 1 : 0);
  this->MarkModified();
}

int vtkTetRayCastVolumeRepresentation::GetIntegrator()
{
  return this->Mapper->GetTrapezoidRule() ? TRAPEZOID : EXACT;
}

void vtkTetRayCastVolumeRepresentation::SetLabelColoring(int mode)
{
  this->Mapper->SetLabelColoring(mode);
  this->MarkModified();
}

int vtkTetRayCastVolumeRepresentation::GetLabelColoring()
{
  return this->Mapper->GetLabelColoring();
}

void vtkTetRayCastVolumeRepresentation::AddIsoValue(double value)
{
  this->IsoValues.push_back(value);
  this->IsoChanged = true;
  this->MarkModified();
}

void vtkTetRayCastVolumeRepresentation::RemoveAllIsoValues()
{
  this->IsoValues.clear();
  this->IsoChanged = true;
  this->MarkModified();
}

void vtkTetRayCastVolumeRepresentation::SetIsoOpacity(double opacity)
{
  this->IsoOpacity = opacity < 0 ? 0 : (opacity > 1 ? 1 : opacity);
  this->IsoChanged = true;
  this->MarkModified();
}

void vtkTetRayCastVolumeRepresentation::UpdateMapperParameters()
{
  this->Superclass::UpdateMapperParameters();
  if (this->GetActiveVolumeMapper() != this->Mapper)
  {
    return;
  }
  if (this->IsoChanged)
  {
    this->Mapper->RemoveAllIsoSurfaces();
    for (size_t i = 0; i < this->IsoValues.size(); ++i)
    {
      const double* c = IsoColours[i % 4];
      this->Mapper->AddIsoSurface(this->IsoValues[i], c[0], c[1], c[2], this->IsoOpacity);
    }
    this->IsoChanged = false;
  }
  // As the superclass does for its smart and multi-block mappers: the colour map's vector mode
  // (Magnitude, or a component) is what the caster draws of a vector array.
  vtkVolumeProperty* p = this->Property;
  vtkColorTransferFunction* ctf = p ? p->GetRGBTransferFunction(0) : nullptr;
  if (ctf && p->GetIndependentComponents())
  {
    const bool magnitude = ctf->GetVectorMode() == vtkScalarsToColors::MAGNITUDE;
    this->Mapper->SetVectorMode(magnitude ? vtkTetRayCastMapper::MAGNITUDE : vtkTetRayCastMapper::COMPONENT);
    this->Mapper->SetVectorComponent(magnitude ? 0 : ctf->GetVectorComponent());
  }
}

int vtkTetRayCastVolumeRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataObject* input =
    inputVector[0]->GetNumberOfInformationObjects() == 1 ? vtkDataObject::GetData(inputVector[0], 0) : nullptr;
  this->ReducerPieces = HoldsReducerPieces(input);
  return this->Superclass::RequestData(request, inputVector, outputVector);
}

int vtkTetRayCastVolumeRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(request, inInfo, outInfo))
  {
    return 0;
  }
  if (request == vtkPVView::REQUEST_UPDATE() && this->ReducerPieces && !this->UseDataPartitions)
  {
    // The superclass asked for redistribution; these pieces are sortable as they lie.
    vtkPVRenderView::SetOrderedCompositingConfiguration(inInfo, this, vtkPVRenderView::USE_BOUNDS_FOR_REDISTRIBUTION);
  }
  return 1;
}

void vtkTetRayCastVolumeRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IsoValues: " << this->IsoValues.size() << " (opacity " << this->IsoOpacity << ")\n";
  os << indent << "ReducerPieces: " << this->ReducerPieces << "\n";
  this->Mapper->PrintSelf(os, indent.GetNextIndent());
}
