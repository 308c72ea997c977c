// adaptivert compare A B: image error metrics between two images (RMSE, PSNR, SSIM), an optional
// difference image, and thresholds that turn it into a regression check (exit 1 when over).
#include "cli/Command.h"
#include "Error.h"
#include "ImageIO.h"
#include "ImageMetrics.h"
#include "cli/Json.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <cstdio>
#include <filesystem>

namespace
{
std::string Fixed(double v, int digits)
{
  std::ostringstream ss;
  ss << std::fixed << std::setprecision(digits) << v;
  return ss.str();
}

void Declare(cli::Options& o)
{
  o.Add("diff", 'd', "FILE", "write |A - B| (scaled by --gain) as an image");
  o.Add("gain", 0, "F", "scale of the difference image", "4");
  o.Add("min-psnr", 0, "DB", "fail (exit 1) when PSNR is below this");
  o.Add("max-rmse", 0, "E", "fail (exit 1) when RMSE is above this");
  o.Add("min-ssim", 0, "S", "fail (exit 1) when SSIM is below this");
  o.Add("background", 0, "R,G,B",
    "the background the images were rendered on (0-1): images with alpha are composited over it, and the "
    "object's pixels are those that differ from it in either image", "0,0,0");
}

std::array<float, 3> ParseBackground(const std::string& text)
{
  std::istringstream in(text);
  std::array<float, 3> bg{};
  char c1 = 0, c2 = 0;
  if (!(in >> bg[0] >> c1 >> bg[1] >> c2 >> bg[2]) || c1 != ',' || c2 != ',' || !(in >> std::ws).eof() ||
    std::any_of(bg.begin(), bg.end(), [](float v) { return !(v >= 0.f && v <= 1.f); }))
  {
    throw cli::UsageError("--background expects R,G,B in [0, 1], got '" + text + "'");
  }
  return bg;
}

int Run(const cli::Options& o)
{
  if (o.Positional().size() != 2)
  {
    throw cli::UsageError("needs exactly two images A B");
  }
  const std::string pa = o.Positional()[0], pb = o.Positional()[1];
  const std::array<float, 3> background = ParseBackground(o.Get("background"));
  if (o.Has("diff"))
  {
    const double gain = o.GetDouble("gain");
    if (!(gain > 0) || !std::isfinite(gain))
    {
      throw cli::UsageError("--gain expects a positive factor, got '" + o.Get("gain") + "'");
    }
    // The difference image replaced an input given as --diff (the baseline of a regression check).
    std::error_code ec;
    for (const std::string& in : { pa, pb })
    {
      if (std::filesystem::equivalent(in, o.Get("diff"), ec) ||
        std::filesystem::weakly_canonical(in, ec) == std::filesystem::weakly_canonical(o.Get("diff"), ec))
      {
        throw cli::UsageError("--diff " + o.Get("diff") + " is one of the images compared; give another file");
      }
    }
  }
  const art::Image a = art::ReadImage(pa), b = art::ReadImage(pb);
  art::RequireFinite(a, pa);
  art::RequireFinite(b, pb);
  if (a.Width() != b.Width() || a.Height() != b.Height())
  {
    throw art::Error("size " + std::to_string(b.Width()) + "x" + std::to_string(b.Height()) +
        " differs from " + pa + " (" + std::to_string(a.Width()) + "x" + std::to_string(a.Height()) + ")",
      pb);
  }
  const art::ImageMetricsResult m = art::CompareOnBackground(a, b, background);
  if (o.Has("diff"))
  {
    art::WriteImage(art::DifferenceImage(a, b, static_cast<float>(o.GetDouble("gain"))), o.Get("diff"));
  }
  std::string failed;
  if (o.Has("min-psnr") && !(m.psnr >= o.GetDouble("min-psnr")))
  {
    failed += " PSNR below " + o.Get("min-psnr") + " dB;";
  }
  if (o.Has("max-rmse") && !(m.rmse <= o.GetDouble("max-rmse")))
  {
    failed += " RMSE above " + o.Get("max-rmse") + ";";
  }
  if (o.Has("min-ssim") && !(m.ssim >= o.GetDouble("min-ssim")))
  {
    failed += " SSIM below " + o.Get("min-ssim") + ";";
  }
  if (o.Flag("json"))
  {
    cli::Json j;
    j.Set("a", pa).Set("b", pb).Set("rmse", m.rmse).Set("psnr_db", m.psnr).Set("ssim", m.ssim)
      .Set("max_abs", m.maxAbs).Set("channels", "RGB").Set("object_rmse", m.objectRmse)
      .Set("object_psnr_db", m.objectPsnr).Set("object_ssim", m.objectSsim).Set("object_pixels", m.objectPixels)
      .Set("pass", failed.empty());
    std::printf("%s\n", j.Str().c_str());
  }
  else
  {
    const auto db = [](double v) { return std::isinf(v) ? std::string("inf dB (identical)") : Fixed(v, 2) + " dB"; };
    std::printf("RMSE     %.6f\n", m.rmse);
    std::printf("PSNR     %s\n", db(m.psnr).c_str());
    std::printf("SSIM     %.5f\n", m.ssim);
    std::printf("max|d|   %.6f\n", m.maxAbs);
    std::printf("over     RGB, composited over the background %s\n", o.Get("background").c_str());
    std::printf("object   PSNR %s, SSIM %.5f, RMSE %.6f over the %lld pixels either image covers\n",
      db(m.objectPsnr).c_str(), m.objectSsim, m.objectRmse, m.objectPixels);
  }
  if (!failed.empty())
  {
    failed.pop_back();
    throw art::Error("differs from " + pa + ":" + failed, pb);
  }
  return cli::ExitOk;
}

cli::Registrar reg({ "compare", "image error between two images: RMSE, PSNR, SSIM over the frame and over the object, a difference image",
  "adaptivert compare [options] A B",
  "  adaptivert compare reference.png reduced.png --diff diff.png\n"
  "  adaptivert compare baseline.png out.png --min-psnr 40   # a regression check: exit 1 below 40 dB\n",
  Declare, Run });
} // namespace
