// OiioImageIO: the OpenImageIO side of ImageIO (EXR, TIFF and every format OpenImageIO reads), in
// a plug-in loaded on first use. OpenImageIO pulls in hundreds of libraries, which would slow the
// start of every program linking IO; PNG, which nearly every run writes, goes through VTK.
#ifndef art_OiioImageIO_h
#define art_OiioImageIO_h

#include "Image.h"

#include <string>

extern "C"
{
  /// Writes `img` to `file` as the format of extension `ext` (".exr", ".tif", ".tiff"); false with
  /// OpenImageIO's message in `error`.
  using ArtOiioWrite = bool (*)(const art::Image& img, const char* file, const char* ext, std::string& error);
  /// Reads any image OpenImageIO reads: grey becomes RGB, missing alpha becomes 1.
  using ArtOiioRead = bool (*)(const char* file, art::Image& img, std::string& error);
}

/// The plug-in's file name, beside the IO library.
#define ART_OIIO_PLUGIN "libAdaptiveRTOIIO.so"

#endif
