// XmlCheck: reads the XML structure of a VTK XML file (.vti .vtu .vtp .vts .vtr, their parallel
// forms and .vtm) before VTK's reader does, and refuses what that reader (VTK 9.1) crashes on or
// reads silently wrong: a negative count (NumberOfCells="-5" segfaulted it), elements nested
// thousands deep (a stack overflow), a NaN spacing (read as 1), appended data cut short (the
// missing bytes read as zeros), a file that does not end with </VTKFile>. Pieces and blocks a
// parallel or multiblock file names are checked too.
#ifndef art_XmlCheck_h
#define art_XmlCheck_h

#include "AdaptiveRTIOModule.h"

#include <string>

namespace art
{
/// What a VTK XML file's pieces promise, summed over its pieces (and over the files a parallel
/// or multiblock file names), for checking the reader's output against.
struct XmlCounts
{
  long long Points = 0, Cells = 0, Polys = 0, Strips = 0, Lines = 0, Verts = 0;
  bool Complete = true; ///< false when some piece's count is not given (a structured piece)
};

/// Throws art::Error naming `path` (or the piece file at fault) when the file is not a VTK XML
/// file its reader can read whole; returns what its pieces promise.
ADAPTIVERTIO_EXPORT XmlCounts CheckVtkXml(const std::string& path);
} // namespace art

#endif
