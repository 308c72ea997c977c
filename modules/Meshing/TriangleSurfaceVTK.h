// TriangleSurfaceVTK: a vtkPolyData's polygons as the TriangleSurface SurfaceCheck and TetGen take
// (vtkTriangleFilter splits polygons and strips; vertices and lines are left out).
#ifndef art_TriangleSurfaceVTK_h
#define art_TriangleSurfaceVTK_h

#include "AdaptiveRTMeshingModule.h"
#include "SurfaceCheck.h"

class vtkPolyData;

namespace art
{
ADAPTIVERTMESHING_EXPORT TriangleSurface TriangleSurfaceFromVTK(vtkPolyData* poly);
} // namespace art

#endif
