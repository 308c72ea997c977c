#include "ReaderRun.h"
#include "AvailableMemory.h"
#include "Error.h"

#include <vtkDataArray.h>
#include <vtkDataObject.h>
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
  std::error_code ec;
  if (path.empty())
  {
    throw Error("empty file name");
  }
  if (!fs::exists(path, ec))
  {
    throw Error("no such file or directory", path);
  }
  if (fs::is_directory(path, ec) && !allowDirectory)
  {
    throw Error("is a directory, expected a file", path);
  }
  if (!fs::is_directory(path, ec) && fs::file_size(path, ec) == 0)
  {
    throw Error("file is empty", path);
  }
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

void RunReader(vtkAlgorithm* reader, const std::string& path)
{
  ErrorCatcher catcher(reader);
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
  if (!catcher.Message.empty() && catcher.Message.rfind("No Points element available", 0) != 0)
  {
    throw Error("cannot read: " + catcher.Message, path);
  }
}
} // namespace art
