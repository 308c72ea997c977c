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
/// Where a volume's voxels are placed. Patient: the LPS patient frame of DICOM and ITK, from the
/// file's orientation (MetaImage TransformMatrix, NRRD space directions, DICOM
/// ImageOrientationPatient, NIfTI sform/qform), so one scan renders alike from any format.
/// Vtk: as VTK's own reader gives them (index space with origin and spacing), the frame ParaView
/// shows, so a reduced mesh overlays the file opened there.
enum class Frame
{
  Patient,
  Vtk
};

/// A raw volume's layout, as ParaView's raw reader (vtkImageReader) takes it.
struct RawLayout
{
  int Dims[3] = { 0, 0, 0 };
  std::string Type;                  ///< uint8 int8 uint16 int16 uint32 int32 uint64 int64 float32 float64
  double Spacing[3] = { 1, 1, 1 };
  bool SpacingGiven = false;         ///< also the spacing of an image stack, whose files hold none
  long long HeaderBytes = -1;        ///< -1: the data are the file's last bytes (VTK's default)
  bool BigEndian = false;
  int Components = 1;
  bool Given() const { return Dims[0] > 0; }
};

/// How a file is loaded: the array to take as scalars, the frame, a raw volume's layout.
struct LoadOptions
{
  std::string Array;
  Frame Placement = Frame::Patient;
  RawLayout Raw;
};

/// Sets one field of `raw` from its command-line text: option "raw-dims" ("X,Y,Z"), "raw-type",
/// "raw-spacing" ("X,Y,Z"), "raw-header" (bytes), "raw-endian" (little|big), "raw-components".
/// A malformed value throws std::invalid_argument with a message naming the option.
ADAPTIVERTIO_EXPORT void SetRawOption(RawLayout& raw, const std::string& option, const std::string& value);

/// "patient" or "vtk"; anything else is an art::Error.
ADAPTIVERTIO_EXPORT Frame ParseFrame(const std::string& name);
ADAPTIVERTIO_EXPORT const char* FrameName(Frame f);

enum class DataKind
{
  Volume,  ///< vtkImageData: .mha .mhd .nii .nii.gz .vti .pvti .nrrd .nhdr .slc .mnc .pic .mrc
           ///< .hdr/.img .tif, a DICOM folder, a folder or pattern of image slices, raw voxels
  Surface, ///< vtkPolyData: .ply .obj .stl .vtp .pvtp .g .byu .facet
  Mesh     ///< vtkUnstructuredGrid: .vtu, .vts / .vtr grids as hexahedra, .exo .e .inp .dat .neu
  // A legacy .vtk file is whichever of the three its header names.
};

/// The formats LoadData reads, by kind, as a user reads them (help texts, errors).
struct InputFormatList
{
  std::string volumes, surfaces, meshes, any;
};
ADAPTIVERTIO_EXPORT InputFormatList InputFormats();

/// The kind a path will load as; throws art::Error for a missing file or an unknown extension.
ADAPTIVERTIO_EXPORT DataKind KindOf(const std::string& path);
/// As KindOf; a file given a raw layout is a volume whatever its extension.
ADAPTIVERTIO_EXPORT DataKind KindOf(const std::string& path, const LoadOptions& options);
ADAPTIVERTIO_EXPORT const char* KindName(DataKind k);

/// The volume's point array `array` becomes its scalars (default: the active scalars, else the
/// first one-component array); a missing array is an art::Error that lists the ones there are.
/// "NAME:magnitude" or "NAME:N" (also X, Y, Z; ":magnitude" alone for the active scalars) takes
/// a vector's magnitude or component N as one-component double scalars (art::SplitComponent).
ADAPTIVERTIO_EXPORT vtkSmartPointer<vtkImageData> LoadVolume(const std::string& path, const std::string& array = {});
/// The volume placed in `options.Placement`; its field data record the placement: "IndexToWorld"
/// (16 doubles, the 4 x 4 matrix taking (i, j, k, 1) to world coordinates, row by row) and
/// "Frame" (its name). Surfaces and meshes carry the identity and "file coordinates".
ADAPTIVERTIO_EXPORT vtkSmartPointer<vtkImageData> LoadVolume(const std::string& path, const LoadOptions& options);
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
ADAPTIVERTIO_EXPORT vtkSmartPointer<vtkDataObject> Load(const std::string& path, const LoadOptions& options, DataKind* kind = nullptr);

/// Records the placement of `data` in its field data ("IndexToWorld", "Frame", see LoadVolume).
ADAPTIVERTIO_EXPORT void RecordPlacement(vtkDataSet* data, const std::string& frame);

/// Writes a mesh as .vtu (binary, zlib) atomically.
ADAPTIVERTIO_EXPORT void SaveMesh(vtkUnstructuredGrid* mesh, const std::string& path);
} // namespace art

#endif
