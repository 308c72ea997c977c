// ReaderPlugin: readers built on netCDF (MINC, Exodus II) live in a plug-in, loaded on first use
// from the folder of the IO library: their libraries (netCDF, HDF5, curl and more) would otherwise
// load with every program that links IO.
#ifndef art_ReaderPlugin_h
#define art_ReaderPlugin_h

#include <vtkAlgorithm.h>
#include <vtkSmartPointer.h>

#include <string>

class vtkAlgorithm;

extern "C"
{
  /// A new reader for `format` ("minc", "exodus") set up to read `file` whole (every array), or
  /// null with the reason in `error`. The caller owns the reader.
  using ArtNewReaderFunction = vtkAlgorithm* (*)(const char* format, const char* file, std::string& error);
}

/// The plug-in's file name, beside the IO library.
#define ART_READERS_PLUGIN "libAdaptiveRTReaders.so"

namespace art
{
/// The plug-in's reader of `format` for `path`; an art::Error when the plug-in is missing.
vtkSmartPointer<vtkAlgorithm> PluginReader(const std::string& format, const std::string& path);
} // namespace art

#endif
