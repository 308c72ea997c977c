// ViewerScene: what adaptivert-view shows, loaded from one file. A volume keeps its voxels (the
// reduction runs later, in the background) and gains tet levels as they arrive; a tet mesh is
// its own single level; a triangle scene goes to the surface tracer (SurfaceTraceView).
#ifndef art_ViewerScene_h
#define art_ViewerScene_h

#include "DataLoader.h"
#include "Box3.h"
#include "SurfaceTraceView.h"
#include "TransferFunction.h"

#include <vtkSmartPointer.h>

#include <memory>
#include <string>
#include <vector>

class vtkImageData;
class vtkUnstructuredGrid;

namespace view
{
struct ViewerScene
{
  vtkSmartPointer<vtkImageData> Image;                     ///< a volume's voxels
  std::vector<vtkSmartPointer<vtkUnstructuredGrid>> Levels; ///< tet levels, coarsest first
  std::vector<std::string> LevelLabels;                     ///< "10,000 tets, RMS error 21.3"
  std::unique_ptr<SurfaceTraceView> Surface;                ///< a triangle scene
  art::TransferFunction Transfer;
  art::Box3 Bounds;
  art::Box3 Object; ///< what the default camera frames: the part the transfer function shows
  double Range[2] = { 0, 1 };
  std::string Note; ///< one line about the data, for the status text
  /// The array shown, as the levels' grids name it ("velocity:magnitude" for --array
  /// velocity:mag); empty for the active scalars.
  std::string ArrayName;
  bool ArrayOnCells = false; ///< ArrayName is a mesh's cell array (the mapper looks there)

  void AddLevel(vtkSmartPointer<vtkUnstructuredGrid> grid, long long tets, double rms);
};

/// Loads `file` (volume, tet mesh or triangle scene) with the transfer-function preset `tf`.
/// Throws art::Error naming the file for anything wrong with it.
ViewerScene LoadScene(const std::string& file, const std::string& tf, const art::LoadOptions& load = {},
  const std::string& labelColours = "values");

/// 12345 -> "12,345".
std::string Grouped(long long n);
} // namespace view

#endif
