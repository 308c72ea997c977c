// ImageIO: art::Image to and from files, format by extension: PNG through VTK (libpng), the rest
// through OpenImageIO in a plug-in loaded on first use (OiioImageIO).
// PNG: 8-bit RGBA (values are already display values). EXR: 32-bit float RGBA,
// bit-exact. TIFF: 32-bit float RGBA. Writes are atomic (AtomicFile).
#ifndef art_ImageIO_h
#define art_ImageIO_h

#include "AdaptiveRTIOModule.h"
#include "Image.h"

#include <string>

namespace art
{
/// Writes `img` to `path` (.png, .exr, .tif/.tiff). Throws art::Error naming the file.
ADAPTIVERTIO_EXPORT void WriteImage(const Image& img, const std::string& path);
/// Reads PNG and any image OpenImageIO reads; grey becomes RGB, missing alpha becomes 1.
ADAPTIVERTIO_EXPORT Image ReadImage(const std::string& path);
/// True when `path`'s extension names a format WriteImage writes.
ADAPTIVERTIO_EXPORT bool IsImageExtension(const std::string& path);
} // namespace art

#endif
