// The readers plug-in (ReaderPlugin.h): VTK's MINC and Exodus II readers, set up to read a file
// whole, behind one C function so that IO need not link netCDF.
#include "ReaderPlugin.h"

#include <vtkExodusIIReader.h>
#include <vtkMINCImageReader.h>

extern "C" __attribute__((visibility("default"))) vtkAlgorithm* ArtNewReader(
  const char* format, const char* file, std::string& error)
{
  const std::string f = format;
  if (f == "minc")
  {
    vtkMINCImageReader* r = vtkMINCImageReader::New();
    if (!r->CanReadFile(file))
    {
      r->Delete();
      error = "is not a MINC file VTK reads (MINC 2, HDF5-based, files are not read: convert with mincconvert -2 off)";
      return nullptr;
    }
    r->SetFileName(file);
    r->RescaleRealValuesOn(); // voxels in the file's real units, as its valid range says
    return r;
  }
  if (f == "exodus")
  {
    vtkExodusIIReader* r = vtkExodusIIReader::New();
    if (!r->CanReadFile(file))
    {
      r->Delete();
      error = "is not an Exodus II file VTK reads";
      return nullptr;
    }
    r->SetFileName(file);
    r->UpdateInformation();
    for (int type : { vtkExodusIIReader::NODAL, vtkExodusIIReader::ELEM_BLOCK, vtkExodusIIReader::ELEM_BLOCK_ELEM_CONN })
    {
      r->SetAllArrayStatus(type, 1);
    }
    return r;
  }
  error = "the readers plug-in knows no format '" + f + "'";
  return nullptr;
}
