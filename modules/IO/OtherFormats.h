// OtherFormats: the rest of what Debian's VTK 9.1 reads that a user could bring as a volume, mesh
// or surface, each with the checks its reader needs first: SLC (.slc), MINC (.mnc), BioRad
// (.pic), MRC (.mrc .map .rec), Analyze (.hdr/.img), 3-D TIFF, stacks of PNG/JPEG/TIFF/BMP slices
// (a folder or a printf pattern), raw voxels (vtkImageReader, as ParaView's raw reader), Exodus II
// (.exo .e .ex2), AVS UCD (.inp), Tecplot ASCII (.tec .dat), GAMBIT (.neu), BYU (.g .byu) and
// facets (.facet). The netCDF-based readers (MINC, Exodus) live in a plug-in loaded on first use:
// their libraries (netCDF, HDF5, curl and more) would slow the start of every program linking IO.
#ifndef art_OtherFormats_h
#define art_OtherFormats_h

#include "DataLoader.h"

#include <vtkAlgorithm.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

namespace art
{
/// Extensions (lower case, with the dot) of the volumes, surfaces and meshes read here.
bool IsOtherVolume(const std::string& ext);
bool IsOtherSurface(const std::string& ext);
bool IsOtherMesh(const std::string& ext);

/// The slices of an image stack: a folder of images of one kind, or a printf pattern
/// ("slice%03d.png") naming files that exist; empty when `path` is neither.
std::vector<std::string> ImageStack(const std::string& path);

/// A reader, checked and set up, for a volume file of another format (or a raw one when
/// `raw.Given()`); throws art::Error naming `path` for what its reader would misread.
vtkSmartPointer<vtkAlgorithm> OtherVolumeReader(const std::string& path, const RawLayout& raw);
vtkSmartPointer<vtkAlgorithm> OtherSurfaceReader(const std::string& path);
vtkSmartPointer<vtkAlgorithm> OtherMeshReader(const std::string& path);
} // namespace art

#endif
