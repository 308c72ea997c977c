// PlyCheck: reads a PLY header and checks it is complete and that a binary body is at least as
// long as its element counts require, before vtkPLYReader sees the file (which may read past
// the end of a truncated or random file).
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
