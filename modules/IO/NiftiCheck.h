// NiftiCheck: reads a NIfTI-1 or NIfTI-2 header (through gzip for .nii.gz) and checks what
// vtkNIFTIImageReader (VTK 9.1) trusts: an unknown datatype code segfaulted it, a NaN pixdim
// became a NaN spacing, and sizes far beyond the file's bytes ended in "out of memory".
#ifndef art_NiftiCheck_h
#define art_NiftiCheck_h

#include "AdaptiveRTIOModule.h"

#include <string>

namespace art
{
/// Throws art::Error naming `path` when the header's datatype, sizes or spacing cannot be read
/// as a volume, or (uncompressed files) the data are shorter than the sizes promise.
ADAPTIVERTIO_EXPORT void CheckNifti(const std::string& path);
} // namespace art

#endif
