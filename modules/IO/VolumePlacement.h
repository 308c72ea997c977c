// VolumePlacement: puts NIfTI and NRRD voxels where their headers say, in the LPS patient frame
// that DICOM and ITK's MetaImage use. vtkNIFTIImageReader leaves the sform and qform to the caller
// (a radiological, x-flipped file rendered mirrored); NIfTI's world is RAS, so x and y are negated.
// vtkNrrdReader keeps only the lengths of "space directions", ignores "space", and reads a first
// axis of 9 or fewer samples as vector components even when the header calls it a domain axis.
#ifndef art_VolumePlacement_h
#define art_VolumePlacement_h

#include "AdaptiveRTIOModule.h"

#include <vtkSmartPointer.h>

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
  bool Placed = false;         ///< a transform placed the voxels (else their orientation is unknown)
  bool SlicesReversed = false; ///< VTK reads the slices last first (qfac -1 or a left-handed sform)
  long long TimePoints = 1;    ///< dim[4]: volumes in the file; VTK reads the first
};
/// Which transform of the NIfTI file `path` places its voxels (its header only is read), for `info`.
ADAPTIVERTIO_EXPORT NiftiPlacementInfo NiftiPlacement(const std::string& path);

/// Returns `img` (or a rebuilt copy) with the geometry of the NRRD header in `path`: a first
/// axis that the header makes spatial (kind domain or space, or a space direction) but VTK read as
/// components becomes the x axis again; "space directions" give the direction and spacing; a
/// RAS or LAS "space" is turned into LPS. A zero direction is an art::Error naming `path`.
ADAPTIVERTIO_EXPORT vtkSmartPointer<vtkImageData> PlaceNrrd(vtkImageData* img, const std::string& path);

/// `img` as vtkNrrdReader placed it (origin, spacing), with only its first axis back from the
/// components where the header makes it spatial (as PlaceNrrd does): the VTK frame.
ADAPTIVERTIO_EXPORT vtkSmartPointer<vtkImageData> NrrdAxesAsVtk(vtkImageData* img, const std::string& path);

/// The anatomical directions the voxel axes i, j, k point to in the LPS world, nibabel's axis
/// codes: "RAS" for a volume whose direction is diag(-1, -1, 1), "LPS" for the identity.
ADAPTIVERTIO_EXPORT std::string AxisCodes(vtkImageData* img);
} // namespace art

#endif
