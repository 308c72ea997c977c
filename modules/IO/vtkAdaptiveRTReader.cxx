#include "vtkAdaptiveRTReader.h"
#include "DataLoader.h"
#include "Error.h"

#include <vtkDataObject.h>
#include <vtkDemandDrivenPipeline.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMatrix3x3.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkUnstructuredGrid.h>

#include <new>
#include <stdexcept>

vtkStandardNewMacro(vtkAdaptiveRTReader);

vtkAdaptiveRTReader::vtkAdaptiveRTReader()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
  this->SetFrame("patient");
}

vtkAdaptiveRTReader::~vtkAdaptiveRTReader()
{
  this->SetFileName(nullptr);
  this->SetArrayName(nullptr);
  this->SetFrame(nullptr);
  this->SetRawScalarType(nullptr);
}

int vtkAdaptiveRTReader::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataObject");
  return 1;
}

// Reads the file once per change of the reader's settings; the output type is known only then.
bool vtkAdaptiveRTReader::ReadFile()
{
  if (this->Data && this->ReadTime >= this->GetMTime())
  {
    return true;
  }
  if (!this->Data && !this->ErrorMessage.empty() && this->ReadTime >= this->GetMTime())
  {
    return false;
  }
  this->Data = nullptr;
  this->ErrorMessage.clear();
  this->ReadTime = this->GetMTime();
  try
  {
    if (!this->FileName || !*this->FileName)
    {
      throw art::Error("no file name set (SetFileName)");
    }
    art::LoadOptions options;
    options.Array = this->ArrayName ? this->ArrayName : "";
    options.Placement = art::ParseFrame(this->Frame ? this->Frame : "patient");
    art::RawLayout& raw = options.Raw;
    std::copy(this->RawSpacing, this->RawSpacing + 3, raw.Spacing); // raw voxels and image stacks
    raw.SpacingGiven = true;
    std::copy(this->RawDimensions, this->RawDimensions + 3, raw.Dims);
    if (raw.Given())
    {
      for (int a = 0; a < 3; ++a)
      {
        if (this->RawDimensions[a] < 1)
        {
          throw art::Error("raw dimensions must all be positive", this->FileName);
        }
      }
      art::SetRawOption(raw, "raw-type", this->RawScalarType ? this->RawScalarType : "");
      raw.HeaderBytes = this->RawHeaderSize;
      raw.BigEndian = this->RawBigEndian;
      raw.Components = this->RawComponents;
    }
    this->Data = art::Load(this->FileName, options);
  }
  catch (const art::Error& e)
  {
    this->ErrorMessage = e.what();
  }
  catch (const std::invalid_argument& e)
  {
    this->ErrorMessage = std::string(this->FileName ? this->FileName : "") + ": " + e.what();
  }
  catch (const std::bad_alloc&)
  {
    this->ErrorMessage = std::string(this->FileName ? this->FileName : "") + ": out of memory while reading it";
  }
  if (!this->ErrorMessage.empty())
  {
    vtkErrorMacro(<< this->ErrorMessage);
    return false;
  }
  return true;
}

vtkTypeBool vtkAdaptiveRTReader::ProcessRequest(vtkInformation* request, vtkInformationVector**, vtkInformationVector* outInfo)
{
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA_OBJECT()))
  {
    return this->RequestDataObject(outInfo);
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_INFORMATION()))
  {
    return this->RequestInformation(outInfo);
  }
  if (request->Has(vtkDemandDrivenPipeline::REQUEST_DATA()))
  {
    return this->RequestData(outInfo);
  }
  return 1;
}

int vtkAdaptiveRTReader::RequestDataObject(vtkInformationVector* outInfo)
{
  vtkInformation* info = outInfo->GetInformationObject(0);
  vtkDataObject* current = info->Get(vtkDataObject::DATA_OBJECT());
  // After an error the output is an empty data set of the kind last read (or image data).
  const char* want = "vtkImageData";
  if (this->ReadFile())
  {
    want = this->Data->GetClassName();
  }
  else if (current)
  {
    want = current->GetClassName();
  }
  if (!current || !current->IsA(want))
  {
    vtkSmartPointer<vtkDataObject> out;
    const std::string w = want;
    if (w == "vtkPolyData")
    {
      out = vtkSmartPointer<vtkPolyData>::New();
    }
    else if (w == "vtkUnstructuredGrid")
    {
      out = vtkSmartPointer<vtkUnstructuredGrid>::New();
    }
    else
    {
      out = vtkSmartPointer<vtkImageData>::New();
    }
    info->Set(vtkDataObject::DATA_OBJECT(), out);
  }
  return 1;
}

int vtkAdaptiveRTReader::RequestInformation(vtkInformationVector* outInfo)
{
  vtkInformation* info = outInfo->GetInformationObject(0);
  if (auto* img = vtkImageData::SafeDownCast(this->Data))
  {
    int e[6];
    img->GetExtent(e);
    info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), e, 6);
    info->Set(vtkDataObject::SPACING(), img->GetSpacing(), 3);
    info->Set(vtkDataObject::ORIGIN(), img->GetOrigin(), 3);
    info->Set(vtkDataObject::DIRECTION(), img->GetDirectionMatrix()->GetData(), 9);
  }
  return 1;
}

int vtkAdaptiveRTReader::RequestData(vtkInformationVector* outInfo)
{
  vtkDataObject* out = outInfo->GetInformationObject(0)->Get(vtkDataObject::DATA_OBJECT());
  if (!this->ReadFile())
  {
    out->Initialize();
    return 0;
  }
  out->ShallowCopy(this->Data);
  return 1;
}

void vtkAdaptiveRTReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ArrayName: " << (this->ArrayName ? this->ArrayName : "(default)") << "\n";
  os << indent << "Frame: " << (this->Frame ? this->Frame : "patient") << "\n";
  os << indent << "RawDimensions: " << this->RawDimensions[0] << " " << this->RawDimensions[1] << " "
     << this->RawDimensions[2] << "\n";
  os << indent << "RawScalarType: " << (this->RawScalarType ? this->RawScalarType : "(none)") << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
