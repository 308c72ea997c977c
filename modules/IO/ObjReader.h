// ObjReader: reads a Wavefront OBJ surface (v, vt, vn, f, l, p, usemtl with the diffuse colours
// of its mtllib libraries; the rest is skipped) keeping every
// face, whatever mix of corner forms (v, v/vt, v//vn, v/vt/vn), relative indices, polygons, "\"
// continuations and CRLF line ends it holds. vtkOBJReader (VTK 9.1) drops each face whose corners
// lack the normals or texture coordinates that another face has, and fails on CRLF files.
#ifndef art_ObjReader_h
#define art_ObjReader_h

#include "AdaptiveRTIOModule.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace art
{
/// The surface in `path`, with double-precision points; vertex colours ("v x y z r g b", 0..1 or
/// 0..255) become 8-bit "RGB" point scalars when every vertex has one. Normals ("Normals") and texture
/// coordinates ("TCoords") become point data only when every face corner has one; a point is
/// then one (vertex, texture coordinate, normal) triple, so faces that share a vertex but not its
/// normal meet at a crease. Faces take their material's diffuse colour (Kd) as 8-bit "RGB" cell
/// scalars when every face has one. A face index that names nothing, a face of fewer than three
/// corners or a vertex without three numbers is an art::Error naming `path` and the line.
ADAPTIVERTIO_EXPORT vtkSmartPointer<vtkPolyData> ReadObj(const std::string& path);
} // namespace art

#endif
