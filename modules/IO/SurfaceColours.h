// SurfaceColours: the RGB colours a triangle scene is drawn with: its point colours (PLY and OBJ
// vertex colours), or, when it has none, its face colours (a PLY's red, green, blue on its faces,
// as MeshLab, CloudCompare and CAD exports write them) on corners of each face's own.
#ifndef art_SurfaceColours_h
#define art_SurfaceColours_h

#include "AdaptiveRTIOModule.h"

#include <vtkSmartPointer.h>

#include <array>
#include <vector>

class vtkPolyData;

namespace art
{
/// `pd` itself, or, when colours are on its faces and not its points, its triangles each with
/// corners of their own carrying the face's colour (the faces are then shaded flat).
ADAPTIVERTIO_EXPORT vtkSmartPointer<vtkPolyData> WithColoursOnPoints(vtkPolyData* pd);
/// One RGB per point in [0, 1] (8-bit colours over 255, 16-bit over 65535, floating ones as they
/// are or over 255 when any exceeds 1); empty when the points carry no colours.
ADAPTIVERTIO_EXPORT std::vector<std::array<float, 3>> PointColours(vtkPolyData* pd);
} // namespace art

#endif
