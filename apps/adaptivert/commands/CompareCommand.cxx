// adaptivert compare A B: image error metrics between two images (RMSE, PSNR, SSIM), an optional
// difference image, and thresholds that turn it into a regression check (exit 1 when over).
#include "cli/Command.h"
#include "Error.h"
#include "ImageIO.h"
#include "ImageMetrics.h"
#include "cli/Json.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

namespace
{
void Declare(cli::Options& o)
{
  o.Add("diff", 'd', "FILE", "write |A - B| (scaled by --gain) as an image");
  o.Add("gain", 0, "F", "scale of the difference image", "4");
  o.Add("min-psnr", 0, "DB", "fail (exit 1) when PSNR is below this");
  o.Add("max-rmse", 0, "E", "fail (exit 1) when RMSE is above this");
  o.Add("min-ssim", 0, "S", "fail (exit 1) when SSIM is below this");
}

int Run(const cli::Options& o)
{
  if (o.Positional().size() != 2)
  {
    throw cli::UsageError("needs exactly two images A B");
  }
  const std::string pa = o.Positional()[0], pb = o.Positional()[1];
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
  const art::ImageMetricsResult m = art::CompareImages(a, b);
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
      .Set("max_abs", m.maxAbs).Set("channels", m.channels == 3 ? "RGB" : "RGBA").Set("pass", failed.empty());
    std::printf("%s\n", j.Str().c_str());
  }
  else
  {
    std::printf("RMSE     %.6f\n", m.rmse);
    if (std::isinf(m.psnr))
    {
      std::printf("PSNR     inf dB (identical)\n");
    }
    else
    {
      std::printf("PSNR     %.2f dB\n", m.psnr);
    }
    std::printf("SSIM     %.5f\n", m.ssim);
    std::printf("max|d|   %.6f\n", m.maxAbs);
    std::printf("over     %s\n", m.channels == 3 ? "RGB (both images are opaque)" : "RGBA");
  }
  if (!failed.empty())
  {
    failed.pop_back();
    throw art::Error("differs from " + pa + ":" + failed, pb);
  }
  return cli::ExitOk;
}

cli::Registrar reg({ "compare", "image error between two images: RMSE, PSNR, SSIM (over RGBA, or RGB when both are opaque), a difference image",
  "adaptivert compare [options] A B",
  "  adaptivert compare reference.png reduced.png --diff diff.png\n"
  "  adaptivert compare baseline.png out.png --min-psnr 40   # a regression check: exit 1 below 40 dB\n",
  Declare, Run });
} // namespace
