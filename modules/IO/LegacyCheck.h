// LegacyCheck: reads the text lines of a legacy .vtk file (its keywords and the data types they
// name) before VTK's legacy readers do, which dereference a null array for a type they do not
// know (a FIELD array of type "aoftl" segfaulted vtkStructuredPointsReader) and take negative
// counts. Binary data between the lines are skipped by the sizes the lines give.
#ifndef art_LegacyCheck_h
#define art_LegacyCheck_h

#include <string>

namespace art
{
/// Throws art::Error naming `path` when a keyword line names an unknown data type or a count
/// that is not a whole number >= 0.
void CheckLegacyVtk(const std::string& path);
} // namespace art

#endif
