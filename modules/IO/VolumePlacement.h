// VolumePlacement: puts a NIfTI volume's voxels where its sform or qform says. vtkNIFTIImageReader
// reports both matrices but leaves the image at origin 0 without a direction, so a radiological
// (x-flipped) file rendered mirrored. The world is the LPS patient frame that DICOM, ITK's
// MetaImage and our other readers use; NIfTI's own world is RAS, so its x and y are negated.
#ifndef art_VolumePlacement_h
#define art_VolumePlacement_h

#include "AdaptiveRTIOModule.h"

#include <string>

class vtkImageData;
class vtkNIFTIImageReader;

namespace art
{
/// Sets `img`'s spacing, origin and direction from the reader's sform when its code is set, else
/// from its qform, else leaves them (NIfTI's method 1: spacing only), as nibabel chooses. A
/// transform whose axes are not perpendicular is an art::Error naming `path` (a sheared sform
/// falls back to the qform when there is one).
ADAPTIVERTIO_EXPORT void PlaceNifti(vtkImageData* img, vtkNIFTIImageReader* reader, const std::string& path);

struct NiftiPlacementInfo
{
  std::string How;             ///< "sform code 2 (aligned anatomy)", "qform code 1 (scanner)" or "none (...)"
  bool SlicesReversed = false; ///< VTK reads the slices last first (qfac -1 or a left-handed sform)
};
/// Which transform of the NIfTI file `path` places its voxels (its header only is read), for `info`.
ADAPTIVERTIO_EXPORT NiftiPlacementInfo NiftiPlacement(const std::string& path);

/// The anatomical directions the voxel axes i, j, k point to in the LPS world, nibabel's axis
/// codes: "RAS" for a volume whose direction is diag(-1, -1, 1), "LPS" for the identity.
ADAPTIVERTIO_EXPORT std::string AxisCodes(vtkImageData* img);
} // namespace art

#endif
