#include "ReaderRun.h"
#include "AvailableMemory.h"
#include "Error.h"
#include "LegacyCheck.h"
#include "RegularFile.h"
#include "StreamCapture.h"

#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkDataSetReader.h>
#include <vtkPolyDataReader.h>
#include <vtkRectilinearGridReader.h>
#include <vtkStructuredGridReader.h>
#include <vtkStructuredPointsReader.h>
#include <vtkUnstructuredGridReader.h>
#include <vtkDataSetAttributes.h>
#include <vtkInformation.h>
#include <vtkStreamingDemandDrivenPipeline.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <new>

namespace fs = std::filesystem;

namespace art
{
void RequireFile(const std::string& path, bool allowDirectory)
{
  RequireRegularFile(path, allowDirectory);
}

// An image whose voxels cannot be held: the read was killed by the system half-way, or thrashed,
// when the allocation passed (the kernel lends more than it has); the header tells the size first.
void CheckImageFits(vtkAlgorithm* reader, const std::string& path)
{
  vtkInformation* info = reader->GetOutputInformation(0);
  if (!info || !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    return; // not an image
  }
  int e[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), e);
  const double voxels = std::max(0, e[1] - e[0] + 1) * double(std::max(0, e[3] - e[2] + 1)) * std::max(0, e[5] - e[4] + 1);
  int type = VTK_UNSIGNED_CHAR, components = 1; // a lower bound when the header does not say
  if (vtkInformation* s = vtkDataObject::GetActiveFieldInformation(
        info, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS))
  {
    type = s->Has(vtkDataObject::FIELD_ARRAY_TYPE()) ? s->Get(vtkDataObject::FIELD_ARRAY_TYPE()) : type;
    components =
      s->Has(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS()) ? s->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS()) : 1;
  }
  const double bytes = voxels * std::max(1, components) * std::max(1, vtkDataArray::GetDataTypeSize(type));
  const double available = AvailableMemoryBytes();
  if (ExceedsAvailableMemory(bytes, available))
  {
    char msg[400];
    std::snprintf(msg, sizeof msg,
      "holding its %d x %d x %d voxels needs about %.3g GB, more than the %.3g GB of memory available; crop or "
      "downsample it first with a tool that reads it in pieces (e.g. ITK or SimpleITK, teem's unu)",
      e[1] - e[0] + 1, e[3] - e[2] + 1, e[5] - e[4] + 1, bytes / 1e9, available / 1e9);
    throw Error(msg, path);
  }
}

namespace
{
// The warnings of VTK's readers that mean data were not read (the rest stand in for zeros).
bool DataWarning(const std::string& w)
{
  for (const char* what : { "rror reading", "Premature EOF", "Unable to read", "Cannot read", "not enough data" })
  {
    if (w.find(what) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}
} // namespace

vtkSmartPointer<vtkAlgorithm> LegacyReader(const std::string& path)
{
  CheckLegacyVtk(path);
  vtkNew<vtkDataSetReader> probe;
  probe->SetFileName(path.c_str());
  ErrorCatcher catcher(probe);
  switch (probe->ReadOutputType())
  {
    case VTK_STRUCTURED_POINTS:
    case VTK_IMAGE_DATA:
      return FileReader<vtkStructuredPointsReader>(path);
    case VTK_POLY_DATA:
      return FileReader<vtkPolyDataReader>(path);
    case VTK_UNSTRUCTURED_GRID:
      return FileReader<vtkUnstructuredGridReader>(path);
    case VTK_STRUCTURED_GRID:
      return FileReader<vtkStructuredGridReader>(path);
    case VTK_RECTILINEAR_GRID:
      return FileReader<vtkRectilinearGridReader>(path);
    default:
      throw Error("is not a legacy VTK data set (no readable header)" +
          (catcher.Message.empty() ? std::string() : ": " + catcher.Message),
        path);
  }
}

void RunReaderInformation(vtkAlgorithm* reader, const std::string& path)
{
  ErrorCatcher catcher(reader);
  StreamCapture quiet;
  reader->UpdateInformation();
  if (!catcher.Message.empty() && !ErrorCatcher::IsRequestDump(catcher.Message))
  {
    throw Error("cannot read: " + catcher.Message, path);
  }
}

void RunReader(vtkAlgorithm* reader, const std::string& path)
{
  ErrorCatcher catcher(reader);
  StreamCapture quiet; // MetaIO and others write to std::cerr and std::cout themselves
  try
  {
    reader->UpdateInformation();
    CheckImageFits(reader, path);
    reader->Update();
  }
  catch (const std::bad_alloc&)
  {
    throw Error("out of memory while reading it (are the header's sizes right?)", path);
  }
  // VTK's XML readers call a data set of no points and no cells (as VTK writes an empty
  // vtkUnstructuredGrid or vtkPolyData) an error; the callers say plainly that it holds nothing.
  if (!catcher.Message.empty() && catcher.Message.rfind("No Points element available", 0) != 0 &&
    !ErrorCatcher::IsRequestDump(catcher.Message))
  {
    throw Error("cannot read: " + catcher.Message, path);
  }
  std::string warning = catcher.Warning;
  if (!DataWarning(warning))
  {
    // The legacy readers' "Error reading binary data!" reaches only the output window.
    const std::string text = quiet.VtkMessages();
    for (const char* what : { "Error reading", "Premature EOF", "Unable to read" })
    {
      const std::size_t at = text.find(what);
      if (at != std::string::npos)
      {
        warning = text.substr(at, text.find('\n', at) - at);
        break;
      }
    }
  }
  if (DataWarning(warning))
  {
    throw Error("cannot read: " + ErrorCatcher::Clean(warning) + " (the file is cut short or its counts are wrong)", path);
  }
  if (!catcher.Message.empty() && ErrorCatcher::IsRequestDump(catcher.Message))
  {
    throw Error("cannot read it (VTK's reader failed without saying why)", path);
  }
}
} // namespace art
