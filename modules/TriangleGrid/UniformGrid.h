// UniformGrid: one level of equal voxels, the resolution chosen from the scene's box and triangle
// count (cells ~ density x triangles, shaped like the box), walked by Amanatides & Woo's 3D-DDA.
// It is the recursive grid with the subdivision turned off, so both share one traversal.
#ifndef art_UniformGrid_h
#define art_UniformGrid_h

#include "RecursiveGrid.h"

namespace art
{
class ADAPTIVERTTRIANGLEGRID_EXPORT UniformGrid : public RecursiveGrid
{
public:
  UniformGrid(std::shared_ptr<const TriangleStore> s, const AcceleratorOptions& o)
    : RecursiveGrid(std::move(s))
  {
    const double density = o.cellsPerTriangle > 0 ? o.cellsPerTriangle : 2.0;
    int dims[3];
    ChooseDims(PaddedBounds(), density * double(std::max<size_t>(S->Size(), 1)), dims);
    Build(dims, 0, 1);
  }
  std::string Name() const override
  {
    return "uniform grid " + std::to_string(TopDims(0)) + "x" + std::to_string(TopDims(1)) + "x" +
      std::to_string(TopDims(2));
  }
};
} // namespace art

#endif
