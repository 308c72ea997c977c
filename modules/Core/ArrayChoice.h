// ArrayChoice: which array of a data set's point or cell data a tool reads, chosen one way for
// the file loader and the tet mesh alike: the named one, else the active scalars, else the first
// one-component array; and the list of what there is, for the error when a name is missing.
#ifndef art_ArrayChoice_h
#define art_ArrayChoice_h

#include "AdaptiveRTCoreModule.h"

#include <initializer_list>
#include <string>

class vtkDataArray;
class vtkDataSetAttributes;
class vtkFieldData;

namespace art
{
/// The array called `name` (null when there is none); without a name the active scalars, else the
/// first array of one component (with a name, when `named`), else null.
ADAPTIVERTCORE_EXPORT vtkDataArray* ChooseArray(vtkDataSetAttributes* d, const std::string& name, bool named = false);
/// "a, b, c" over the arrays of every field given ("(unnamed)" for one without a name), or "none".
ADAPTIVERTCORE_EXPORT std::string ArrayNames(std::initializer_list<vtkFieldData*> fields);
} // namespace art

#endif
