/**
 * @class vtkImageMetrics
 * @brief Image error metrics (RMSE, PSNR, SSIM) between two 2-D images or image files.
 *
 * Images may have 1 to 4 components of any scalar type; integer values are scaled by their
 * type's largest value (1/255 for unsigned char, 1/65535 for unsigned short), floating-point
 * values are taken as values in [0, 1]. The figures are over RGBA, or over RGB when alpha is 1
 * throughout both images (opaque images, as written ones are, or images without alpha): an
 * error-free alpha would only dilute the others. Files are read as art::ReadImage reads them (PNG
 * through VTK; EXR, TIFF and others through OpenImageIO). After a successful Compare the
 * figures are available through the getters; on failure Compare returns false,
 * GetErrorMessage() says why and the figures are NaN (as before any comparison).
 */
#ifndef vtkImageMetrics_h
#define vtkImageMetrics_h

#include "AdaptiveRTIOModule.h"
#include "vtkObject.h"

#include <cmath>
#include <string>

class vtkImageData;

class ADAPTIVERTIO_EXPORT vtkImageMetrics : public vtkObject
{
public:
  static vtkImageMetrics* New();
  vtkTypeMacro(vtkImageMetrics, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Compares two images of equal size. */
  bool Compare(vtkImageData* a, vtkImageData* b);
  /** Compares two image files. */
  bool CompareFiles(const char* fileA, const char* fileB);

  vtkGetMacro(RMSE, double);
  /** PSNR in dB with peak 1; VTK_DOUBLE_MAX for identical images. */
  vtkGetMacro(PSNR, double);
  vtkGetMacro(SSIM, double);
  vtkGetMacro(MaxAbsDifference, double);
  const char* GetErrorMessage() const { return this->ErrorMessage.c_str(); }

protected:
  vtkImageMetrics() = default;
  ~vtkImageMetrics() override = default;

  double RMSE = std::nan("");
  double PSNR = std::nan("");
  double SSIM = std::nan("");
  double MaxAbsDifference = std::nan("");
  std::string ErrorMessage;

private:
  vtkImageMetrics(const vtkImageMetrics&) = delete;
  void operator=(const vtkImageMetrics&) = delete;
};

#endif
