// TetMesh's builders from VTK data: full-resolution tets of an image (five per voxel cell) and
// the tets of any vtkUnstructuredGrid (other cells tetrahedralised, cell data moved to points,
// unused and duplicate points removed), with the checks that name the file.
#include "TetMesh.h"
#include "SourceStatistics.h"
#include "ArrayChoice.h"
#include "AvailableMemory.h"

#include "Error.h"
#include "ValueMagnitude.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellDataToPointData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDataSetTriangleFilter.h>
#include <vtkFieldData.h>
#include <vtkGenericCell.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <tuple>

namespace art
{
void TetMesh::CheckFullResolutionFits(long long tets, double availableBytes, const std::string& file)
{
  if (tets >= (1LL << 29))
  {
    throw Error("volume too large for full-resolution tets (" + std::to_string(tets) +
        " tets, at most 2^29); reduce it first (--tets N or --max-error E)",
      file);
  }
  // About 160 bytes per tet with its share of the vertices (measured: 660 MB for the 4.3 M tets of
  // the 128 x 128 x 54 CT). Past the memory available the build would be killed without a word.
  const double need = 160.0 * tets;
  if (ExceedsAvailableMemory(need, availableBytes))
  {
    char msg[200];
    std::snprintf(msg, sizeof msg,
      "full-resolution tets of this volume (%lld) need about %.3g GB, more than the %.3g GB of memory available; "
      "reduce it first (--tets N or --max-error E)",
      tets, need / 1e9, availableBytes / 1e9);
    throw Error(msg, file);
  }
}

void TetMesh::CheckMeshFits(long long tets, double availableBytes, const std::string& file)
{
  const double need = 200.0 * tets;
  if (ExceedsAvailableMemory(need, availableBytes))
  {
    char msg[300];
    std::snprintf(msg, sizeof msg,
      "its cells make about %lld tets, which need about %.3g GB, more than the %.3g GB of memory available; "
      "render a part of it first (e.g. ParaView's Extract Cells By Region, Clip or Threshold)",
      tets, need / 1e9, availableBytes / 1e9);
    throw Error(msg, file);
  }
}

TetMesh TetMesh::FromImage(vtkImageData* image, const std::string& file)
{
  vtkDataArray* s = image ? image->GetPointData()->GetScalars() : nullptr;
  int d[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(d);
  }
  if (!s)
  {
    throw Error("volume has no point scalars", file);
  }
  if (d[0] < 2 || d[1] < 2 || d[2] < 2)
  {
    throw Error("volume of " + std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " + std::to_string(d[2]) +
        " voxels has no cells to tetrahedralise (at least 2 x 2 x 2 voxels are needed)",
      file);
  }
  const long long np = static_cast<long long>(d[0]) * d[1] * d[2];
  if (s->GetNumberOfTuples() < np)
  {
    // Read past its end otherwise (scalars set by hand on an image of other dimensions).
    throw Error("the volume's scalars hold " + std::to_string(s->GetNumberOfTuples()) + " values for " +
        std::to_string(d[0]) + " x " + std::to_string(d[1]) + " x " + std::to_string(d[2]) + " voxels",
      file);
  }
  const long long nt = 5 * (d[0] - 1LL) * (d[1] - 1) * (d[2] - 1);
  CheckFullResolutionFits(nt, AvailableMemoryBytes(), file);
  std::vector<Vec3> pts(np);
  std::vector<double> val(np);
  const int* e = image->GetExtent(); // indices start at the extent's first corner
  for (int k = 0, id = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i, ++id)
      {
        double p[3];
        image->TransformContinuousIndexToPhysicalPoint(e[0] + i, e[2] + j, e[4] + k, p); // origin, spacing, direction
        pts[id] = Vec3(p);
        val[id] = s->GetComponent(id, 0);
      }
  // A voxel's own words (its index) rather than the mesh's "point N has a non-finite ...".
  const int first[3] = { e[0], e[2], e[4] };
  RequireFiniteVoxels(val, d, first, file);
  const auto [lo, hi] = std::minmax_element(val.begin(), val.end());
  RequireComputableRange(*lo, *hi, file);
  static const int five[5][4] = { { 0, 1, 2, 4 }, { 3, 1, 2, 7 }, { 5, 1, 4, 7 }, { 6, 2, 4, 7 }, { 1, 2, 4, 7 } };
  std::vector<std::array<int, 4>> tets;
  tets.reserve(5 * (d[0] - 1LL) * (d[1] - 1) * (d[2] - 1));
  for (int k = 0; k + 1 < d[2]; ++k)
    for (int j = 0; j + 1 < d[1]; ++j)
      for (int i = 0; i + 1 < d[0]; ++i)
      {
        int c[8];
        for (int b = 0; b < 8; ++b)
        {
          c[b] = ((k + ((b >> 2) & 1)) * d[1] + j + ((b >> 1) & 1)) * d[0] + i + (b & 1);
        }
        const int flip = (i + j + k) & 1; // mirror odd cells in x so shared face diagonals agree
        for (const auto& t : five)
        {
          tets.push_back({ c[t[0] ^ flip], c[t[1] ^ flip], c[t[2] ^ flip], c[t[3] ^ flip] });
        }
      }
  try
  {
    return TetMesh(std::move(pts), std::move(val), std::move(tets));
  }
  catch (const Error& e)
  {
    throw Error(e.problem(), file);
  }
}

namespace
{
// Keeps the points with to[i] == i, in input order, and renumbers each tet's ids i through to[i]
// (a kept point); ids out of range stay, for the constructor to name.
void KeepPoints(std::vector<Vec3>& pts, std::vector<double>& val, std::vector<std::array<int, 4>>& tets,
  const std::vector<int>& to)
{
  const std::size_t np = pts.size();
  std::vector<int> index(np, -1);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < np; ++i)
  {
    if (to[i] == static_cast<int>(i))
    {
      index[i] = static_cast<int>(kept);
      pts[kept] = pts[i], val[kept] = val[i];
      ++kept;
    }
  }
  pts.resize(kept), val.resize(kept);
  for (auto& t : tets)
  {
    for (int& id : t)
    {
      id = id >= 0 && id < static_cast<int>(np) ? index[to[id]] : id;
    }
  }
}

// Points no tet uses (left over by a clip or threshold filter, or stray) are dropped, in order:
// they would widen the bounds a camera frames, and a NaN among them would refuse the mesh.
// Returns how many went; ids out of range are left for the constructor to name.
std::size_t DropUnusedPoints(std::vector<Vec3>& pts, std::vector<double>& val, std::vector<std::array<int, 4>>& tets)
{
  const std::size_t np = pts.size();
  std::vector<int> to(np, -1);
  for (const auto& t : tets)
  {
    for (int v : t)
    {
      if (v < 0 || static_cast<std::size_t>(v) >= np)
      {
        return 0;
      }
      to[v] = v;
    }
  }
  const std::size_t dropped = static_cast<std::size_t>(std::count(to.begin(), to.end(), -1));
  if (dropped > 0)
  {
    KeepPoints(pts, val, tets, to);
  }
  return dropped;
}

// Points equal in position and scalar become one (exported meshes often give every cell its own
// points). Without shared faces each tet would be a piece of its own, found through the boundary
// grid at every step; points that differ in the scalar (a field discontinuous across a face) stay
// apart. Returns how many points went.
std::size_t MergeDuplicatePoints(std::vector<Vec3>& pts, std::vector<double>& val, std::vector<std::array<int, 4>>& tets)
{
  const std::size_t np = pts.size();
  for (std::size_t i = 0; i < np; ++i)
  {
    if (!IsFinite(pts[i]) || !std::isfinite(val[i]))
    {
      return 0; // no order to sort by; the constructor names the point
    }
  }
  std::vector<int> order(np);
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](int i) { return std::make_tuple(pts[i].x, pts[i].y, pts[i].z, val[i]); };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return key(a) != key(b) ? key(a) < key(b) : a < b; });
  std::vector<int> to(np);
  std::size_t merged = 0;
  for (std::size_t k = 0; k < np; ++k)
  {
    const bool same = k > 0 && key(order[k]) == key(order[k - 1]);
    to[order[k]] = same ? to[order[k - 1]] : order[k];
    merged += same ? 1 : 0;
  }
  if (merged == 0)
  {
    return 0;
  }
  KeepPoints(pts, val, tets, to); // the first of each group
  return merged;
}

// Flat tets (four points in one plane, to within rounding against the tet's own longest edge)
// with a face that more than two tets share are left out: a clip through grid points
// (vtkTableBasedClipDataSet, ParaView's Clip) leaves stacks of such pieces on its plane, and the
// walk refused the mesh ('a face of tet 0 is shared by 5 tets'). Other flat tets stay: in a
// Delaunay mesh of lattice points one links the two tets beside it. Returns how many went.
std::size_t DropFlatTets(const std::vector<Vec3>& pts, std::vector<std::array<int, 4>>& tets)
{
  auto flat = [&](const std::array<int, 4>& t) {
    for (int v : t)
    {
      if (v < 0 || static_cast<std::size_t>(v) >= pts.size() || !IsFinite(pts[v]))
      {
        return false; // the constructor names it
      }
    }
    const Vec3 a = pts[t[1]] - pts[t[0]], b = pts[t[2]] - pts[t[0]], c = pts[t[3]] - pts[t[0]];
    const double edge =
      std::sqrt(std::max({ Dot(a, a), Dot(b, b), Dot(c, c), Dot(b - a, b - a), Dot(c - a, c - a), Dot(c - b, c - b) }));
    return std::fabs(Dot(a, Cross(b, c))) <= 1e-10 * edge * edge * edge;
  };
  using Face = std::array<int, 3>;
  auto faceOf = [](const std::array<int, 4>& t, int k) {
    Face f{ t[(k + 1) % 4], t[(k + 2) % 4], t[(k + 3) % 4] };
    std::sort(f.begin(), f.end());
    return f;
  };
  // Only the flat tets' faces are counted: a mesh without flat tets costs one pass.
  std::vector<Face> faces;
  for (const auto& t : tets)
  {
    if (flat(t))
    {
      for (int k = 0; k < 4; ++k)
      {
        faces.push_back(faceOf(t, k));
      }
    }
  }
  if (faces.empty())
  {
    return 0;
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  std::vector<int> count(faces.size(), 0);
  auto find = [&](const Face& f) { return std::lower_bound(faces.begin(), faces.end(), f); };
  for (const auto& t : tets)
  {
    for (int k = 0; k < 4; ++k)
    {
      const Face f = faceOf(t, k);
      const auto it = find(f);
      if (it != faces.end() && *it == f)
      {
        ++count[it - faces.begin()];
      }
    }
  }
  const std::size_t before = tets.size();
  tets.erase(std::remove_if(tets.begin(), tets.end(),
               [&](const std::array<int, 4>& t) {
                 if (!flat(t))
                 {
                   return false;
                 }
                 for (int k = 0; k < 4; ++k)
                 {
                   if (count[find(faceOf(t, k)) - faces.begin()] > 2)
                   {
                     return true;
                   }
                 }
                 return false;
               }),
    tets.end());
  return before - tets.size();
}
// The range of the volume a reducer's output approximates (its field data scalar_range_min/max),
// when `scalars` still look like that reduction (StillTheSource: the fit's overshoot allowed); a
// filter that rescaled or thresholded them keeps its own.
bool SourceRange(vtkUnstructuredGrid* grid, vtkDataArray* scalars, double range[2])
{
  vtkFieldData* fd = grid->GetFieldData();
  vtkDataArray* lo = fd ? fd->GetArray("scalar_range_min") : nullptr;
  vtkDataArray* hi = fd ? fd->GetArray("scalar_range_max") : nullptr;
  if (!lo || !hi || lo->GetNumberOfTuples() < 1 || hi->GetNumberOfTuples() < 1)
  {
    return false;
  }
  range[0] = lo->GetComponent(0, 0);
  range[1] = hi->GetComponent(0, 0);
  return std::isfinite(range[0]) && std::isfinite(range[1]) && range[1] >= range[0] &&
    StillTheSource(range[0], range[1], scalars->GetNumberOfTuples(), [scalars](long long i) { return scalars->GetComponent(i, 0); });
}

// A vector (or other multi-component) array is one error naming how to choose a component.
void CheckOneComponent(vtkDataArray* a, const char* kind, const std::string& file)
{
  if (a->GetNumberOfComponents() != 1)
  {
    throw Error(std::string(kind) + " array '" + (a->GetName() ? a->GetName() : "") + "' has " +
        std::to_string(a->GetNumberOfComponents()) + " components; rendering needs one (choose with --array " +
        ComponentHint(a) + ", or another array)",
      file);
  }
}

// An array shorter than its points or cells (built by hand: SetNumberOfTuples forgotten or wrong)
// was read past its end: garbage values, reported as 'point 31 has a non-finite coordinate or
// scalar', or a crash.
void CheckLength(vtkDataArray* a, const char* kind, vtkIdType count, const std::string& file)
{
  if (a->GetNumberOfTuples() < count)
  {
    throw Error(std::string(kind) + " array '" + (a->GetName() ? a->GetName() : "") + "' holds " +
        std::to_string(a->GetNumberOfTuples()) + " values for " + std::to_string(count) + " " + kind + "s",
      file);
  }
}
} // namespace

TetMesh TetMesh::FromVTK(vtkUnstructuredGrid* grid, const std::string& array, std::string* note, const std::string& file)
{
  if (!grid || grid->GetNumberOfCells() == 0)
  {
    throw Error("mesh has no cells", file);
  }
  // A surface or a line set saved as a grid has nothing to cast through: say what it holds.
  // Cells of lower dimension beside 3-D ones are left out, with a note.
  vtkIdType lower = 0;
  bool low[256] = {}; // by cell type: of lower dimension than 3
  {
    // The distinct cell types by a scan (GetCellTypes(vtkCellTypes*) is deprecated in VTK 9.2,
    // its successor missing in 9.1).
    bool seen[256] = {};
    for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
    {
      seen[grid->GetCellType(c)] = true;
    }
    bool anyLower = false;
    vtkNew<vtkGenericCell> cell;
    for (int type = 0; type < 256; ++type)
    {
      if (!seen[type])
      {
        continue;
      }
      cell->SetCellType(type);
      low[type] = cell->GetCellDimension() < 3;
      anyLower = anyLower || low[type];
    }
    for (vtkIdType c = 0; anyLower && c < grid->GetNumberOfCells(); ++c)
    {
      lower += low[grid->GetCellType(c)] ? 1 : 0;
    }
  }
  if (lower == grid->GetNumberOfCells())
  {
    throw Error("holds no 3-D cells (its " + std::to_string(lower) +
        " cells are surface, line or vertex cells): a tet mesh is needed; a surface renders from .vtp, .ply, .obj or .stl",
      file);
  }
  // The scalars are chosen, and cell scalars averaged to the points, on the cells as given: after
  // tetrahedralising, a cell's weight at a corner would depend on how many tets it became.
  vtkSmartPointer<vtkUnstructuredGrid> ug = grid;
  std::string notes = lower > 0 ? std::to_string(lower) + " cells that are not 3-D were left out" : "";
  vtkDataArray* s = ChooseArray(ug->GetPointData(), array);
  if (!s)
  {
    // Cell scalars (common in simulation output) are averaged to the points by VTK's
    // vtkCellDataToPointData, since the walk interpolates linearly inside each tet.
    vtkCellData* cd = ug->GetCellData();
    vtkDataArray* cs = ChooseArray(cd, array);
    if (!cs || !cs->GetName())
    {
      throw Error(array.empty() ? "mesh has no point or cell scalars"
                                : "mesh has no point or cell array '" + array + "' (it has: " +
            ArrayNames({ ug->GetPointData(), cd }) + ")",
        file);
    }
    CheckOneComponent(cs, "cell", file);
    CheckLength(cs, "cell", ug->GetNumberOfCells(), file);
    // A NaN cell (a masked or failed cell of a simulation) spread to its corners and was reported
    // as points holding NaN, in a mesh whose points hold no data at all.
    long long badCells = 0;
    vtkIdType firstBad = -1;
    for (vtkIdType c = 0; c < ug->GetNumberOfCells(); ++c)
    {
      if (!low[ug->GetCellType(c)] && !std::isfinite(cs->GetComponent(c, 0)))
      {
        firstBad = badCells++ == 0 ? c : firstBad;
      }
    }
    if (badCells > 0)
    {
      throw Error("cell array '" + std::string(cs->GetName()) + "' holds NaN or infinite values in " +
          std::to_string(badCells) + (badCells > 1 ? " cells" : " cell") + " (the first: cell " +
          std::to_string(firstBad) + "); rendering needs finite values: replace them (e.g. ParaView's Calculator, "
          "numpy.nan_to_num) or cut those cells away (ParaView's Threshold)",
        file);
    }
    vtkNew<vtkCellDataToPointData> toPoints;
    toPoints->SetInputData(ug);
    toPoints->ProcessAllArraysOff();
    toPoints->AddCellDataArray(cs->GetName());
    toPoints->Update();
    const std::string name = cs->GetName();
    ug = vtkUnstructuredGrid::SafeDownCast(toPoints->GetOutput());
    s = ug->GetPointData()->GetArray(name.c_str());
    notes += (notes.empty() ? "" : "; ") + ("cell scalars '" + name + "' were averaged to the points");
  }
  CheckOneComponent(s, "point", file);
  CheckLength(s, "point", ug->GetNumberOfPoints(), file);
  double source[2];
  const bool fromVolume = s == grid->GetPointData()->GetScalars() && SourceRange(grid, s, source);
  // Only 3-D cells other than tets need tetrahedralising; lower cells beside tets (ParaView's
  // output often has some) are skipped below, not worth a pass of the triangle filter over every tet.
  vtkIdType solids = 0, tetCells = 0;
  long long tetsAhead = 0; // tets once tetrahedralised: a hexahedron makes up to 6, a wedge 3
  {
    vtkNew<vtkGenericCell> cell;
    int dimension[256];
    std::fill(dimension, dimension + 256, -1);
    for (vtkIdType c = 0; c < ug->GetNumberOfCells(); ++c)
    {
      const unsigned char type = ug->GetCellType(c);
      if (dimension[type] < 0)
      {
        cell->SetCellType(type);
        dimension[type] = cell->GetCellDimension();
      }
      tetCells += type == VTK_TETRA ? 1 : 0;
      solids += dimension[type] == 3 ? 1 : 0;
      tetsAhead += dimension[type] != 3 ? 0
        : type == VTK_TETRA                                  ? 1
        : type == VTK_PYRAMID                                ? 2
        : type == VTK_WEDGE                                  ? 3
        : type == VTK_HEXAHEDRON || type == VTK_VOXEL        ? 6
                                                             : 12; // quadratic and polyhedral cells
    }
  }
  // A mesh too large for the memory left was killed by the system half-way through the triangle
  // filter or the engine's arrays.
  CheckMeshFits(tetsAhead, AvailableMemoryBytes(), file);
  if (tetCells < solids)
  {
    // The chosen array rides through as the active scalars.
    auto withScalars = vtkSmartPointer<vtkUnstructuredGrid>::New();
    withScalars->ShallowCopy(ug);
    withScalars->GetPointData()->SetScalars(s);
    vtkNew<vtkDataSetTriangleFilter> tri;
    tri->SetInputData(withScalars);
    tri->TetrahedraOnlyOn();
    tri->Update();
    ug = tri->GetOutput();
    notes = "non-tetrahedral cells were tetrahedralised (" + std::to_string(solids) + " 3-D cells -> " +
      std::to_string(ug->GetNumberOfCells()) + " tets)" + (notes.empty() ? "" : "; " + notes);
    if (ug->GetNumberOfCells() == 0)
    {
      throw Error("mesh has no 3D cells to tetrahedralise", file);
    }
    s = ug->GetPointData()->GetScalars();
  }
  if (note)
  {
    *note += std::string(note->empty() || notes.empty() ? "" : "; ") + notes;
  }
  const vtkIdType np = ug->GetNumberOfPoints();
  std::vector<Vec3> pts(np);
  std::vector<double> val(np);
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    ug->GetPoint(i, p);
    pts[i] = Vec3(p);
    val[i] = s->GetComponent(i, 0);
  }
  std::vector<std::array<int, 4>> tets;
  tets.reserve(ug->GetNumberOfCells());
  vtkIdType n;
  const vtkIdType* ids;
  for (vtkIdType c = 0; c < ug->GetNumberOfCells(); ++c)
  {
    if (ug->GetCellType(c) != VTK_TETRA)
    {
      continue;
    }
    ug->GetCellPoints(c, n, ids);
    tets.push_back({ static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]),
      static_cast<int>(ids[3]) });
  }
  std::size_t unused = DropUnusedPoints(pts, val, tets);
  const std::size_t merged = MergeDuplicatePoints(pts, val, tets);
  // After the merge: a clip's points on its plane repeat the grid's, and only merged do the
  // flat pieces' faces show as shared.
  const std::size_t flat = DropFlatTets(pts, tets);
  if (flat > 0)
  {
    unused += DropUnusedPoints(pts, val, tets);
  }
  if (flat > 0 && note)
  {
    *note += std::string(note->empty() ? "" : "; ") + std::to_string(flat) +
      " flat tets (no volume, as a clip through grid points leaves) were left out";
  }
  if (unused > 0 && note)
  {
    *note += std::string(note->empty() ? "" : "; ") + std::to_string(unused) + " points no tet uses were dropped";
  }
  if (merged > 0 && note)
  {
    *note += std::string(note->empty() ? "" : "; ") + std::to_string(merged) +
      " duplicate points (same position and scalar) were merged, so their tets share faces";
  }
  try
  {
    TetMesh mesh(std::move(pts), std::move(val), std::move(tets));
    // Values of 1e300 or 1e-310 crashed the transfer function's table (range scaled to inf).
    RequireComputableRange(mesh.ScalarRange(0), mesh.ScalarRange(1), file);
    if (fromVolume)
    {
      mesh.Range[0] = source[0];
      mesh.Range[1] = source[1];
    }
    return mesh;
  }
  catch (const Error& e)
  {
    throw Error(e.problem(), file);
  }
}
} // namespace art
