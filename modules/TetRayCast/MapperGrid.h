// MapperGrid: the input grid as vtkTetRayCastMapper hands it to the engine: the array its
// ScalarMode selects, without ghost cells, moved by a volume matrix the camera cannot absorb; and
// the mapper's clipping planes in the engine's coordinates (VTK's volume-mapper conventions).
#ifndef art_MapperGrid_h
#define art_MapperGrid_h

#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

class vtkMatrix4x4;
class vtkPlaneCollection;
class vtkUnstructuredGrid;

namespace art
{
namespace mapper
{
/// The scale of `m` when its linear part is a rotation or mirror times one scale (orthogonal
/// columns of one length), else 0.
double SimilarityScale(vtkMatrix4x4* m);
/// grid with its points taken through `m`, into the coordinates the engine casts in.
vtkSmartPointer<vtkUnstructuredGrid> Transformed(vtkUnstructuredGrid* grid, vtkMatrix4x4* m);
/// The grid as the engine should see it under ScalarMode `mode` (array `name`, else number `id`),
/// a vector array taken as its magnitude or one component (art::TakeComponent's `component`);
/// `key` names the choice (a change rebuilds the mesh); nullptr, with `error` set, when there is none.
vtkSmartPointer<vtkUnstructuredGrid> SelectedScalars(vtkUnstructuredGrid* grid, int mode, const char* name, int id,
  int component, std::string& key, std::string& error);
/// engineGrid (grid, or a view sharing its cells) without the cells grid marks as ghosts.
vtkSmartPointer<vtkUnstructuredGrid> WithoutGhosts(vtkUnstructuredGrid* engineGrid, vtkUnstructuredGrid* grid);
/// The clipping planes (world coordinates) in the engine's: (a, b, c, d), a x + b y + c z + d >= 0 kept.
std::vector<std::array<double, 4>> PlanesInData(vtkPlaneCollection* planes, vtkMatrix4x4* toWorld);
} // namespace mapper
} // namespace art

#endif
