#include "VTKImageConvert.h"
#include "Error.h"

#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

namespace art
{
Image FromVTKImage(vtkImageData* img)
{
  if (!img || !img->GetPointData()->GetScalars())
  {
    throw Error("image has no scalars");
  }
  int dims[3];
  img->GetDimensions(dims);
  if (dims[2] != 1)
  {
    throw Error("expected a 2-D image, got depth " + std::to_string(dims[2]));
  }
  vtkDataArray* s = img->GetPointData()->GetScalars();
  const int nc = s->GetNumberOfComponents();
  if (nc < 1 || nc > 4)
  {
    throw Error("expected 1 to 4 components, got " + std::to_string(nc));
  }
  // Integers are fractions of their type's largest value, as ReadImage takes a file's: a 16-bit
  // image (vtkPNGReader's of a 16-bit PNG) compares with the same picture in 8 bits.
  // Floating-point values are taken as they are.
  const int type = s->GetDataType();
  const double scale = type == VTK_FLOAT || type == VTK_DOUBLE ? 1.0 : 1.0 / s->GetDataTypeMax();
  Image out(dims[0], dims[1], { 0.f, 0.f, 0.f, 1.f });
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const vtkIdType id = static_cast<vtkIdType>(y) * dims[0] + x;
      float* d = out.Pixel(x, dims[1] - 1 - y);
      const bool grey = nc < 3;
      for (int c = 0; c < 3; ++c)
      {
        d[c] = static_cast<float>(s->GetComponent(id, grey ? 0 : c) * scale);
      }
      if (nc == 2 || nc == 4)
      {
        d[3] = static_cast<float>(s->GetComponent(id, nc - 1) * scale);
      }
    }
  }
  return out;
}

vtkSmartPointer<vtkImageData> ToVTKImage(const Image& img)
{
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->SetDimensions(img.Width(), img.Height(), 1);
  vtkNew<vtkFloatArray> a;
  a->SetName("RGBA");
  a->SetNumberOfComponents(4);
  a->SetNumberOfTuples(static_cast<vtkIdType>(img.Width()) * img.Height());
  for (int y = 0; y < img.Height(); ++y)
  {
    for (int x = 0; x < img.Width(); ++x)
    {
      a->SetTypedTuple(static_cast<vtkIdType>(img.Height() - 1 - y) * img.Width() + x, img.Pixel(x, y));
    }
  }
  out->GetPointData()->SetScalars(a);
  return out;
}
} // namespace art
