#include "DataLoader.h"
#include "ArrayChoice.h"
#include "CellVoxels.h"
#include "AtomicFile.h"
#include "DicomSeries.h"
#include "Error.h"
#include "MetaImageCheck.h"
#include "NiftiCheck.h"
#include "NrrdCheck.h"
#include "ObjReader.h"
#include "PlyCheck.h"
#include "StlCheck.h"
#include "VolumePlacement.h"

#include <vtkAlgorithm.h>
#include <vtkAppendFilter.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDICOMImageReader.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkDataSetReader.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkExecutive.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkMetaImageReader.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>
#include <vtkNrrdReader.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLImageDataReader.h>
#include <vtkXMLPImageDataReader.h>
#include <vtkXMLPPolyDataReader.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLRectilinearGridReader.h>
#include <vtkXMLStructuredGridReader.h>
#include <vtkCompositeDataSet.h>
#include <vtkCompositeDataIterator.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLPRectilinearGridReader.h>
#include <vtkXMLPStructuredGridReader.h>
#include <vtkXMLPUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <new>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace art
{
namespace
{
// Parallel image and polydata pieces (.pvti .pvtp, as ParaView saves them from several ranks) are
// read whole, as the mesh pieces below are.
const std::set<std::string> VolumeExt = { ".mha", ".mhd", ".nii", ".nii.gz", ".vti", ".pvti", ".nrrd", ".nhdr" };
const std::set<std::string> SurfaceExt = { ".ply", ".obj", ".stl", ".vtp", ".pvtp" };
// Parallel pieces (.pvtu .pvts .pvtr) and multiblock files (.vtm), as MPI solvers and ParaView
// write them, are read whole: every piece or block appended into one grid.
const std::set<std::string> MeshExt = { ".vtu", ".vts", ".vtr", ".pvtu", ".pvts", ".pvtr", ".vtm" };

// Keeps the first error a VTK object reports instead of letting it reach the output window.
struct ErrorCatcher
{
  std::string Message;
  vtkNew<vtkCallbackCommand> Cmd;

  explicit ErrorCatcher(vtkAlgorithm* alg)
  {
    Cmd->SetClientData(this);
    Cmd->SetCallback([](vtkObject*, unsigned long event, void* self, void* data) {
      auto* me = static_cast<ErrorCatcher*>(self);
      if (event == vtkCommand::ErrorEvent && me->Message.empty() && data)
      {
        me->Message = Clean(static_cast<const char*>(data));
      }
    });
    alg->AddObserver(vtkCommand::ErrorEvent, Cmd);
    alg->AddObserver(vtkCommand::WarningEvent, Cmd);
    alg->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, Cmd);
  }
  // VTK messages carry "ERROR: In file, line N\nclass (0x..): text"; keep only the text.
  static std::string Clean(std::string m)
  {
    auto p = m.rfind("): ");
    if (p != std::string::npos)
    {
      m = m.substr(p + 3);
    }
    while (!m.empty() && (m.back() == '\n' || m.back() == ' ' || m.back() == '\r'))
    {
      m.pop_back();
    }
    for (char& c : m)
    {
      c = (c == '\n') ? ' ' : c;
    }
    return m;
  }
};

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

void RunReader(vtkAlgorithm* reader, const std::string& path)
{
  ErrorCatcher catcher(reader);
  try
  {
    reader->Update();
  }
  catch (const std::bad_alloc&)
  {
    throw Error("out of memory while reading it (are the header's sizes right?)", path);
  }
  if (!catcher.Message.empty())
  {
    throw Error("cannot read: " + catcher.Message, path);
  }
}

template <class Reader>
vtkSmartPointer<vtkAlgorithm> FileReader(const std::string& path)
{
  auto r = vtkSmartPointer<Reader>::New();
  r->SetFileName(path.c_str());
  return r;
}

void CheckPolyIndices(vtkPolyData* pd, const std::string& path)
{
  const vtkIdType n = pd->GetNumberOfPoints();
  for (vtkCellArray* cells : { pd->GetVerts(), pd->GetLines(), pd->GetPolys(), pd->GetStrips() })
  {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType npts;
      const vtkIdType* ids;
      it->GetCurrentCell(npts, ids);
      for (vtkIdType i = 0; i < npts; ++i)
      {
        if (ids[i] < 0 || ids[i] >= n)
        {
          throw Error("a face refers to vertex " + std::to_string(ids[i]) + " of " +
              std::to_string(n),
            path);
        }
      }
    }
  }
}
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

// A legacy .vtk file may hold any data set: its header says which.
DataKind LegacyKind(const std::string& path)
{
  vtkNew<vtkDataSetReader> r;
  r->SetFileName(path.c_str());
  ErrorCatcher catcher(r);
  switch (r->ReadOutputType())
  {
    case VTK_STRUCTURED_POINTS:
    case VTK_IMAGE_DATA:
      return DataKind::Volume;
    case VTK_POLY_DATA:
      return DataKind::Surface;
    case VTK_UNSTRUCTURED_GRID:
    case VTK_STRUCTURED_GRID:
    case VTK_RECTILINEAR_GRID:
      return DataKind::Mesh;
    default:
      throw Error("is not a legacy VTK data set (no readable header)" +
          (catcher.Message.empty() ? std::string() : ": " + catcher.Message),
        path);
  }
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
// which the voxel reference took as positive: it rendered the volume mirrored against the reduced
// mesh (8 dB apart). The sign moves into the direction matrix, placing every voxel where it was.
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

// A time series (a ParaView .pvd collection, as ParaView, FEniCS, deal.II and foamToVTK write
// them, or a .series JSON file) said "unknown file type". One step is one file the tools read:
// the error names the first.
namespace
{
[[noreturn]] void TimeSeriesError(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const bool pvd = LowerExtension(path) == ".pvd";
  const std::regex entry(pvd ? R"re(<DataSet\b[^>]*>)re" : R"re(\{[^{}]*"name"[^{}]*\})re");
  const std::regex name(pvd ? R"re(\bfile\s*=\s*"([^"]*)")re" : R"re("name"\s*:\s*"([^"]*)")re");
  const std::regex time(pvd ? R"re(\btimestep\s*=\s*"([^"]*)")re" : R"re("time"\s*:\s*([-+0-9.eE]+))re");
  std::vector<std::pair<std::string, std::string>> steps; // file, time
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry); it != std::sregex_iterator(); ++it)
  {
    const std::string item = it->str();
    std::smatch f, t;
    if (std::regex_search(item, f, name))
    {
      steps.emplace_back(f[1].str(), std::regex_search(item, t, time) ? t[1].str() : std::string());
    }
  }
  if (steps.empty())
  {
    throw Error(std::string("is a time series (") + (pvd ? "ParaView .pvd collection" : ".series file") +
        ") that names no data files",
      path);
  }
  const fs::path first = fs::path(steps[0].first).is_absolute() ? fs::path(steps[0].first)
                                                                 : fs::path(path).parent_path() / steps[0].first;
  throw Error(std::string("is a time series of ") + std::to_string(steps.size()) + " data files (" +
      (pvd ? "ParaView .pvd collection" : ".series file") + "), which the tools do not step through: give one of its files, e.g. '" +
      first.string() + "'" + (steps[0].second.empty() ? "" : " (time " + steps[0].second + ")"),
    path);
}
} // namespace

const char* KindName(DataKind k)
{
  switch (k)
  {
    case DataKind::Volume:
      return "volume";
    case DataKind::Surface:
      return "surface";
    default:
      return "mesh";
  }
}

DataKind KindOf(const std::string& path)
{
  RequireFile(path, true);
  std::error_code ec;
  const std::string e = LowerExtension(path);
  if (fs::is_directory(path, ec))
  {
    if (!e.empty())
    {
      throw Error("is a directory, expected a file", path);
    }
    return DataKind::Volume; // a DICOM series
  }
  if (VolumeExt.count(e))
  {
    return DataKind::Volume;
  }
  if (SurfaceExt.count(e))
  {
    return DataKind::Surface;
  }
  if (MeshExt.count(e))
  {
    return DataKind::Mesh;
  }
  if (e == ".vtk")
  {
    return LegacyKind(path);
  }
  if (e == ".pvd" || e == ".series")
  {
    TimeSeriesError(path);
  }
  throw Error("unknown file type '" + (e.empty() ? std::string("(none)") : e) +
      "' (volumes: .mha .mhd .nii .nii.gz .vti .pvti .nrrd or a DICOM folder; surfaces: .ply .obj "
      ".stl .vtp .pvtp; meshes: .vtu .vts .vtr, their parallel .pvtu .pvts .pvtr, .vtm; any of them: legacy .vtk)",
    path);
}

vtkSmartPointer<vtkImageData> LoadVolume(const std::string& path, const std::string& array)
{
  if (KindOf(path) != DataKind::Volume)
  {
    throw Error("is not a volume (expected .mha .mhd .nii .nii.gz .vti .pvti .nrrd, image data in .vtk, or a DICOM folder)",
      path);
  }
  std::error_code ec;
  const std::string e = LowerExtension(path);
  vtkSmartPointer<vtkAlgorithm> reader;
  std::unique_ptr<DicomLinkFolder> series; // lives until the reader has read
  if (fs::is_directory(path, ec))
  {
    if (!HasDicomFile(path))
    {
      throw Error("folder holds no readable DICOM series", path);
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
    reader = FileReader<vtkXMLImageDataReader>(path);
  }
  else if (e == ".pvti")
  {
    reader = FileReader<vtkXMLPImageDataReader>(path);
  }
  else if (e == ".vtk")
  {
    reader = FileReader<vtkDataSetReader>(path);
  }
  else
  {
    CheckNrrd(path);
    reader = FileReader<vtkNrrdReader>(path);
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
  if (vtkMetaImageReader::SafeDownCast(reader) && MetaImageDirection(path, direction))
  {
    img->SetDirectionMatrix(direction);
  }
  if (e == ".nrrd" || e == ".nhdr")
  {
    if (vtkDataArray* s = img->GetPointData()->GetScalars())
    {
      ReadNrrdText(path, s); // VTK read text data as zeros
    }
    img = PlaceNrrd(img, path);
  }
  if (auto* dicom = vtkDICOMImageReader::SafeDownCast(reader))
  {
    ApplyDicomGeometry(img, dicom);
  }
  if (auto* nifti = vtkNIFTIImageReader::SafeDownCast(reader))
  {
    ApplyRescale(img, nifti->GetRescaleSlope(), nifti->GetRescaleIntercept());
    PlaceNifti(img, nifti, path);
  }
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
      throw Error("has no one-component point array to take as the voxels (point arrays: " +
          ArrayNames({ img->GetPointData() }) + "; extract a component first)",
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

void RequireOneComponent(vtkImageData* volume, const std::string& path)
{
  vtkDataArray* s = volume->GetPointData()->GetScalars();
  if (const int nc = s ? s->GetNumberOfComponents() : 0; nc != 1)
  {
    throw Error("the scalars have " + std::to_string(nc) +
        " components; rendering needs one (pick a one-component array with --array, or extract a component)",
      path);
  }
}

vtkSmartPointer<vtkPolyData> LoadSurface(const std::string& path)
{
  if (KindOf(path) != DataKind::Surface)
  {
    throw Error("is not a surface (expected .ply .obj .stl .vtp .pvtp or polygons in .vtk)", path);
  }
  const std::string e = LowerExtension(path);
  vtkSmartPointer<vtkAlgorithm> reader;
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  std::vector<double> plyDoubles, plyColours;
  if (e == ".obj")
  {
    pd = ReadObj(path); // vtkOBJReader drops faces (see ObjReader.h)
  }
  else if (e == ".ply")
  {
    CheckPly(path, &plyDoubles, &plyColours);
    reader = FileReader<vtkPLYReader>(path);
  }
  else if (e == ".stl")
  {
    CheckStl(path);
    reader = FileReader<vtkSTLReader>(path);
  }
  else if (e == ".vtk")
  {
    reader = FileReader<vtkDataSetReader>(path);
  }
  else if (e == ".pvtp")
  {
    reader = FileReader<vtkXMLPPolyDataReader>(path);
  }
  else
  {
    reader = FileReader<vtkXMLPolyDataReader>(path);
  }
  if (reader)
  {
    RunReader(reader, path);
    pd->ShallowCopy(reader->GetOutputDataObject(0));
  }
  if (!plyDoubles.empty() && static_cast<vtkIdType>(plyDoubles.size()) == 3 * pd->GetNumberOfPoints())
  {
    // The file's double coordinates, not vtkPLYReader's floats (survey data far from the origin).
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(pd->GetNumberOfPoints());
    for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
    {
      points->SetPoint(i, &plyDoubles[3 * static_cast<std::size_t>(i)]);
    }
    pd->SetPoints(points);
  }
  if (!plyColours.empty() && static_cast<vtkIdType>(plyColours.size()) == 3 * pd->GetNumberOfPoints())
  {
    // Floating-point colours as written, not vtkPLYReader's 8-bit casts of them (1.0 read as 1
    // of 255, so a red mesh rendered black); 0..255 when any exceeds 1, else 0..1.
    const double hi = *std::max_element(plyColours.begin(), plyColours.end());
    const double scale = hi > 1 ? 1.0 / 255.0 : 1.0;
    vtkNew<vtkFloatArray> rgb;
    rgb->SetName("RGB");
    rgb->SetNumberOfComponents(3);
    rgb->SetNumberOfTuples(pd->GetNumberOfPoints());
    for (std::size_t i = 0; i < plyColours.size(); ++i)
    {
      const double v = plyColours[i] * scale;
      rgb->SetValue(static_cast<vtkIdType>(i), static_cast<float>(std::isfinite(v) ? std::clamp(v, 0.0, 1.0) : 0.0));
    }
    pd->GetPointData()->SetScalars(rgb);
  }
  if (pd->GetNumberOfPoints() == 0 || pd->GetNumberOfPolys() + pd->GetNumberOfStrips() == 0)
  {
    // A readable file of lines or points only ("empty or unreadable" sent users looking for damage).
    const vtkIdType lines = pd->GetNumberOfLines(), verts = pd->GetNumberOfVerts();
    throw Error(lines + verts > 0 ? "holds no polygons, only " + std::to_string(lines) + " lines and " +
          std::to_string(verts) + " vertices (surfaces are drawn from polygons and triangle strips)"
                                  : std::string("holds no polygons (empty or unreadable surface)"),
      path);
  }
  CheckPolyIndices(pd, path);
  return pd;
}

vtkSmartPointer<vtkUnstructuredGrid> LoadMesh(const std::string& path)
{
  if (KindOf(path) != DataKind::Mesh)
  {
    throw Error("is not a mesh (expected .vtu .vts .vtr .pvtu .pvts .pvtr .vtm, or a grid in .vtk)", path);
  }
  const std::string e = LowerExtension(path);
  vtkSmartPointer<vtkAlgorithm> reader;
  if (e == ".vtu")
  {
    reader = FileReader<vtkXMLUnstructuredGridReader>(path);
  }
  else if (e == ".vts")
  {
    reader = FileReader<vtkXMLStructuredGridReader>(path);
  }
  else if (e == ".vtr")
  {
    reader = FileReader<vtkXMLRectilinearGridReader>(path);
  }
  else if (e == ".pvtu")
  {
    reader = FileReader<vtkXMLPUnstructuredGridReader>(path);
  }
  else if (e == ".pvts")
  {
    reader = FileReader<vtkXMLPStructuredGridReader>(path);
  }
  else if (e == ".pvtr")
  {
    reader = FileReader<vtkXMLPRectilinearGridReader>(path);
  }
  else if (e == ".vtm")
  {
    reader = FileReader<vtkXMLMultiBlockDataReader>(path);
  }
  else
  {
    reader = FileReader<vtkDataSetReader>(path);
  }
  RunReader(reader, path);
  vtkSmartPointer<vtkUnstructuredGrid> ug = vtkUnstructuredGrid::SafeDownCast(reader->GetOutputDataObject(0));
  if (!ug)
  {
    // Structured and rectilinear grids become hexahedra (TetMesh tetrahedralises them); the
    // blocks of a multiblock file are appended into one grid (points shared between blocks are
    // merged later, by TetMesh).
    vtkNew<vtkAppendFilter> toUG;
    if (auto* blocks = vtkCompositeDataSet::SafeDownCast(reader->GetOutputDataObject(0)))
    {
      auto it = vtk::TakeSmartPointer(blocks->NewIterator());
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      {
        if (auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject()))
        {
          toUG->AddInputData(ds);
        }
      }
      if (toUG->GetNumberOfInputConnections(0) == 0)
      {
        throw Error("holds no data sets in its blocks", path);
      }
    }
    else if (auto* ds = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0)))
    {
      toUG->SetInputData(ds);
    }
    else
    {
      throw Error("does not hold a grid", path);
    }
    toUG->Update();
    ug = toUG->GetOutput();
  }
  auto copy = vtkSmartPointer<vtkUnstructuredGrid>::New();
  copy->ShallowCopy(ug);
  if (copy->GetCellData()->GetArray(vtkDataSetAttributes::GhostArrayName()))
  {
    // Pieces saved from a parallel run with ghost levels repeat their neighbours' boundary cells,
    // marked in vtkGhostType: appended, the copies overlapped and the mesh was refused
    // ("inconsistent neighbours ... (overlap)"). Each cell is kept once, where it is not a ghost,
    // and the marks go (a mesh without point scalars took them as its cell scalars).
    copy->RemoveGhostCells();
    copy->GetCellData()->RemoveArray(vtkDataSetAttributes::GhostArrayName());
  }
  if (copy->GetNumberOfCells() == 0)
  {
    throw Error("holds no cells (empty or unreadable mesh)", path);
  }
  return copy;
}

vtkSmartPointer<vtkDataObject> Load(const std::string& path, DataKind* kind)
{
  const DataKind k = KindOf(path);
  if (kind)
  {
    *kind = k;
  }
  switch (k)
  {
    case DataKind::Volume:
      return LoadVolume(path);
    case DataKind::Surface:
      return LoadSurface(path);
    default:
      return LoadMesh(path);
  }
}

void SaveMesh(vtkUnstructuredGrid* mesh, const std::string& path)
{
  if (LowerExtension(path) != ".vtu")
  {
    throw Error("meshes are written as .vtu", path);
  }
  AtomicFile file(path);
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(mesh);
  w->SetFileName(file.TempPath().c_str());
  w->SetDataModeToBinary();
  w->SetCompressorTypeToZLib();
  ErrorCatcher catcher(w);
  if (!w->Write() || !catcher.Message.empty())
  {
    throw Error("cannot write mesh: " + catcher.Message, path);
  }
  file.Commit();
}
} // namespace art
