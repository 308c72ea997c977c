#include "vtkTriangleGridLocator.h"

#include "Accelerator.h"
#include "Error.h"

#include <vtkCell.h>
#include <vtkCellArray.h>
#include <vtkCellType.h>
#include <vtkGenericCell.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkTriangleGridLocator);

namespace
{
// VTK's line queries take a segment p1 -> p2 with t in [0, 1]: the ray from p1 along p2 - p1,
// in the engine's coordinates (taken from `origin`; t is the same in both).
art::Ray SegmentRay(const double p1[3], const double p2[3], const double origin[3])
{
  art::Ray r;
  r.org = art::Vec3(p1) - art::Vec3(origin);
  r.dir = art::Vec3(p2) - art::Vec3(p1);
  r.tmin = 0;
  r.tmax = 1;
  return r;
}

// Any other data set (an unstructured grid of triangles from a clip, a one-slice image of pixels)
// as a polydata of its 2-D cells, `original` naming each cell's id in `ds` (polygons first, then
// strips, as vtkPolyData numbers them). Vertices and lines are counted in `others`, 3-D cells in
// `solids`; neither is added.
vtkSmartPointer<vtkPolyData> SurfaceOf(
  vtkDataSet* ds, std::vector<vtkIdType>& original, vtkIdType& others, vtkIdType& solids)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->SetNumberOfPoints(ds->GetNumberOfPoints());
  for (vtkIdType i = 0; i < ds->GetNumberOfPoints(); ++i)
  {
    pts->SetPoint(i, ds->GetPoint(i));
  }
  pd->SetPoints(pts);
  vtkNew<vtkCellArray> polys, strips;
  std::vector<vtkIdType> stripIds;
  vtkNew<vtkGenericCell> cell;
  others = solids = 0;
  for (vtkIdType c = 0; c < ds->GetNumberOfCells(); ++c)
  {
    ds->GetCell(c, cell);
    vtkIdList* ids = cell->GetPointIds();
    const int type = cell->GetCellType();
    if (cell->GetCellDimension() == 3)
    {
      ++solids;
    }
    else if (cell->GetCellDimension() < 2 || type == VTK_EMPTY_CELL)
    {
      others += type == VTK_EMPTY_CELL ? 0 : 1;
    }
    else if (type == VTK_TRIANGLE_STRIP)
    {
      strips->InsertNextCell(ids);
      stripIds.push_back(c);
    }
    else if (type == VTK_PIXEL)
    {
      // A pixel's corners go row by row; a quad's go round.
      const vtkIdType q[4] = { ids->GetId(0), ids->GetId(1), ids->GetId(3), ids->GetId(2) };
      polys->InsertNextCell(4, q);
      original.push_back(c);
    }
    else
    {
      // Triangles, quads, polygons; a quadratic cell by its corners (the first, linear, points).
      const vtkIdType corners = cell->IsLinear() ? ids->GetNumberOfIds() : cell->GetNumberOfEdges();
      polys->InsertNextCell(corners, ids->GetPointer(0));
      original.push_back(c);
    }
  }
  pd->SetPolys(polys);
  pd->SetStrips(strips);
  original.insert(original.end(), stripIds.begin(), stripIds.end());
  return pd;
}
} // namespace

vtkTriangleGridLocator::vtkTriangleGridLocator() = default;
vtkTriangleGridLocator::~vtkTriangleGridLocator() = default;

void vtkTriangleGridLocator::FreeSearchStructure()
{
  this->Engine.reset();
  this->Built = false;
}

void vtkTriangleGridLocator::BuildLocator()
{
  // A failed build counts as built too, so a dataset without polygons gives one error, not one per query.
  if (this->Built && this->BuildTime > this->MTime &&
    (!this->DataSet || this->BuildTime > this->DataSet->GetMTime()))
  {
    return;
  }
  // Kept only over a data set with as many cells as it was built over: one with fewer had its
  // cell ids past its end handed to GetCell (vtkStaticCellLocator rebuilds there too).
  if (this->Engine && this->UseExistingSearchStructure && this->DataSet &&
    this->DataSet->GetNumberOfCells() == this->BuiltCells)
  {
    this->BuildTime.Modified();
    return;
  }
  this->BuildLocatorInternal();
}

void vtkTriangleGridLocator::ForceBuildLocator()
{
  this->BuildLocatorInternal();
}

void vtkTriangleGridLocator::BuildLocatorInternal()
{
  this->FreeSearchStructure();
  this->Built = true;
  this->BuildTime.Modified();
  this->OriginalIds.clear();
  this->BuiltCells = this->DataSet ? this->DataSet->GetNumberOfCells() : -1;
  if (!this->DataSet)
  {
    vtkErrorMacro(<< "no dataset to locate in");
    return;
  }
  vtkSmartPointer<vtkPolyData> pd = vtkPolyData::SafeDownCast(this->DataSet);
  vtkIdType others = 0;
  if (pd)
  {
    others = pd->GetNumberOfVerts() + pd->GetNumberOfLines();
  }
  else
  {
    // Any data set's surface cells, as vtkCellLocator takes them (it said 'needs a vtkPolyData').
    vtkIdType solids = 0;
    pd = SurfaceOf(this->DataSet, this->OriginalIds, others, solids);
    if (solids > 0)
    {
      vtkErrorMacro(<< "the " << this->DataSet->GetClassName() << " has " << solids
                    << " 3-D cells; this locator finds surfaces (extract one first, e.g. with vtkGeometryFilter)");
      this->OriginalIds.clear();
      return;
    }
  }
  if (pd->GetNumberOfPolys() + pd->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro(<< "the dataset has no polygons or triangle strips to locate (" << this->DataSet->GetNumberOfCells()
                  << " cells: " << others << " vertex or line)");
    return;
  }
  if (others > 0)
  {
    vtkWarningMacro(<< others << " vertex and line cells are ignored: only polygons and strips are located");
  }
  try
  {
    double b[6];
    pd->GetBounds(b);
    double largest = 0;
    for (double v : b)
    {
      largest = std::isfinite(v) ? std::max(largest, std::fabs(v)) : largest;
    }
    this->OnSurfaceSlack = 1e-12 * largest;
    const art::Vec3 origin = art::TriangleStore::OriginFor(art::Box3::FromBounds(b));
    this->Origin[0] = origin.x, this->Origin[1] = origin.y, this->Origin[2] = origin.z;
    auto store = std::make_shared<art::TriangleStore>(art::TriangleStore::FromPolyData(pd, origin));
    art::AcceleratorOptions o;
    o.kind = static_cast<art::AcceleratorKind>(this->AcceleratorType);
    o.voxelThreshold = this->VoxelThreshold;
    o.subdivisions = this->Subdivisions;
    o.planeWeight = this->PlaneWeight;
    o.topLevelGrid = this->TopLevelGrid != 0;
    if (store->Size() == 0)
    {
      vtkErrorMacro(<< "the dataset's " << pd->GetNumberOfPolys() + pd->GetNumberOfStrips()
                    << " polygons and strips hold no triangle of non-zero area");
      return;
    }
    this->Engine = art::MakeAccelerator(store, o);
    // Queries ask the data set for a cell's type and points (GetCellType, GetCell). A polydata
    // builds its cell map on the first such call, which is not thread safe: build it here, so
    // queries from several threads at once (each with its own vtkGenericCell) only read it, as
    // with vtkStaticCellLocator (whose build asks for every cell's bounds).
    if (auto* own = vtkPolyData::SafeDownCast(this->DataSet))
    {
      if (own->NeedToBuildCells())
      {
        own->BuildCells();
      }
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro(<< e.what());
  }
}

int vtkTriangleGridLocator::IntersectWithLine(const double p1[3], const double p2[3], double, double& t,
  double x[3], double pcoords[3], int& subId, vtkIdType& cellId, vtkGenericCell* cell)
{
  this->BuildLocator();
  cellId = -1;
  subId = 0;
  if (!this->Engine)
  {
    return 0;
  }
  const art::Ray r = SegmentRay(p1, p2, this->Origin);
  art::Hit h;
  art::Counters c;
  if (!this->Engine->Closest(r, h, c))
  {
    return 0;
  }
  t = h.t;
  const art::Vec3 p = r.At(h.t) + art::Vec3(this->Origin);
  x[0] = p.x;
  x[1] = p.y;
  x[2] = p.z;
  pcoords[0] = h.u;
  pcoords[1] = h.v;
  pcoords[2] = 0;
  cellId = this->Original(h.triangle);
  if (this->DataSet->GetCellType(cellId) != VTK_TRIANGLE)
  {
    // u, v belong to the triangle of the cell's triangulation that was hit; a quad's, polygon's
    // or strip's own pcoords and subId (what vtkCellPicker interpolates normals and texture
    // coordinates with) come from the cell at the hit point.
    vtkNew<vtkGenericCell> own;
    vtkGenericCell* gc = cell ? cell : own.GetPointer();
    this->DataSet->GetCell(cellId, gc);
    std::vector<double> weights(static_cast<size_t>(gc->GetNumberOfPoints()) + 1);
    double cp[3], d2;
    gc->EvaluatePosition(x, cp, subId, pcoords, d2, weights.data());
  }
  else if (cell)
  {
    this->DataSet->GetCell(cellId, cell);
  }
  return 1;
}

int vtkTriangleGridLocator::IntersectWithLine(
  const double p1[3], const double p2[3], vtkPoints* points, vtkIdList* cellIds)
{
  this->BuildLocator();
  if (points)
  {
    points->Reset();
  }
  if (cellIds)
  {
    cellIds->Reset();
  }
  if (!this->Engine)
  {
    return 0;
  }
  art::Ray r = SegmentRay(p1, p2, this->Origin); // tmax is widened below for the inside test
  std::vector<art::Hit> hits;
  art::Counters c;
  this->Engine->All(r, hits, c);
  for (const art::Hit& h : hits)
  {
    if (points)
    {
      const art::Vec3 p = r.At(h.t) + art::Vec3(this->Origin);
      points->InsertNextPoint(p.x, p.y, p.z);
    }
    if (cellIds)
    {
      cellIds->InsertNextId(this->Original(h.triangle));
    }
  }
  if (hits.empty())
  {
    return 0;
  }
  // Inside a closed surface when the ray from p1 onwards crosses it an odd number of times.
  r.tmax = std::numeric_limits<double>::infinity();
  std::vector<art::Hit> beyond;
  this->Engine->All(r, beyond, c);
  return beyond.size() % 2 == 1 ? -1 : 1;
}

void vtkTriangleGridLocator::FindCellsAlongLine(const double p1[3], const double p2[3], double, vtkIdList* cells)
{
  this->BuildLocator();
  cells->Reset();
  if (!this->Engine)
  {
    return;
  }
  const art::Ray r = SegmentRay(p1, p2, this->Origin);
  std::vector<long long> ids;
  art::Counters c;
  this->Engine->Candidates(r, ids, c);
  for (long long id : ids)
  {
    cells->InsertNextId(this->Original(id));
  }
}

bool vtkTriangleGridLocator::Nearest(const double x[3], double maxDist2, double closestPoint[3],
  vtkIdType& cellId, double& dist2, bool& inside)
{
  this->BuildLocator();
  cellId = -1;
  inside = false;
  if (!this->Engine)
  {
    return false;
  }
  art::NearestPoint np;
  art::Counters c;
  if (!this->Engine->ClosestPoint(art::Vec3(x) - art::Vec3(this->Origin), maxDist2, np, c))
  {
    return false;
  }
  const art::Vec3 p = np.point + art::Vec3(this->Origin);
  closestPoint[0] = p.x;
  closestPoint[1] = p.y;
  closestPoint[2] = p.z;
  cellId = this->Original(np.triangle);
  dist2 = np.dist2;
  inside = np.inside;
  return true;
}

void vtkTriangleGridLocator::Finish(
  const double x[3], vtkIdType cellId, vtkGenericCell* cell, int& subId, bool& inside)
{
  subId = 0;
  if (this->DataSet->GetCellType(cellId) == VTK_TRIANGLE)
  {
    if (cell)
    {
      this->DataSet->GetCell(cellId, cell);
    }
    return;
  }
  vtkNew<vtkGenericCell> own;
  vtkGenericCell* gc = cell ? cell : own.GetPointer();
  this->DataSet->GetCell(cellId, gc);
  std::vector<double> weights(static_cast<size_t>(gc->GetNumberOfPoints()) + 1);
  double cp[3], pcoords[3], d2;
  inside = gc->EvaluatePosition(x, cp, subId, pcoords, d2, weights.data()) == 1;
}

void vtkTriangleGridLocator::FindClosestPoint(const double x[3], double closestPoint[3],
  vtkGenericCell* cell, vtkIdType& cellId, int& subId, double& dist2)
{
  bool inside;
  subId = 0;
  if (!this->Nearest(x, std::numeric_limits<double>::infinity(), closestPoint, cellId, dist2, inside))
  {
    dist2 = VTK_DOUBLE_MAX;
    return;
  }
  this->Finish(x, cellId, cell, subId, inside);
}

vtkIdType vtkTriangleGridLocator::FindClosestPointWithinRadius(double x[3], double radius,
  double closestPoint[3], vtkGenericCell* cell, vtkIdType& cellId, int& subId, double& dist2, int& inside)
{
  bool in = false;
  subId = 0;
  inside = 0;
  if (!(radius > 0) || !this->Nearest(x, radius * radius, closestPoint, cellId, dist2, in))
  {
    cellId = -1;
    return 0;
  }
  this->Finish(x, cellId, cell, subId, in);
  inside = in ? 1 : 0;
  return 1;
}

void vtkTriangleGridLocator::FindCellsWithinBounds(double* bbox, vtkIdList* cells)
{
  this->BuildLocator();
  cells->Reset();
  if (!this->Engine || !bbox)
  {
    return;
  }
  art::Box3 b;
  b.lo = art::Vec3(bbox[0], bbox[2], bbox[4]) - art::Vec3(this->Origin);
  b.hi = art::Vec3(bbox[1], bbox[3], bbox[5]) - art::Vec3(this->Origin);
  std::vector<long long> ids;
  art::Counters c;
  this->Engine->InBox(b, ids, c);
  for (long long id : ids)
  {
    cells->InsertNextId(this->Original(id));
  }
}

vtkIdType vtkTriangleGridLocator::FindCell(
  double x[3], double tol2, vtkGenericCell* cell, double pcoords[3], double* weights)
{
  int subId;
  return this->FindCellAt(x, tol2, cell, subId, pcoords, weights);
}

#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
vtkIdType vtkTriangleGridLocator::FindCell(
  double x[3], double tol2, vtkGenericCell* cell, int& subId, double pcoords[3], double* weights)
{
  return this->FindCellAt(x, tol2, cell, subId, pcoords, weights);
}
#endif

vtkIdType vtkTriangleGridLocator::FindCellAt(
  double x[3], double tol2, vtkGenericCell* cell, int& subId, double pcoords[3], double* weights)
{
  subId = 0;
  double cp[3], d2;
  vtkIdType cellId;
  bool inside;
  // Within tol means d2 <= tol2, less rounding: a point on the surface (a random point of a
  // triangle, in double) is left ~1e-17 of its coordinates from it by the closest point's
  // arithmetic, and tol2 = 0 (FindCell(x)) missed such points where VTK's locators find them.
  if (!(tol2 >= 0))
  {
    return -1;
  }
  this->BuildLocator();
  const double tol = std::sqrt(tol2) + this->OnSurfaceSlack;
  if (!this->Nearest(x, std::nextafter(tol * tol, std::numeric_limits<double>::infinity()), cp, cellId, d2, inside))
  {
    return -1;
  }
  vtkNew<vtkGenericCell> own;
  vtkGenericCell* gc = cell ? cell : own.GetPointer();
  this->DataSet->GetCell(cellId, gc);
  std::vector<double> w(static_cast<size_t>(gc->GetNumberOfPoints()) + 1);
  double pc[3];
  gc->EvaluatePosition(x, cp, subId, pc, d2, w.data());
  if (pcoords)
  {
    std::copy(pc, pc + 3, pcoords);
  }
  if (weights)
  {
    std::copy(w.begin(), w.begin() + gc->GetNumberOfPoints(), weights);
  }
  return cellId;
}

void vtkTriangleGridLocator::GenerateRepresentation(int level, vtkPolyData* pd)
{
  this->BuildLocator();
  if (!pd || !this->Engine)
  {
    return;
  }
  std::vector<art::Box3> boxes;
  this->Engine->VoxelBoxes(level < 0 ? 1000 : level, boxes);
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> quads;
  static const int faces[6][4] = { { 0, 2, 6, 4 }, { 1, 5, 7, 3 }, { 0, 4, 5, 1 }, { 2, 3, 7, 6 }, { 0, 1, 3, 2 },
    { 4, 6, 7, 5 } };
  for (const art::Box3& b : boxes)
  {
    const vtkIdType base = pts->GetNumberOfPoints();
    for (int k = 0; k < 8; ++k)
    {
      pts->InsertNextPoint((k & 1 ? b.hi.x : b.lo.x) + this->Origin[0], (k & 2 ? b.hi.y : b.lo.y) + this->Origin[1],
        (k & 4 ? b.hi.z : b.lo.z) + this->Origin[2]);
    }
    for (const auto& f : faces)
    {
      const vtkIdType q[4] = { base + f[0], base + f[1], base + f[2], base + f[3] };
      quads->InsertNextCell(4, q);
    }
  }
  pd->Initialize();
  pd->SetPoints(pts);
  pd->SetPolys(quads);
}

vtkIdType vtkTriangleGridLocator::GetNumberOfTriangles()
{
  this->BuildLocator();
  return this->Engine ? static_cast<vtkIdType>(this->Engine->Store().Size()) : 0;
}

unsigned long vtkTriangleGridLocator::GetMemoryBytes()
{
  this->BuildLocator();
  return this->Engine ? static_cast<unsigned long>(this->Engine->MemoryBytes() + this->Engine->Store().MemoryBytes()) : 0;
}

void vtkTriangleGridLocator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AcceleratorType: " << this->AcceleratorType << "\n";
  os << indent << "VoxelThreshold: " << this->VoxelThreshold << "\n";
  os << indent << "Subdivisions: " << this->Subdivisions << "\n";
  os << indent << "PlaneWeight: " << this->PlaneWeight << "\n";
  os << indent << "TopLevelGrid: " << this->TopLevelGrid << "\n";
  os << indent << "Engine: " << (this->Engine ? this->Engine->Name() : std::string("(not built)")) << "\n";
}
