// ArrayChoice: which array of a data set's point or cell data a tool reads, chosen one way for
// the file loader and the tet mesh alike: the named one, else the active scalars, else the first
// one-component array; and the list of what there is, for the error when a name is missing.
#ifndef art_ArrayChoice_h
#define art_ArrayChoice_h

#include "AdaptiveRTCoreModule.h"

#include <initializer_list>
#include <string>

#include <vtkSmartPointer.h>

class vtkDataArray;
class vtkDataSetAttributes;
class vtkFieldData;

namespace art
{
/// The array called `name` (null when there is none); without a name the active scalars, else the
/// first array of one component (with a name, when `named`) whose name does not start with "vtk"
/// (VTK's bookkeeping: vtkOriginalPointIds, vtkValidPointMask), else the first such, else null.
ADAPTIVERTCORE_EXPORT vtkDataArray* ChooseArray(vtkDataSetAttributes* d, const std::string& name, bool named = false);
/// "a, b, c" over the arrays of every field given ("(unnamed)" for one without a name), or "none".
ADAPTIVERTCORE_EXPORT std::string ArrayNames(std::initializer_list<vtkFieldData*> fields);

/// What to take from a vector (velocity, RGB) array, as VTK's volume mappers do (VectorMode).
enum : int
{
  WholeArray = -2, ///< the array as it is (one component needed)
  Magnitude = -1   ///< the Euclidean norm of each tuple
};
/// Splits a ParaView-style "NAME:magnitude", "NAME:N" (0-based) or "NAME:X|Y|Z" into the name
/// and Magnitude or N; any other text is a name, read whole (WholeArray). Case is ignored in the
/// suffix; an empty name means the active scalars.
ADAPTIVERTCORE_EXPORT std::string SplitComponent(const std::string& spec, int* component);
/// One component of `a` (0-based) or its magnitude, as a double array named "NAME:magnitude" or
/// "NAME:N"; `a` itself for WholeArray. A component past the last throws art::Error naming how
/// many there are.
ADAPTIVERTCORE_EXPORT vtkSmartPointer<vtkDataArray> TakeComponent(vtkDataArray* a, int component);
/// "NAME:magnitude or NAME:0 .. NAME:n-1", for errors about an array of n components.
ADAPTIVERTCORE_EXPORT std::string ComponentHint(vtkDataArray* a);
} // namespace art

#endif
