// DataLoader: reads any volume, surface or mesh VTK can read, chosen by extension (a legacy .vtk
// file by its header), and turns every failure (missing file, unknown type, truncated or garbage
// content, a VTK reader error) into one art::Error that names the file and the problem.
#ifndef art_DataLoader_h
#define art_DataLoader_h

#include "AdaptiveRTIOModule.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkDataObject;
class vtkDataSet;
class vtkImageData;
class vtkPolyData;
class vtkUnstructuredGrid;

namespace art
{
enum class DataKind
{
  Volume,  ///< vtkImageData: .mha .mhd .nii .nii.gz .vti .pvti .nrrd .nhdr, or a DICOM folder
  Surface, ///< vtkPolyData: .ply .obj .stl .vtp .pvtp
  Mesh     ///< vtkUnstructuredGrid: .vtu, or .vts / .vtr grids as hexahedra
  // A legacy .vtk file is whichever of the three its header names.
};

/// The kind a path will load as; throws art::Error for a missing file or an unknown extension.
ADAPTIVERTIO_EXPORT DataKind KindOf(const std::string& path);
ADAPTIVERTIO_EXPORT const char* KindName(DataKind k);

/// The volume's point array `array` becomes its scalars (default: the active scalars, else the
/// first one-component array); a missing array is an art::Error that lists the ones there are.
/// "NAME:magnitude" or "NAME:N" (also X, Y, Z; ":magnitude" alone for the active scalars) takes
/// a vector's magnitude or component N as one-component double scalars (art::SplitComponent).
ADAPTIVERTIO_EXPORT vtkSmartPointer<vtkImageData> LoadVolume(const std::string& path, const std::string& array = {});
/// For renderers and the reducer: an art::Error naming `path` unless the volume's scalars have one
/// component and a magnitude they compute with (art::RequireComputableRange).
ADAPTIVERTIO_EXPORT void RequireOneComponent(vtkImageData* volume, const std::string& path);
ADAPTIVERTIO_EXPORT vtkSmartPointer<vtkPolyData> LoadSurface(const std::string& path);
ADAPTIVERTIO_EXPORT vtkSmartPointer<vtkUnstructuredGrid> LoadMesh(const std::string& path);
/// For `--array NAME:magnitude` or `NAME:N` on a mesh (art::SplitComponent): adds the vector's
/// magnitude or component N beside it (in its point data, else its cell data) and returns the new
/// array's name ("NAME:magnitude", "NAME:N") to look up; any other `array` comes back as it is.
/// A missing array or component is an art::Error naming `path`.
ADAPTIVERTIO_EXPORT std::string AddComponentArray(vtkDataSet* data, const std::string& array, const std::string& path);
/// Loads whatever the extension says; the result is one of the three types above.
ADAPTIVERTIO_EXPORT vtkSmartPointer<vtkDataObject> Load(const std::string& path, DataKind* kind = nullptr);

/// Writes a mesh as .vtu (binary, zlib) atomically.
ADAPTIVERTIO_EXPORT void SaveMesh(vtkUnstructuredGrid* mesh, const std::string& path);
} // namespace art

#endif
