#include "vtkImageMetrics.h"

#include "Error.h"
#include "ImageIO.h"
#include "ImageMetrics.h"
#include "VTKImageConvert.h"

#include <vtkObjectFactory.h>

#include <cmath>

vtkStandardNewMacro(vtkImageMetrics);

namespace
{
void Store(const art::ImageMetricsResult& r, double& rmse, double& psnr, double& ssim, double& maxAbs)
{
  rmse = r.rmse;
  psnr = std::isfinite(r.psnr) ? r.psnr : VTK_DOUBLE_MAX;
  ssim = r.ssim;
  maxAbs = r.maxAbs;
}

// A failed comparison leaves no figures of an earlier one behind: RMSE 0 and SSIM 1 (the
// defaults) or the last pair's figures read as a pass to a script that did not test the result.
void Clear(double& rmse, double& psnr, double& ssim, double& maxAbs)
{
  rmse = psnr = ssim = maxAbs = std::nan("");
}
}

bool vtkImageMetrics::Compare(vtkImageData* a, vtkImageData* b)
{
  try
  {
    Store(art::CompareImages(art::FromVTKImage(a), art::FromVTKImage(b)), this->RMSE, this->PSNR,
      this->SSIM, this->MaxAbsDifference);
    this->ErrorMessage.clear();
    return true;
  }
  catch (const art::Error& e)
  {
    Clear(this->RMSE, this->PSNR, this->SSIM, this->MaxAbsDifference);
    this->ErrorMessage = e.what();
    return false;
  }
}

bool vtkImageMetrics::CompareFiles(const char* fileA, const char* fileB)
{
  try
  {
    // Read in order, so an error names the first bad file.
    const art::Image a = art::ReadImage(fileA ? fileA : "");
    const art::Image b = art::ReadImage(fileB ? fileB : "");
    art::RequireFinite(a, fileA);
    art::RequireFinite(b, fileB);
    Store(art::CompareImages(a, b), this->RMSE, this->PSNR, this->SSIM, this->MaxAbsDifference);
    this->ErrorMessage.clear();
    return true;
  }
  catch (const art::Error& e)
  {
    Clear(this->RMSE, this->PSNR, this->SSIM, this->MaxAbsDifference);
    this->ErrorMessage = e.what();
    return false;
  }
}

void vtkImageMetrics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RMSE: " << this->RMSE << "\n";
  os << indent << "PSNR: " << this->PSNR << " dB\n";
  os << indent << "SSIM: " << this->SSIM << "\n";
  os << indent << "MaxAbsDifference: " << this->MaxAbsDifference << "\n";
  os << indent << "ErrorMessage: " << this->ErrorMessage << "\n";
}
