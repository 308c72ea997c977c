/**
 * @class   vtkTriangleGridLocator
 * @brief   a cell locator over the TriangleGrid ray tracing machine (recursive grid, octree, ...)
 *
 * vtkTriangleGridLocator answers line queries on a vtkPolyData surface with the accelerators of
 * AdaptiveRT::TriangleGrid (after K. Dmitriev, "Efficiency issues on Ray Tracing Machine").
 * Polygons and strips are triangulated internally; cell ids reported are the polydata's own.
 * The ray/triangle test is watertight (Woop, Benthin & Wald 2013), so the tolerance argument of
 * the VTK interface is not needed and is ignored: a segment through a shared edge hits exactly
 * one of its triangles. A segment lying in a triangle's plane does not hit it (VTK's locators
 * report where it enters), and a non-planar quad is split along its 0-2 diagonal (VTK's choice
 * of diagonal differs between versions), so hits on a bent quad may differ from VTK's.
 *
 * - IntersectWithLine(p1, p2, tol, t, x, pcoords, subId[, cellId[, cell]]): the hit nearest p1.
 *   pcoords and subId are the hit cell's own at x (for a triangle, the barycentric weights of its
 *   2nd and 3rd point), so cell->EvaluateLocation(subId, pcoords, ...) gives back x.
 * - IntersectWithLine(p1, p2, points, cellIds): every hit along the segment, sorted from p1,
 *   one per surface where the segment crosses a shared edge or vertex. Returns 0 for no hit,
 *   otherwise -1 when p1 lies inside the closed surface and +1 when outside (by ray parity).
 * - FindCellsAlongLine: the unique cells in the voxels the segment passes.
 * - FindClosestPoint / FindClosestPointWithinRadius: the exact closest point of the surface (in
 *   double on the dataset's points), found by a search of the accelerator's voxels bounded by the
 *   best distance so far (a scan of every triangle only for BRUTE_FORCE). Of equally near cells the
 *   lowest id wins. `inside` is 1 when x projects inside the closest cell. Within a radius means
 *   strictly closer than it, as vtkCellLocator has it.
 * - FindCellsWithinBounds: the cells that intersect the closed box (exactly; VTK's own locators
 *   return every cell of the buckets the box touches, a superset of this).
 * - FindCell(x, tol2, cell, pcoords, weights): for a surface, the cell nearest x if it lies within
 *   sqrt(tol2) (widened by 1e-12 of the scene's largest coordinate, for rounding, so FindCell(x)
 *   with its zero tolerance finds a point lying on the surface), with the cell's own pcoords and
 *   weights at x; -1 otherwise. (VTK 9.1's
 *   vtkCellLocator ignores tol2 on a surface: it answers wherever x lies in a cell's bounding box and
 *   projects inside the cell, however far from it. Where its cell lies within tol, this gives the
 *   same cell or an equally near one.)
 *
 * Only polygons and strips are located: vertex and line cells are ignored (with a warning), and a
 * dataset with no polygons is an error. The dataset may be any vtkDataSet of surface cells, as for
 * vtkCellLocator (an unstructured grid of triangles and quads, a one-slice image's pixels; a
 * quadratic cell by its corners); one with 3-D cells is an error. BuildLocator rebuilds when the locator or its dataset was
 * modified since the last build, unless UseExistingSearchStructure is on and a structure exists
 * over as many cells as the dataset has (then the structure, and the geometry it copied, is kept).
 */
#ifndef vtkTriangleGridLocator_h
#define vtkTriangleGridLocator_h

#include "AdaptiveRTTriangleGridModule.h"
#include "vtkAbstractCellLocator.h"
#include "vtkVersionMacros.h" // the FindCell VTK 9.2 adds

#include <memory> // for std::unique_ptr
#include <vector> // for std::vector

namespace art
{
class Accelerator;
}

class ADAPTIVERTTRIANGLEGRID_EXPORT vtkTriangleGridLocator : public vtkAbstractCellLocator
{
public:
  static vtkTriangleGridLocator* New();
  vtkTypeMacro(vtkTriangleGridLocator, vtkAbstractCellLocator);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum
  {
    BRUTE_FORCE = 0,
    UNIFORM_GRID = 1,
    RECURSIVE_GRID = 2,
    OCTREE = 3
  };

  ///@{
  /** The accelerator: BRUTE_FORCE, UNIFORM_GRID, RECURSIVE_GRID (default) or OCTREE. */
  vtkSetClampMacro(AcceleratorType, int, BRUTE_FORCE, OCTREE);
  vtkGetMacro(AcceleratorType, int);
  ///@}

  ///@{
  /** R: VOX_NTRG_THR; O: VX_THRESHOLD. 0 chooses the default. */
  vtkSetClampMacro(VoxelThreshold, int, 0, 1000000);
  vtkGetMacro(VoxelThreshold, int);
  ///@}

  ///@{
  /** R: N_SUB_VOXELS per axis (0 = default). */
  vtkSetClampMacro(Subdivisions, int, 0, 16);
  vtkGetMacro(Subdivisions, int);
  ///@}

  ///@{
  /** O: PLANE_WEIGHT (0 = default). */
  vtkSetClampMacro(PlaneWeight, int, 0, 1000);
  vtkGetMacro(PlaneWeight, int);
  ///@}

  ///@{
  /** R: build the top-level uniform grid (on by default). */
  vtkSetMacro(TopLevelGrid, vtkTypeBool);
  vtkGetMacro(TopLevelGrid, vtkTypeBool);
  vtkBooleanMacro(TopLevelGrid, vtkTypeBool);
  ///@}

  void BuildLocator() override;
  /** Rebuilds even when nothing changed. */
  void ForceBuildLocator();
  void FreeSearchStructure() override;
  void GenerateRepresentation(int level, vtkPolyData* pd) override;

  using vtkAbstractCellLocator::IntersectWithLine;
  int IntersectWithLine(const double p1[3], const double p2[3], double tol, double& t, double x[3],
    double pcoords[3], int& subId, vtkIdType& cellId, vtkGenericCell* cell) override;
  int IntersectWithLine(
    const double p1[3], const double p2[3], vtkPoints* points, vtkIdList* cellIds) override;
  void FindCellsAlongLine(
    const double p1[3], const double p2[3], double tolerance, vtkIdList* cells) override;

  using vtkAbstractCellLocator::FindCell;
  using vtkAbstractCellLocator::FindClosestPoint;
  using vtkAbstractCellLocator::FindClosestPointWithinRadius;
  void FindClosestPoint(const double x[3], double closestPoint[3], vtkGenericCell* cell,
    vtkIdType& cellId, int& subId, double& dist2) override;
  vtkIdType FindClosestPointWithinRadius(double x[3], double radius, double closestPoint[3],
    vtkGenericCell* cell, vtkIdType& cellId, int& subId, double& dist2, int& inside) override;
  void FindCellsWithinBounds(double* bbox, vtkIdList* cells) override;
  vtkIdType FindCell(
    double x[3], double tol2, vtkGenericCell* cell, double pcoords[3], double* weights) override;
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 0)
  /** The same with the cell's sub-id at x: VTK 9.2's probe filters (ParaView 5.11's) call this one. */
  vtkIdType FindCell(double x[3], double tol2, vtkGenericCell* cell, int& subId, double pcoords[3],
    double* weights) override;
#endif

  /** Triangles in the search structure (after triangulation, zero-area ones dropped). */
  vtkIdType GetNumberOfTriangles();
  /** Bytes of the search structure and the triangle store. */
  unsigned long GetMemoryBytes();

protected:
  vtkTriangleGridLocator();
  ~vtkTriangleGridLocator() override;
  void BuildLocatorInternal();
  // The engine's nearest point closer than sqrt(maxDist2), in world coordinates.
  bool Nearest(const double x[3], double maxDist2, double closestPoint[3], vtkIdType& cellId,
    double& dist2, bool& inside);
  // Fills `cell` (when given) with cell cellId; for a cell that is not a triangle, subId and inside
  // come from the cell's own EvaluatePosition at x (a strip's triangle, a polygon's interior).
  void Finish(const double x[3], vtkIdType cellId, vtkGenericCell* cell, int& subId, bool& inside);
  // Both FindCell signatures: the cell nearest x within sqrt(tol2), with its own coordinates at x.
  vtkIdType FindCellAt(double x[3], double tol2, vtkGenericCell* cell, int& subId, double pcoords[3], double* weights);

  int AcceleratorType = RECURSIVE_GRID;
  int VoxelThreshold = 0;
  int Subdivisions = 0;
  int PlaneWeight = 0;
  vtkTypeBool TopLevelGrid = 1;

private:
  vtkTriangleGridLocator(const vtkTriangleGridLocator&) = delete;
  void operator=(const vtkTriangleGridLocator&) = delete;

  std::unique_ptr<art::Accelerator> Engine;
  // For a data set that is no vtkPolyData: the data set's id of each cell of the surface built
  // from it (empty for a polydata, whose ids are the engine's).
  std::vector<vtkIdType> OriginalIds;
  vtkIdType Original(long long id) const
  {
    return this->OriginalIds.empty() ? static_cast<vtkIdType>(id) : this->OriginalIds[static_cast<size_t>(id)];
  }
  bool Built = false; // a build was tried (it may have failed: no triangles) since the last free
  // The cell count the structure was built over: UseExistingSearchStructure keeps it only for a
  // data set with as many cells, whose ids it names.
  vtkIdType BuiltCells = -1;
  double Origin[3] = { 0, 0, 0 }; // the engine's coordinates are taken from here (far scenes)
  // What rounding leaves of the distance from a point lying on the surface (the closest point is
  // computed in double): FindCell's tol is widened by this, so tol2 = 0 finds such a point.
  double OnSurfaceSlack = 0;
};

#endif
