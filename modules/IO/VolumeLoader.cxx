// The volume loader behind DataLoader.h's LoadVolume: every format's reader, then the placement,
// rescaling and checks that make one scan load alike from any of them.
#include "DataLoader.h"
#include "ArrayChoice.h"
#include "AtomicFile.h"
#include "CellVoxels.h"
#include "DicomSeries.h"
#include "Error.h"
#include "MetaImageCheck.h"
#include "NiftiCheck.h"
#include "NrrdCheck.h"
#include "OtherFormats.h"
#include "XmlCheck.h"
#include "ReaderRun.h"
#include "ValueMagnitude.h"
#include "VolumePlacement.h"

#include <vtkCellData.h>
#include <vtkDICOMImageReader.h>
#include <vtkDataArray.h>
#include <vtkDataSetReader.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkMetaImageReader.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNrrdReader.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPImageDataReader.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace art
{
namespace
{
// A DICOM Part 10 file has "DICM" at byte 128; vtkDICOMImageReader gives no useful message
// for a folder without one.
bool HasDicomFile(const std::string& dir)
{
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec))
  {
    if (!entry.is_regular_file(ec))
    {
      continue;
    }
    std::ifstream in(entry.path(), std::ios::binary);
    char magic[4] = {};
    if (in.seekg(128) && in.read(magic, 4) && std::string(magic, 4) == "DICM")
    {
      return true;
    }
  }
  return false;
}

// VTK 9.1's vtkXMLPImageDataReader leaves the direction at the identity, and its writer leaves it
// out of the .pvti (its pieces keep it): a turned image saved in pieces loaded unturned. The
// direction is taken from the .pvti (as later VTK writes it), else from its first piece.
bool PvtiDirection(const std::string& path, double dir[9])
{
  auto attribute = [](const std::string& file, const char* element, const char* name) -> std::string {
    std::ifstream in(file, std::ios::binary);
    std::string head(1 << 16, '\0');
    in.read(&head[0], static_cast<std::streamsize>(head.size()));
    head.resize(static_cast<std::size_t>(in.gcount()));
    const std::size_t e = head.find(std::string("<") + element);
    const std::size_t end = e == std::string::npos ? e : head.find('>', e);
    if (end == std::string::npos)
    {
      return {};
    }
    const std::string tag = head.substr(e, end - e);
    const std::string key = std::string(" ") + name + "=\"";
    const std::size_t a = tag.find(key);
    const std::size_t q = a == std::string::npos ? a : tag.find('"', a + key.size());
    return q == std::string::npos ? std::string() : tag.substr(a + key.size(), q - a - key.size());
  };
  std::string text = attribute(path, "PImageData", "Direction");
  if (text.empty())
  {
    const std::string piece = attribute(path, "Piece", "Source");
    if (piece.empty())
    {
      return false;
    }
    const fs::path p = fs::path(piece).is_absolute() ? fs::path(piece) : fs::path(path).parent_path() / piece;
    text = attribute(p.string(), "ImageData", "Direction");
  }
  std::istringstream in(text);
  for (int i = 0; i < 9; ++i)
  {
    if (!(in >> dir[i]))
    {
      return false;
    }
  }
  return true;
}

// Makes `name` the active scalars of `pd`; without a name keeps the active scalars, or takes the
// first one-component array when none is active (XML files need not mark one).
void SelectScalars(vtkPointData* pd, const std::string& name, const std::string& path)
{
  vtkDataArray* a = ChooseArray(pd, name, true); // SetActiveScalars needs the name
  if (!a && !name.empty())
  {
    throw Error("has no point array '" + name + "' (it has: " + ArrayNames({ pd }) + ")", path);
  }
  if (a && a != pd->GetScalars())
  {
    pd->SetActiveScalars(a->GetName());
  }
}

// An image whose values are on its cells (voxel-centred data: labels, a finite-volume simulation)
// and not on its points "held no voxels". Its cells become the voxels, placed at the cell centres.
vtkSmartPointer<vtkImageData> CellsAsVoxels(vtkImageData* img, const std::string& name)
{
  vtkPointData* pd = img->GetPointData();
  vtkCellData* cd = img->GetCellData();
  const bool onPoints = name.empty() ? ChooseArray(pd, "", true) != nullptr : pd->GetArray(name.c_str()) != nullptr;
  const bool onCells = name.empty() ? ChooseArray(cd, "", true) != nullptr : cd->GetArray(name.c_str()) != nullptr;
  if (onPoints || !onCells)
  {
    return img;
  }
  return CellVoxels(img, cd);
}

// NIfTI stores values as slope * stored + intercept (a CT in Hounsfield units is often uint16 with
// intercept -1024); vtkNIFTIImageReader reports the pair but leaves the voxels as stored (unlike
// vtkDICOMImageReader, which applies its own). A zero or non-finite slope means no scaling, as in
// nifti1_io.
void ApplyRescale(vtkImageData* img, double slope, double intercept)
{
  vtkDataArray* in = img->GetPointData()->GetScalars();
  if (!in || slope == 0 || !std::isfinite(slope) || !std::isfinite(intercept) || (slope == 1 && intercept == 0))
  {
    return;
  }
  // Float holds 16-bit values scaled exactly enough; wider types keep double.
  vtkSmartPointer<vtkDataArray> out = in->GetDataTypeSize() <= 2 ? vtkSmartPointer<vtkDataArray>(vtkSmartPointer<vtkFloatArray>::New())
                                                                  : vtkSmartPointer<vtkDataArray>(vtkSmartPointer<vtkDoubleArray>::New());
  out->SetName(in->GetName());
  out->SetNumberOfComponents(in->GetNumberOfComponents());
  out->SetNumberOfTuples(in->GetNumberOfTuples());
  for (vtkIdType t = 0; t < in->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < in->GetNumberOfComponents(); ++c)
    {
      out->SetComponent(t, c, slope * in->GetComponent(t, c) + intercept);
    }
  }
  img->GetPointData()->SetScalars(out);
}

// vtkDICOMImageReader (VTK 9.1) stores the rows bottom-up and the slices from the last along the
// slice normal n = row x column cosines, reports the first slice's ImagePositionPatient, takes
// PixelSpacing's (row, column) pair as (x, y), and leaves origin 0 and no direction. Put each voxel
// where the patient coordinates say (as ITK and a MetaImage of the same series do): columns
// along r, rows along -c, slices along -n from the far corner; x spacing is the column spacing.
void ApplyDicomGeometry(vtkImageData* img, vtkDICOMImageReader* r)
{
  const float* iop = r->GetImageOrientationPatient();
  const float* ipp = r->GetImagePositionPatient();
  if (!iop || !ipp)
  {
    return;
  }
  const double rc[3] = { iop[0], iop[1], iop[2] }, cc[3] = { iop[3], iop[4], iop[5] };
  const double rr = rc[0] * rc[0] + rc[1] * rc[1] + rc[2] * rc[2];
  const double ccc = cc[0] * cc[0] + cc[1] * cc[1] + cc[2] * cc[2];
  const double rdc = rc[0] * cc[0] + rc[1] * cc[1] + rc[2] * cc[2];
  if (std::abs(rr - 1) > 1e-3 || std::abs(ccc - 1) > 1e-3 || std::abs(rdc) > 1e-3)
  {
    return; // no (or no usable) orientation: keep VTK's layout
  }
  const double n[3] = { rc[1] * cc[2] - rc[2] * cc[1], rc[2] * cc[0] - rc[0] * cc[2], rc[0] * cc[1] - rc[1] * cc[0] };
  const double* sp = img->GetSpacing();
  const double sx = sp[1], sy = sp[0], sz = sp[2];
  int d[3];
  img->GetDimensions(d);
  double origin[3];
  for (int a = 0; a < 3; ++a)
  {
    origin[a] = ipp[a] + (d[1] - 1) * sy * cc[a] + (d[2] - 1) * sz * n[a];
  }
  img->SetSpacing(sx, sy, sz);
  img->SetOrigin(origin);
  img->SetDirectionMatrix(rc[0], -cc[0], -n[0], rc[1], -cc[1], -n[1], rc[2], -cc[2], -n[2]);
}

// VTK's XML and legacy readers keep a negative spacing (a flipped axis, as some tools write one),
// which the voxel reference would take as positive, mirroring the volume against the reduced
// mesh. The sign moves into the direction matrix, placing every voxel where it was.
// A zero or non-finite spacing along an axis of several voxels puts them all in one plane.
void MakeSpacingPositive(vtkImageData* img, const std::string& path)
{
  double sp[3];
  img->GetSpacing(sp);
  int d[3];
  img->GetDimensions(d);
  double dir[9];
  std::copy_n(img->GetDirectionMatrix()->GetData(), 9, dir);
  bool flipped = false;
  for (int a = 0; a < 3; ++a)
  {
    if (d[a] > 1 && !(std::abs(sp[a]) > 0 && std::isfinite(sp[a])))
    {
      std::ostringstream what;
      what << "spacing along " << "xyz"[a] << " is " << sp[a]
           << "; it must be finite and non-zero (the voxels of that axis would lie in one plane)";
      throw Error(what.str(), path);
    }
    if (sp[a] < 0)
    {
      sp[a] = -sp[a];
      for (int r = 0; r < 3; ++r)
      {
        dir[3 * r + a] = -dir[3 * r + a];
      }
      flipped = true;
    }
  }
  if (flipped)
  {
    img->SetSpacing(sp);
    img->SetDirectionMatrix(dir);
  }
}
} // namespace

namespace
{
// vtkNrrdReader itself: in a Python program that imported all of VTK, the object factory hands
// out vtkPNrrdReader, which refuses to read without an MPI controller.
vtkSmartPointer<vtkAlgorithm> PlainNrrdReader(const std::string& path)
{
  auto r = vtkSmartPointer<vtkNrrdReader>::New();
  if (std::string(r->GetClassName()) != "vtkNrrdReader")
  {
    vtkObjectFactory::SetAllEnableFlags(0, "vtkNrrdReader"); // factories are registered: one made r
    r = vtkSmartPointer<vtkNrrdReader>::New();
    vtkObjectFactory::SetAllEnableFlags(1, "vtkNrrdReader");
  }
  r->SetFileName(path.c_str());
  return r;
}

// The voxels read against the extent the reader's header promised (a reader stopping short left
// a smaller or empty array behind the full extent).
void CheckVoxelCount(vtkAlgorithm* reader, vtkImageData* img, const std::string& path)
{
  vtkDataArray* s = img->GetPointData()->GetScalars();
  if (s && s->GetNumberOfTuples() != img->GetNumberOfPoints())
  {
    throw Error("holds " + std::to_string(s->GetNumberOfTuples()) + " voxel values for its " +
        std::to_string(img->GetNumberOfPoints()) + " voxels (damaged or cut short)",
      path);
  }
  (void)reader;
}

vtkSmartPointer<vtkImageData> LoadWholeVolume(const std::string& path, const LoadOptions& options);
}

vtkSmartPointer<vtkImageData> LoadVolume(const std::string& path, const std::string& array)
{
  LoadOptions options;
  options.Array = array;
  return LoadVolume(path, options);
}

vtkSmartPointer<vtkImageData> LoadVolume(const std::string& path, const LoadOptions& options)
{
  // "velocity:magnitude", "velocity:0": a vector's magnitude or one component becomes the scalars
  // (what VTK's volume mappers draw of a vector with VectorMode), after any rescale of the file.
  int component;
  LoadOptions whole = options;
  whole.Array = SplitComponent(options.Array, &component);
  auto img = LoadWholeVolume(path, whole);
  if (component != WholeArray)
  {
    try
    {
      img->GetPointData()->SetScalars(TakeComponent(img->GetPointData()->GetScalars(), component));
    }
    catch (const Error& e)
    {
      throw Error(e.problem(), path);
    }
  }
  RecordPlacement(img, options.Placement == Frame::Patient ? "LPS patient" : "VTK reader");
  return img;
}

namespace
{
vtkSmartPointer<vtkImageData> LoadWholeVolume(const std::string& path, const LoadOptions& options)
{
  const std::string& array = options.Array;
  const bool patient = options.Placement == Frame::Patient;
  if (KindOf(path, options) != DataKind::Volume)
  {
    throw Error("is not a volume (expected .mha .mhd .nii .nii.gz .vti .pvti .nrrd, image data in .vtk, or a DICOM folder)",
      path);
  }
  std::error_code ec;
  const std::string e = LowerExtension(path);
  vtkSmartPointer<vtkAlgorithm> reader;
  std::unique_ptr<DicomLinkFolder> series; // lives until the reader has read
  if (options.Raw.Given() || IsOtherVolume(e) || !ImageStack(path).empty())
  {
    reader = OtherVolumeReader(path, options.Raw);
  }
  else if (fs::is_directory(path, ec))
  {
    if (!HasDicomFile(path))
    {
      throw Error("folder holds no readable DICOM series and no image slices (.png .jpg .tif .bmp)", path);
    }
    // vtkDICOMImageReader reads every series in a folder as one: give it one (DicomSeries.h).
    int seriesInFolder = 0;
    const std::vector<std::string> files = DicomSeriesFiles(path, &seriesInFolder);
    auto r = vtkSmartPointer<vtkDICOMImageReader>::New();
    if (seriesInFolder > 1)
    {
      series = std::make_unique<DicomLinkFolder>(files);
    }
    r->SetDirectoryName(series ? series->Path().c_str() : path.c_str());
    reader = r;
  }
  else if (e == ".mha" || e == ".mhd")
  {
    CheckMetaImage(path);
    reader = FileReader<vtkMetaImageReader>(path);
  }
  else if (e == ".nii" || e == ".nii.gz")
  {
    CheckNifti(path);
    reader = FileReader<vtkNIFTIImageReader>(path);
  }
  else if (e == ".vti")
  {
    CheckVtkXml(path);
    reader = FileReader<vtkXMLImageDataReader>(path);
  }
  else if (e == ".pvti")
  {
    CheckVtkXml(path);
    reader = FileReader<vtkXMLPImageDataReader>(path);
  }
  else if (e == ".vtk")
  {
    reader = LegacyReader(path);
  }
  else
  {
    CheckNrrd(path);
    reader = PlainNrrdReader(path);
  }
  RunReader(reader, path);
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->ShallowCopy(reader->GetOutputDataObject(0));
  double direction[9];
  if (e == ".pvti" && PvtiDirection(path, direction))
  {
    img->SetDirectionMatrix(direction); // before cell centres are placed
  }
  img = CellsAsVoxels(img, array);
  SelectScalars(img->GetPointData(), array, path);
  if (patient && vtkMetaImageReader::SafeDownCast(reader) && MetaImageDirection(path, direction))
  {
    img->SetDirectionMatrix(direction);
  }
  if (e == ".nrrd" || e == ".nhdr")
  {
    if (vtkDataArray* s = img->GetPointData()->GetScalars())
    {
      ReadNrrdText(path, s); // VTK read text data as zeros
    }
    img = patient ? PlaceNrrd(img, path) : NrrdAxesAsVtk(img, path);
  }
  if (auto* dicom = vtkDICOMImageReader::SafeDownCast(reader); dicom && patient)
  {
    ApplyDicomGeometry(img, dicom);
  }
  if (auto* nifti = vtkNIFTIImageReader::SafeDownCast(reader))
  {
    ApplyRescale(img, nifti->GetRescaleSlope(), nifti->GetRescaleIntercept());
    if (patient && !IsOtherVolume(e))
    {
      PlaceNifti(img, nifti, path);
    }
  }
  CheckVoxelCount(reader, img, path);
  MakeSpacingPositive(img, path);
  int dims[3];
  img->GetDimensions(dims);
  if (dims[0] <= 0 || dims[1] <= 0 || dims[2] <= 0 || !img->GetPointData()->GetScalars())
  {
    if (fs::is_directory(path, ec))
    {
      throw Error("folder holds no readable DICOM series", path);
    }
    // Voxels without values said "holds no voxels (empty or unreadable volume)" too.
    if (img->GetNumberOfPoints() > 0 && img->GetPointData()->GetNumberOfArrays() > 0)
    {
      vtkDataArray* vector = nullptr;
      for (int i = 0; i < img->GetPointData()->GetNumberOfArrays() && !vector; ++i)
      {
        vtkDataArray* a = img->GetPointData()->GetArray(i);
        vector = a && a->GetName() && a->GetNumberOfComponents() > 1 ? a : nullptr;
      }
      throw Error("has no one-component point array to take as the voxels (point arrays: " +
          ArrayNames({ img->GetPointData() }) +
          (vector ? "; choose a vector's magnitude or component with --array " + ComponentHint(vector) : "") + ")",
        path);
    }
    if (img->GetNumberOfPoints() > 0)
    {
      vtkFieldData* fd = img->GetFieldData();
      throw Error(std::string("has ") + std::to_string(img->GetNumberOfPoints()) + " voxels but no values on them" +
          (fd && fd->GetNumberOfArrays() > 0 ? " (only field data: " + ArrayNames({ fd }) + ")" : ""),
        path);
    }
    throw Error("holds no voxels (empty or unreadable volume)", path);
  }
  return img;
}
} // namespace

void RequireOneComponent(vtkImageData* volume, const std::string& path)
{
  vtkDataArray* s = volume->GetPointData()->GetScalars();
  if (const int nc = s ? s->GetNumberOfComponents() : 0; nc != 1)
  {
    throw Error("the scalars" + (s && s->GetName() ? " '" + std::string(s->GetName()) + "'" : std::string()) +
        " have " + std::to_string(nc) + " components; one is needed (choose with --array " + ComponentHint(s) +
        ", or another array)",
      path);
  }
  // Values of 1e300 or 1e-310 reached the transfer function and the fit (a crash, 'RMS inf').
  double r[2];
  s->GetRange(r, 0);
  if (std::isfinite(r[0]) && std::isfinite(r[1]))
  {
    RequireComputableRange(r[0], r[1], path);
  }
}
} // namespace art
