// FormatChecks: what the headers of the other formats (OtherFormats.h) promise, checked against
// the files before VTK's readers trust it. vtkSLCReader decodes its run-length slices without a
// bound (a bad run wrote past the slice), vtkMRCReader and the Analyze reader read a file shorter
// than its sizes as zeros; BioRad .pic, which VTK has no reader for, is read here as raw voxels.
#ifndef art_FormatChecks_h
#define art_FormatChecks_h

#include <vtkAlgorithm.h>
#include <vtkSmartPointer.h>

#include <string>

namespace art
{
/// Each throws art::Error naming `path` when the file is not one its reader reads whole.
void CheckSlc(const std::string& path);
void CheckMrc(const std::string& path);
/// The Analyze 7.5 header of `path` (.hdr, or the .hdr beside an .img), checked with its data.
std::string CheckAnalyze(const std::string& path);
void CheckAvsUcd(const std::string& path);
void CheckTecplot(const std::string& path);
void CheckGambit(const std::string& path);
void CheckByu(const std::string& path);
/// Every page of a TIFF file: sizes, samples and strips libtiff can read (it crashed on others).
void CheckTiff(const std::string& path);
/// A BioRad .pic (76-byte header, 8- or 16-bit voxels, notes giving the spacing) as a reader.
vtkSmartPointer<vtkAlgorithm> BioRadReader(const std::string& path);
} // namespace art

#endif
