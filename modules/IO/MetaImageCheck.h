// MetaImageCheck: reads a MetaImage (.mha/.mhd) header and checks that the file holds as many
// data bytes as the header promises. VTK's MetaIO reader prints to std::cerr and returns a
// half-filled volume on a truncated file; checking first turns that into one clear error.
// It also reads the direction that VTK 9.1's reader ignores.
#ifndef art_MetaImageCheck_h
#define art_MetaImageCheck_h

#include "AdaptiveRTIOModule.h"

#include <string>

namespace art
{
/// Throws art::Error naming `path` when the header is malformed or the data is short.
ADAPTIVERTIO_EXPORT void CheckMetaImage(const std::string& path);

/// The volume's direction matrix (row-major, VTK's layout) from the header's TransformMatrix and
/// the signs of its ElementSpacing, both of which vtkMetaImageReader drops (a mirrored CT would
/// render mirrored). Returns false when it is the identity.
ADAPTIVERTIO_EXPORT bool MetaImageDirection(const std::string& path, double direction[9]);
} // namespace art

#endif
