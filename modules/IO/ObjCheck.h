// ObjCheck: scans a Wavefront OBJ file's faces and checks that every vertex, texture-coordinate
// and normal index refers to one defined before it, before vtkOBJReader sees the file (VTK 9.1's
// reader writes past its arrays on an out-of-range "vt" or "vn" index: a crash or garbage normals).
#ifndef art_ObjCheck_h
#define art_ObjCheck_h

#include "AdaptiveRTIOModule.h"

#include <string>

namespace art
{
/// Throws art::Error naming `path` and the line when a face refers to an element that is not there.
ADAPTIVERTIO_EXPORT void CheckObj(const std::string& path);
} // namespace art

#endif
