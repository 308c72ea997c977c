// VTKImageConvert: art::Image <-> vtkImageData. VTK images have row 0 at the bottom and art
// images at the top, so rows are flipped; integer data is scaled by its type's
// largest value (unsigned char and unsigned short to [0, 1]), floating-point data kept as it is.
#ifndef art_VTKImageConvert_h
#define art_VTKImageConvert_h

#include "AdaptiveRTIOModule.h"
#include "Image.h"

#include <vtkSmartPointer.h>

class vtkImageData;

namespace art
{
/// 1 to 4 components of any scalar type; throws art::Error for other shapes.
ADAPTIVERTIO_EXPORT Image FromVTKImage(vtkImageData* img);
/// Float RGBA vtkImageData of the same size.
ADAPTIVERTIO_EXPORT vtkSmartPointer<vtkImageData> ToVTKImage(const Image& img);
} // namespace art

#endif
