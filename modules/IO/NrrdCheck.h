// NrrdCheck: reads a NRRD header and checks that raw data (attached or in its "data file") holds
// as many bytes as the sizes and type promise, before vtkNrrdReader sees it (which reports a
// short file as "File operation failed: 18446744073709305856, ext: ...").
#ifndef art_NrrdCheck_h
#define art_NrrdCheck_h

#include "AdaptiveRTIOModule.h"

#include <istream>
#include <map>
#include <string>

class vtkDataArray;

namespace art
{
/// The "key: value" fields of a NRRD header, read from `in` up to the first empty line (where
/// attached data starts, `in` is left there); comments and "key:=value" pairs are skipped.
ADAPTIVERTIO_EXPORT std::map<std::string, std::string> ReadNrrdFields(std::istream& in);

/// Throws art::Error naming `path` when raw NRRD data is shorter than the header promises.
/// A data file series (LIST or a pattern), which vtkNrrdReader segfaults on, is an error too.
/// Compressed encodings and byte skip -1 are left to VTK.
ADAPTIVERTIO_EXPORT void CheckNrrd(const std::string& path);

/// For text data (encoding ascii, text or txt), which vtkNrrdReader (VTK 9.1) reads as all zeros:
/// reads the values (attached, or in the "data file", after "line skip" lines) into `values`, in
/// file order, and returns true; false for any other encoding. Too few values or a word that is
/// not a number throw art::Error naming `path`.
ADAPTIVERTIO_EXPORT bool ReadNrrdText(const std::string& path, vtkDataArray* values);
} // namespace art

#endif
