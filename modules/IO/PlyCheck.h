// PlyCheck: reads a PLY header and checks it is complete, then reads the body through and checks
// that every element is there and every face names an existing vertex, before vtkPLYReader sees
// the file (which reads past the end of a truncated file and segfaults on a bad face index).
#ifndef art_PlyCheck_h
#define art_PlyCheck_h

#include "AdaptiveRTIOModule.h"

#include <string>

namespace art
{
/// Throws art::Error naming `path` when the file is not a well-formed PLY.
ADAPTIVERTIO_EXPORT void CheckPly(const std::string& path);
} // namespace art

#endif
