// ImageMetrics: RMSE and PSNR over RGBA (values in [0, 1], peak 1), and SSIM (Wang, Bovik,
// Sheikh & Simoncelli 2004: 11x11 Gaussian window, sigma 1.5, K1 0.01, K2 0.03) averaged over
// the four channels; over RGB alone when alpha is 1 throughout both images (written, opaque
// images). Used for every accuracy figure the project reports.
#ifndef art_ImageMetrics_h
#define art_ImageMetrics_h

#include "AdaptiveRTIOModule.h"
#include "Image.h"

#include <array>
#include <string>

namespace art
{
struct ImageMetricsResult
{
  double rmse = 0.0;
  double psnr = 0.0; ///< dB; +infinity for identical images
  double ssim = 1.0;
  double maxAbs = 0.0; ///< largest absolute channel difference
  int channels = 4;    ///< 3 when both images are opaque and alpha was left out
  /// Over the object's pixels only (CompareOnBackground; -1 pixels: not measured).
  long long objectPixels = -1;
  double objectRmse = 0.0;
  double objectPsnr = 0.0;
  double objectSsim = 1.0;
};

/// A pixel belongs to the object when a channel differs from the background by more than half
/// an 8-bit step, so a PNG and the float image it was written from agree on it.
constexpr float ObjectStep = 0.5f / 255.f;

/// Throws art::Error naming `file` when a channel value is NaN or infinite (a float EXR or TIFF
/// can hold them): RMSE would be NaN, and PSNR, read as "rmse > 0", infinite, "identical".
ADAPTIVERTIO_EXPORT void RequireFinite(const Image& img, const std::string& file = {});

/// Throws art::Error when the sizes differ or a value is not finite.
ADAPTIVERTIO_EXPORT double RMSE(const Image& a, const Image& b);
ADAPTIVERTIO_EXPORT double PSNR(const Image& a, const Image& b);
ADAPTIVERTIO_EXPORT double SSIM(const Image& a, const Image& b);
ADAPTIVERTIO_EXPORT ImageMetricsResult CompareImages(const Image& a, const Image& b);
/// The figures every command reports for rendered images: both composited over `background` (a
/// no-op for opaque images) and compared over RGB, over the whole frame and over the object's
/// pixels alone (those either image covers), since a mostly empty background flatters the
/// whole-frame figures. render, compare and batch all use it, so one pair of images has one PSNR.
ADAPTIVERTIO_EXPORT ImageMetricsResult CompareOnBackground(
  const Image& a, const Image& b, const std::array<float, 3>& background = { 0.f, 0.f, 0.f });
/// |a - b| per channel, scaled by `gain` and clamped to 1; alpha set to 1 so it can be viewed.
ADAPTIVERTIO_EXPORT Image DifferenceImage(const Image& a, const Image& b, float gain = 1.f);
} // namespace art

#endif
