#include "cli/LoadOptions.h"

#include "Error.h"

#include <stdexcept>

namespace cli
{
namespace
{
const char* const RawOptions[] = { "raw-dims", "raw-type", "raw-spacing", "raw-header", "raw-endian", "raw-components" };
}

void AddLoadOptions(Options& o)
{
  o.Add("frame", 0, "patient|vtk",
    "where a volume's voxels are placed: patient (LPS patient coordinates from the file's orientation) or vtk (as "
    "VTK's readers and ParaView show them: origin and spacing, so a reduced mesh overlays the file there)",
    "patient");
  o.Add("raw-dims", 0, "X,Y,Z", "read INPUT as raw voxels of these sizes (with --raw-type)");
  o.Add("raw-type", 0, "TYPE", "raw voxel type: uint8 int8 uint16 int16 uint32 int32 uint64 int64 float32 float64");
  o.Add("raw-spacing", 0, "X,Y,Z", "spacing of raw voxels, or of a stack of image slices", "1,1,1");
  o.Add("raw-header", 0, "BYTES", "bytes before the raw voxels (default: the voxels are the file's last bytes)");
  o.Add("raw-endian", 0, "little|big", "byte order of raw voxels", "little");
  o.Add("raw-components", 0, "N", "values per raw voxel", "1");
}

bool IsLoadOption(const std::string& option)
{
  if (option == "frame")
  {
    return true;
  }
  for (const char* r : RawOptions)
  {
    if (option == r)
    {
      return true;
    }
  }
  return false;
}

art::LoadOptions LoadOptionsFrom(const Options& o)
{
  art::LoadOptions l;
  l.Array = o.Get("array");
  try
  {
    l.Placement = art::ParseFrame(o.Get("frame").empty() ? "patient" : o.Get("frame"));
  }
  catch (const art::Error& e)
  {
    throw UsageError(e.what());
  }
  bool rawGiven = false;
  for (const char* r : RawOptions)
  {
    if (!o.Has(r))
    {
      continue;
    }
    rawGiven = rawGiven || std::string(r) != "raw-spacing";
    try
    {
      art::SetRawOption(l.Raw, r, o.Get(r));
    }
    catch (const std::invalid_argument& e)
    {
      throw UsageError(e.what());
    }
  }
  if (rawGiven && (!l.Raw.Given() || l.Raw.Type.empty()))
  {
    throw UsageError("a raw volume needs both --raw-dims X,Y,Z and --raw-type TYPE");
  }
  return l;
}
} // namespace cli
