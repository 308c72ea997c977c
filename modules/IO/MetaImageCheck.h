// MetaImageCheck: reads a MetaImage (.mha/.mhd) header and checks that the file holds as many
// data bytes as the header promises. VTK's MetaIO reader prints to std::cerr and returns a
// half-filled volume on a truncated file; checking first turns that into one clear error.
#ifndef art_MetaImageCheck_h
#define art_MetaImageCheck_h

#include "AdaptiveRTIOModule.h"

#include <string>

namespace art
{
/// Throws art::Error naming `path` when the header is malformed or the data is short.
ADAPTIVERTIO_EXPORT void CheckMetaImage(const std::string& path);
} // namespace art

#endif
