// DicomSeries: picks the files of one DICOM series in a folder before vtkDICOMImageReader reads it.
// The reader (VTK 9.1) takes whichever series UID sorts first (a 2-image scout as readily as the
// CT beside it) with the image size of the last file it parsed: a scout of another size in the
// folder corrupted the heap (abort), and a slice of another size read as garbage.
#ifndef art_DicomSeries_h
#define art_DicomSeries_h

#include "AdaptiveRTIOModule.h"

#include <string>
#include <vector>

namespace art
{
/// The DICOM files of `dir` that hold the series with the most images. Throws art::Error naming
/// `dir` when two series tie for the most, or when images of that series differ in size.
ADAPTIVERTIO_EXPORT std::vector<std::string> DicomSeriesFiles(const std::string& dir, int* seriesInFolder = nullptr);

/// A temporary folder of links to `files`, removed with the object (vtkDICOMImageReader reads
/// folders, not lists of files).
class ADAPTIVERTIO_EXPORT DicomLinkFolder
{
public:
  explicit DicomLinkFolder(const std::vector<std::string>& files);
  ~DicomLinkFolder();
  DicomLinkFolder(const DicomLinkFolder&) = delete;
  DicomLinkFolder& operator=(const DicomLinkFolder&) = delete;
  const std::string& Path() const { return Dir; }

private:
  std::string Dir;
};
} // namespace art

#endif
