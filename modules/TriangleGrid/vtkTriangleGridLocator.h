/**
 * @class   vtkTriangleGridLocator
 * @brief   a cell locator over the TriangleGrid ray tracing machine (recursive grid, octree, ...)
 *
 * vtkTriangleGridLocator answers line queries on a vtkPolyData surface with the accelerators of
 * AdaptiveRT::TriangleGrid (after K. Dmitriev, "Efficiency issues on Ray Tracing Machine").
 * Polygons and strips are triangulated internally; cell ids reported are the polydata's own.
 * The ray/triangle test is watertight (Woop, Benthin & Wald 2013), so the tolerance argument of
 * the VTK interface is not needed and is ignored: a segment through a shared edge hits exactly
 * one of its triangles.
 *
 * - IntersectWithLine(p1, p2, tol, t, x, pcoords, subId[, cellId[, cell]]): the hit nearest p1.
 *   pcoords are the barycentric weights of the hit triangle's 2nd and 3rd point.
 * - IntersectWithLine(p1, p2, points, cellIds): every hit along the segment, sorted from p1,
 *   one per surface where the segment crosses a shared edge or vertex. Returns 0 for no hit,
 *   otherwise -1 when p1 lies inside the closed surface and +1 when outside (by ray parity).
 * - FindCellsAlongLine: the unique cells in the voxels the segment passes.
 */
#ifndef vtkTriangleGridLocator_h
#define vtkTriangleGridLocator_h

#include "AdaptiveRTTriangleGridModule.h"
#include "vtkAbstractCellLocator.h"

#include <memory> // for std::unique_ptr

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

  /** Triangles in the search structure (after triangulation, zero-area ones dropped). */
  vtkIdType GetNumberOfTriangles();
  /** Bytes of the search structure and the triangle store. */
  unsigned long GetMemoryBytes();

protected:
  vtkTriangleGridLocator();
  ~vtkTriangleGridLocator() override;
  void BuildLocatorInternal();

  int AcceleratorType = RECURSIVE_GRID;
  int VoxelThreshold = 0;
  int Subdivisions = 0;
  int PlaneWeight = 0;
  vtkTypeBool TopLevelGrid = 1;

private:
  vtkTriangleGridLocator(const vtkTriangleGridLocator&) = delete;
  void operator=(const vtkTriangleGridLocator&) = delete;

  std::unique_ptr<art::Accelerator> Engine;
  double Origin[3] = { 0, 0, 0 }; // the engine's coordinates are taken from here (far scenes)
};

#endif
