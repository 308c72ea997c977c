#include "DataLoader.h"
#include "ArrayChoice.h"
#include "AtomicFile.h"
#include "Error.h"
#include "ObjReader.h"
#include "OtherFormats.h"
#include "PlyCheck.h"
#include "ReaderRun.h"
#include "StlCheck.h"
#include "XmlCheck.h"

#include <vtkAlgorithm.h>
#include <vtkAppendFilter.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDataSetAttributes.h>
#include <vtkDataSetReader.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFloatArray.h>
#include <vtkMatrix3x3.h>
#include <vtkStringArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkUnstructuredGrid.h>
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
#include <stdexcept>

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
// The reader's output against what the file's header promised (a cut binary .vtu read 730 of its
// cells as empty).
void RequireCount(vtkIdType got, long long promised, const char* what, const std::string& path)
{
  if (got != promised)
  {
    throw Error("holds " + std::to_string(got) + " " + what + " where its header promises " + std::to_string(promised) +
        " (damaged or cut short)",
      path);
  }
}

// A cell naming a point past the last (vertex 1e9 of 4096) crashed the renderers that trust it.
void CheckCellIndices(vtkUnstructuredGrid* ug, const std::string& path)
{
  vtkCellArray* cells = ug->GetCells();
  if (!cells || cells->GetNumberOfConnectivityIds() == 0)
  {
    return;
  }
  double r[2];
  cells->GetConnectivityArray()->GetRange(r, 0);
  if (r[0] < 0 || r[1] >= static_cast<double>(ug->GetNumberOfPoints()))
  {
    throw Error("a cell refers to point " + std::to_string(static_cast<long long>(r[0] < 0 ? r[0] : r[1])) + " of " +
        std::to_string(ug->GetNumberOfPoints()),
      path);
  }
}

// A multiblock file whose blocks are all polydata (.vtp, .pvtp: a CAD assembly or a surface
// ParaView extracted from blocks) is a triangle scene; any other is a mesh. Its XML lists the
// blocks' files, so the kind is known without reading them.
DataKind MultiBlockKind(const std::string& path)
{
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  static const std::regex fileAttr("\\bfile\\s*=\\s*\"([^\"]*)\"");
  bool any = false;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), fileAttr); it != std::sregex_iterator(); ++it)
  {
    const std::string e = LowerExtension((*it)[1].str());
    if (e != ".vtp" && e != ".pvtp")
    {
      return DataKind::Mesh;
    }
    any = true;
  }
  return any ? DataKind::Surface : DataKind::Mesh;
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
  return KindOf(path, LoadOptions());
}

DataKind KindOf(const std::string& path, const LoadOptions& options)
{
  const std::string e = LowerExtension(path);
  if (options.Raw.Given())
  {
    RequireFile(path, false);
    return DataKind::Volume;
  }
  if (path.find('%') != std::string::npos && !ImageStack(path).empty())
  {
    return DataKind::Volume; // a pattern of slices
  }
  RequireFile(path, true);
  std::error_code ec;
  if (fs::is_directory(path, ec))
  {
    if (!e.empty() && ImageStack(path).empty())
    {
      throw Error("is a directory, expected a file", path);
    }
    return DataKind::Volume; // a DICOM series or a stack of slices
  }
  if (VolumeExt.count(e) || IsOtherVolume(e))
  {
    return DataKind::Volume;
  }
  if (SurfaceExt.count(e) || IsOtherSurface(e))
  {
    return DataKind::Surface;
  }
  if (e == ".vtm")
  {
    return MultiBlockKind(path);
  }
  if (MeshExt.count(e) || IsOtherMesh(e))
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
  if (e == ".png" || e == ".jpg" || e == ".jpeg" || e == ".bmp" || e == ".pgm" || e == ".ppm")
  {
    throw Error("is a 2-D image, not a volume: give the folder of its slices, or a pattern such as slice%03d" + e +
        " (with --raw-spacing X,Y,Z for their spacing)",
      path);
  }
  const InputFormatList f = InputFormats();
  throw Error("unknown file type '" + (e.empty() ? std::string("(none)") : e) + "' (volumes: " + f.volumes +
      "; surfaces: " + f.surfaces + "; meshes: " + f.meshes + "; any of them: " + f.any + ")",
    path);
}

InputFormatList InputFormats()
{
  // One list for every program's help and errors: keep it in step with KindOf.
  return { ".mha .mhd .nii .nii.gz .vti .pvti .nrrd .nhdr .slc .mnc .pic .mrc .hdr/.img .tif, a DICOM folder, "
           "a folder or pattern of image slices, raw with --raw-dims",
    ".ply .obj .stl .vtp .pvtp .g .facet", ".vtu .vts .vtr .pvtu .pvts .pvtr .vtm .exo .inp .tec .neu", "legacy .vtk" };
}

vtkSmartPointer<vtkPolyData> LoadSurface(const std::string& path)
{
  if (KindOf(path) != DataKind::Surface)
  {
    throw Error("is not a surface (expected .ply .obj .stl .vtp .pvtp, a .vtm of .vtp blocks, or polygons in .vtk)", path);
  }
  const std::string e = LowerExtension(path);
  vtkSmartPointer<vtkAlgorithm> reader;
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  std::vector<double> plyDoubles, plyColours;
  XmlCounts promised;
  promised.Complete = false;
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
    reader = LegacyReader(path);
  }
  else if (e == ".pvtp")
  {
    CheckVtkXml(path);
    reader = FileReader<vtkXMLPPolyDataReader>(path);
  }
  else if (e == ".vtm")
  {
    CheckVtkXml(path);
    reader = FileReader<vtkXMLMultiBlockDataReader>(path);
  }
  else if (e == ".vtp")
  {
    promised = CheckVtkXml(path);
    reader = FileReader<vtkXMLPolyDataReader>(path);
  }
  else
  {
    reader = OtherSurfaceReader(path);
  }
  if (reader)
  {
    RunReader(reader, path);
    if (auto* blocks = vtkCompositeDataSet::SafeDownCast(reader->GetOutputDataObject(0)))
    {
      // Every block's polygons in one scene (their arrays kept where all blocks have them).
      vtkNew<vtkAppendPolyData> all;
      auto it = vtk::TakeSmartPointer(blocks->NewIterator());
      for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
      {
        if (auto* block = vtkPolyData::SafeDownCast(it->GetCurrentDataObject()))
        {
          all->AddInputData(block);
        }
      }
      if (all->GetNumberOfInputConnections(0) > 0)
      {
        all->Update();
        pd->ShallowCopy(all->GetOutput());
      }
    }
    else
    {
      pd->ShallowCopy(reader->GetOutputDataObject(0));
    }
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
  if (promised.Complete)
  {
    RequireCount(pd->GetNumberOfPoints(), promised.Points, "points", path);
    RequireCount(pd->GetNumberOfPolys(), promised.Polys, "polygons", path);
    RequireCount(pd->GetNumberOfStrips(), promised.Strips, "triangle strips", path);
  }
  CheckPolyIndices(pd, path);
  RecordPlacement(pd, "file coordinates");
  return pd;
}

std::string AddComponentArray(vtkDataSet* data, const std::string& array, const std::string& path)
{
  int component;
  const std::string name = SplitComponent(array, &component);
  if (component == WholeArray)
  {
    return array;
  }
  vtkDataSetAttributes* where = data->GetPointData();
  vtkDataArray* a = ChooseArray(where, name, true);
  if (!a)
  {
    where = data->GetCellData();
    a = ChooseArray(where, name, true);
  }
  if (!a)
  {
    throw Error("has no point or cell array '" + name + "' (it has: " +
        ArrayNames({ data->GetPointData(), data->GetCellData() }) + ")",
      path);
  }
  try
  {
    vtkSmartPointer<vtkDataArray> one = TakeComponent(a, component);
    where->AddArray(one);
    return one->GetName();
  }
  catch (const Error& e)
  {
    throw Error(e.problem(), path);
  }
}

vtkSmartPointer<vtkUnstructuredGrid> LoadMesh(const std::string& path)
{
  if (KindOf(path) != DataKind::Mesh)
  {
    throw Error("is not a mesh (expected .vtu .vts .vtr .pvtu .pvts .pvtr .vtm, or a grid in .vtk)", path);
  }
  const std::string e = LowerExtension(path);
  vtkSmartPointer<vtkAlgorithm> reader;
  XmlCounts promised;
  promised.Complete = false;
  if (e == ".vtu")
  {
    promised = CheckVtkXml(path);
    reader = FileReader<vtkXMLUnstructuredGridReader>(path);
  }
  else if (e == ".vts")
  {
    CheckVtkXml(path);
    reader = FileReader<vtkXMLStructuredGridReader>(path);
  }
  else if (e == ".vtr")
  {
    CheckVtkXml(path);
    reader = FileReader<vtkXMLRectilinearGridReader>(path);
  }
  else if (e == ".pvtu")
  {
    CheckVtkXml(path);
    reader = FileReader<vtkXMLPUnstructuredGridReader>(path);
  }
  else if (e == ".pvts")
  {
    CheckVtkXml(path);
    reader = FileReader<vtkXMLPStructuredGridReader>(path);
  }
  else if (e == ".pvtr")
  {
    CheckVtkXml(path);
    reader = FileReader<vtkXMLPRectilinearGridReader>(path);
  }
  else if (e == ".vtm")
  {
    CheckVtkXml(path);
    reader = FileReader<vtkXMLMultiBlockDataReader>(path);
  }
  else if (e == ".vtk")
  {
    reader = LegacyReader(path);
  }
  else
  {
    reader = OtherMeshReader(path);
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
  if (promised.Complete)
  {
    RequireCount(copy->GetNumberOfPoints(), promised.Points, "points", path);
    RequireCount(copy->GetNumberOfCells(), promised.Cells, "cells", path);
  }
  CheckCellIndices(copy, path);
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
  if (!copy->GetFieldData()->GetArray("IndexToWorld"))
  {
    RecordPlacement(copy, "file coordinates"); // a reduced mesh keeps its volume's
  }
  return copy;
}

vtkSmartPointer<vtkDataObject> Load(const std::string& path, DataKind* kind)
{
  return Load(path, LoadOptions(), kind);
}

vtkSmartPointer<vtkDataObject> Load(const std::string& path, const LoadOptions& options, DataKind* kind)
{
  const DataKind k = KindOf(path, options);
  if (kind)
  {
    *kind = k;
  }
  switch (k)
  {
    case DataKind::Volume:
      return LoadVolume(path, options);
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
  if (!w->Write() || !catcher.Message.empty() || w->GetErrorCode() != vtkErrorCode::NoError)
  {
    // The executive's failure names no cause (a dump of its request followed): say the writer's.
    const unsigned long code = w->GetErrorCode();
    throw Error(code == vtkErrorCode::OutOfDiskSpaceError ? std::string("cannot write mesh: no space left on device")
        : !catcher.Message.empty() && !ErrorCatcher::IsRequestDump(catcher.Message) ? "cannot write mesh: " + catcher.Message
        : std::string("cannot write mesh: ") + vtkErrorCode::GetStringFromErrorCode(code),
      path);
  }
  file.Commit();
}
} // namespace art
