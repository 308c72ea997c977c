#include "ImageMetrics.h"
#include "Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace art
{
namespace
{
void CheckSameSize(const Image& a, const Image& b)
{
  if (a.Width() != b.Width() || a.Height() != b.Height())
  {
    throw Error("images differ in size: " + std::to_string(a.Width()) + "x" +
      std::to_string(a.Height()) + " vs " + std::to_string(b.Width()) + "x" +
      std::to_string(b.Height()));
  }
  RequireFinite(a, "the first image");
  RequireFinite(b, "the second image");
}

// Alpha is left out when it is 1 in both images (written images are composited over a
// background): a channel with no error would only dilute the others'.
int Channels(const Image& a, const Image& b)
{
  const auto& pa = a.Pixels();
  const auto& pb = b.Pixels();
  for (size_t i = 3; i < pa.size(); i += 4)
  {
    if (pa[i] != 1.f || pb[i] != 1.f)
    {
      return 4;
    }
  }
  return 3;
}

// Separable Gaussian filter with the image edge clamped.
std::vector<double> Blur(const std::vector<double>& in, int w, int h, const std::vector<double>& k)
{
  const int r = static_cast<int>(k.size() / 2);
  std::vector<double> tmp(in.size()), out(in.size());
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      double s = 0;
      for (int i = -r; i <= r; ++i)
      {
        s += k[i + r] * in[static_cast<size_t>(y) * w + std::clamp(x + i, 0, w - 1)];
      }
      tmp[static_cast<size_t>(y) * w + x] = s;
    }
  }
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      double s = 0;
      for (int i = -r; i <= r; ++i)
      {
        s += k[i + r] * tmp[static_cast<size_t>(std::clamp(y + i, 0, h - 1)) * w + x];
      }
      out[static_cast<size_t>(y) * w + x] = s;
    }
  }
  return out;
}

// Mean SSIM of channel c over the image, and over the pixels `mask` marks (when given) into
// *maskMean.
double ChannelSSIM(const Image& a, const Image& b, int c, const std::vector<double>& k,
  const std::vector<char>* mask = nullptr, double* maskMean = nullptr)
{
  const int w = a.Width(), h = a.Height();
  const size_t n = static_cast<size_t>(w) * h;
  std::vector<double> x(n), y(n), xx(n), yy(n), xy(n);
  for (size_t i = 0; i < n; ++i)
  {
    x[i] = a.Pixels()[4 * i + c];
    y[i] = b.Pixels()[4 * i + c];
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  const auto mx = Blur(x, w, h, k), my = Blur(y, w, h, k);
  const auto sxx = Blur(xx, w, h, k), syy = Blur(yy, w, h, k), sxy = Blur(xy, w, h, k);
  const double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;
  double sum = 0, maskSum = 0;
  size_t masked = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const double vx = sxx[i] - mx[i] * mx[i], vy = syy[i] - my[i] * my[i];
    const double cxy = sxy[i] - mx[i] * my[i];
    const double v = ((2 * mx[i] * my[i] + C1) * (2 * cxy + C2)) / ((mx[i] * mx[i] + my[i] * my[i] + C1) * (vx + vy + C2));
    sum += v;
    if (mask && (*mask)[i])
    {
      maskSum += v;
      ++masked;
    }
  }
  if (maskMean)
  {
    *maskMean = masked ? maskSum / double(masked) : 1.0;
  }
  return sum / double(n);
}

std::vector<double> SsimKernel()
{
  std::vector<double> k(11);
  double ks = 0;
  for (int i = 0; i < 11; ++i)
  {
    k[i] = std::exp(-double((i - 5) * (i - 5)) / (2 * 1.5 * 1.5));
    ks += k[i];
  }
  for (double& v : k)
  {
    v /= ks;
  }
  return k;
}

// Over the first `channels` channels; the sizes checked.
double RmseOver(const Image& a, const Image& b, int channels)
{
  const auto& pa = a.Pixels();
  const auto& pb = b.Pixels();
  if (pa.empty())
  {
    return 0.0;
  }
  double s = 0;
  for (size_t i = 0; i < pa.size(); ++i)
  {
    if (static_cast<int>(i % 4) < channels)
    {
      const double d = double(pa[i]) - double(pb[i]);
      s += d * d;
    }
  }
  return std::sqrt(s / double(pa.size() / 4 * channels));
}

double SsimOver(const Image& a, const Image& b, int channels)
{
  if (a.Empty())
  {
    return 1.0;
  }
  const std::vector<double> k = SsimKernel();
  double s = 0;
  for (int c = 0; c < channels; ++c)
  {
    s += ChannelSSIM(a, b, c, k);
  }
  return s / channels;
}
} // namespace

void RequireFinite(const Image& img, const std::string& file)
{
  const auto& p = img.Pixels();
  std::size_t bad = 0, first = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
  {
    if (!std::isfinite(p[i]))
    {
      first = bad++ ? first : i;
    }
  }
  if (bad)
  {
    const std::size_t pixel = first / 4;
    throw Error("holds " + std::to_string(bad) + " NaN or infinite channel values, the first at pixel (" +
        std::to_string(pixel % std::size_t(img.Width())) + ", " + std::to_string(pixel / std::size_t(img.Width())) +
        "): no error figure can be computed",
      file);
  }
}

double RMSE(const Image& a, const Image& b)
{
  CheckSameSize(a, b);
  return RmseOver(a, b, Channels(a, b));
}

double PSNR(const Image& a, const Image& b)
{
  const double e = RMSE(a, b);
  return e > 0 ? -20.0 * std::log10(e) : std::numeric_limits<double>::infinity();
}

double SSIM(const Image& a, const Image& b)
{
  CheckSameSize(a, b);
  return SsimOver(a, b, Channels(a, b));
}

ImageMetricsResult CompareImages(const Image& a, const Image& b)
{
  CheckSameSize(a, b); // and every value finite: once for all the figures
  ImageMetricsResult r;
  r.channels = Channels(a, b);
  r.rmse = RmseOver(a, b, r.channels);
  r.psnr = r.rmse > 0 ? -20.0 * std::log10(r.rmse) : std::numeric_limits<double>::infinity();
  r.ssim = SsimOver(a, b, r.channels);
  for (size_t i = 0; i < a.Pixels().size(); ++i)
  {
    r.maxAbs = std::max(r.maxAbs, std::fabs(double(a.Pixels()[i]) - double(b.Pixels()[i])));
  }
  return r;
}

ImageMetricsResult CompareOnBackground(const Image& a, const Image& b, const std::array<float, 3>& background)
{
  CheckSameSize(a, b);
  Image ca = a, cb = b;
  ca.CompositeOver(background);
  cb.CompositeOver(background);
  ImageMetricsResult r;
  r.channels = 3;
  const std::size_t n = static_cast<std::size_t>(a.Width()) * a.Height();
  std::vector<char> object(n, 0);
  double whole = 0, inside = 0;
  long long count = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    double d2 = 0;
    bool covered = false;
    for (int c = 0; c < 3; ++c)
    {
      const float va = ca.Pixels()[4 * i + c], vb = cb.Pixels()[4 * i + c];
      const double d = double(va) - double(vb);
      d2 += d * d;
      r.maxAbs = std::max(r.maxAbs, std::fabs(d));
      covered = covered || std::fabs(va - background[c]) > ObjectStep || std::fabs(vb - background[c]) > ObjectStep;
    }
    whole += d2;
    if (covered)
    {
      object[i] = 1;
      inside += d2;
      ++count;
    }
  }
  const auto psnr = [](double rmse) { return rmse > 0 ? -20.0 * std::log10(rmse) : std::numeric_limits<double>::infinity(); };
  r.rmse = n ? std::sqrt(whole / double(3 * n)) : 0.0;
  r.psnr = psnr(r.rmse);
  r.objectPixels = count;
  r.objectRmse = count ? std::sqrt(inside / double(3 * count)) : 0.0;
  r.objectPsnr = psnr(r.objectRmse);
  r.ssim = r.objectSsim = 1.0;
  if (n)
  {
    const std::vector<double> k = SsimKernel();
    double s = 0, so = 0;
    for (int c = 0; c < 3; ++c)
    {
      double m = 1.0;
      s += ChannelSSIM(ca, cb, c, k, &object, &m);
      so += m;
    }
    r.ssim = s / 3;
    r.objectSsim = so / 3;
  }
  return r;
}

Image DifferenceImage(const Image& a, const Image& b, float gain)
{
  CheckSameSize(a, b);
  Image d(a.Width(), a.Height(), { 0.f, 0.f, 0.f, 1.f });
  for (size_t i = 0; i < a.Pixels().size(); i += 4)
  {
    for (int c = 0; c < 3; ++c)
    {
      d.Pixels()[i + c] = std::min(1.f, gain * std::fabs(a.Pixels()[i + c] - b.Pixels()[i + c]));
    }
  }
  return d;
}
} // namespace art
