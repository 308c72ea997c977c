// StlCheck: checks that a binary STL file holds as many triangles as its header counts before
// vtkSTLReader sees it (VTK 9.1 reads a truncated file's first triangles and says nothing, and
// reads random bytes as triangles of size 1e38). Text STL is left to VTK, which reports errors.
#ifndef art_StlCheck_h
#define art_StlCheck_h

#include "AdaptiveRTIOModule.h"

#include <string>

namespace art
{
/// Throws art::Error naming `path` when a binary STL is shorter than its triangle count says.
ADAPTIVERTIO_EXPORT void CheckStl(const std::string& path);
} // namespace art

#endif
