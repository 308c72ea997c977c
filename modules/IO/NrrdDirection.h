// NrrdDirection: reads a NRRD header's "space directions", whose signs and rotation
// vtkNrrdReader drops (it keeps only their lengths as the spacing), so a volume stored mirrored
// or turned would render mirrored or turned.
#ifndef art_NrrdDirection_h
#define art_NrrdDirection_h

#include "AdaptiveRTIOModule.h"

#include <string>

namespace art
{
/// The volume's direction matrix (row-major, VTK's layout: column c is where index axis c points,
/// of unit length) from a NRRD header. Returns false when the header has no three spatial
/// directions or they form the identity; throws art::Error naming `path` when a direction is zero.
ADAPTIVERTIO_EXPORT bool NrrdDirection(const std::string& path, double direction[9]);
} // namespace art

#endif
