#include "Error.h"
#include "ImageMetrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using art::Image;

namespace
{
Image Noise(int w, int h, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  Image img(w, h);
  for (float& v : img.Pixels())
  {
    v = u(rng);
  }
  return img;
}
}

TEST(ImageMetrics, IdenticalImages)
{
  const Image a = Noise(40, 30, 1);
  const auto r = art::CompareImages(a, a);
  EXPECT_EQ(r.rmse, 0.0);
  EXPECT_TRUE(std::isinf(r.psnr));
  EXPECT_NEAR(r.ssim, 1.0, 1e-12);
}

TEST(ImageMetrics, ConstantOffsetGivesKnownRmseAndPsnr)
{
  Image a(32, 32, { 0.2f, 0.4f, 0.6f, 0.5f });
  Image b(32, 32, { 0.3f, 0.5f, 0.7f, 0.6f });
  // Every channel differs by 0.1: RMSE 0.1, PSNR 20 dB (float rounding only).
  EXPECT_NEAR(art::RMSE(a, b), 0.1, 1e-7);
  EXPECT_NEAR(art::PSNR(a, b), 20.0, 1e-5);
}

// Written images are opaque: alpha 1 in both is left out, so RGB differing by 0.1 is 20 dB, as
// an RGB-only tool reports (over RGBA the error-free alpha gave 21.25 dB). One pixel of alpha
// below 1 brings alpha back into every figure.
TEST(ImageMetrics, OpaqueImagesAreComparedOverRGB)
{
  Image a(32, 32, { 0.2f, 0.4f, 0.6f, 1.f });
  Image b(32, 32, { 0.3f, 0.5f, 0.7f, 1.f });
  const auto r = art::CompareImages(a, b);
  EXPECT_EQ(r.channels, 3);
  EXPECT_NEAR(r.rmse, 0.1, 1e-7);
  EXPECT_NEAR(r.psnr, 20.0, 1e-5);
  const double C1 = 1e-4;
  auto lum = [&](double x, double y) { return (2 * x * y + C1) / (x * x + y * y + C1); };
  EXPECT_NEAR(r.ssim, (lum(0.2, 0.3) + lum(0.4, 0.5) + lum(0.6, 0.7)) / 3, 1e-6);
  b.Pixels()[3] = 0.5f;
  const auto t = art::CompareImages(a, b);
  EXPECT_EQ(t.channels, 4);
  EXPECT_NEAR(t.rmse, std::sqrt((3 * 0.01 * 1024 + 0.25) / 4096), 1e-7);
}

TEST(ImageMetrics, SsimOfConstantImagesIsTheLuminanceTerm)
{
  // For constant images the variances vanish: SSIM = (2ab + C1) / (a^2 + b^2 + C1).
  const float va = 0.2f, vb = 0.5f;
  Image a(24, 24, { va, va, va, va });
  Image b(24, 24, { vb, vb, vb, vb });
  const double C1 = 1e-4, x = va, y = vb;
  EXPECT_NEAR(art::SSIM(a, b), (2 * x * y + C1) / (x * x + y * y + C1), 1e-6);
}

TEST(ImageMetrics, SsimFallsWithNoise)
{
  const Image a = Noise(64, 64, 7);
  Image b = a, c = a;
  std::mt19937 rng(3);
  std::normal_distribution<float> n(0.f, 1.f);
  for (size_t i = 0; i < b.Pixels().size(); ++i)
  {
    const float e = n(rng);
    b.Pixels()[i] += 0.02f * e;
    c.Pixels()[i] += 0.2f * e;
  }
  const double sb = art::SSIM(a, b), sc = art::SSIM(a, c);
  EXPECT_LT(sb, 1.0);
  EXPECT_GT(sb, 0.9);
  EXPECT_LT(sc, sb);
}

TEST(ImageMetrics, DifferentSizesAreAnError)
{
  EXPECT_THROW(art::RMSE(Image(4, 4), Image(4, 5)), art::Error);
}

TEST(ImageMetrics, DifferenceImage)
{
  Image a(2, 1, { 0.5f, 0.5f, 0.5f, 1.f });
  Image b(2, 1, { 0.25f, 0.5f, 0.75f, 1.f });
  const Image d = art::DifferenceImage(a, b, 2.f);
  EXPECT_FLOAT_EQ(d.Pixel(1, 0)[0], 0.5f);
  EXPECT_FLOAT_EQ(d.Pixel(1, 0)[1], 0.0f);
  EXPECT_FLOAT_EQ(d.Pixel(1, 0)[2], 0.5f);
  EXPECT_FLOAT_EQ(d.Pixel(1, 0)[3], 1.0f);
}

// A float EXR or TIFF may hold NaN or infinity: RMSE was NaN and PSNR, read as "rmse > 0",
// infinite, so `compare --min-psnr` passed and the figures said "identical". Now an error that
// names the image and the first pixel.
TEST(ImageMetrics, NonFiniteValuesAreAnError)
{
  for (const float bad : { std::nanf(""), INFINITY })
  {
    Image a(8, 6, { 0.5f, 0.5f, 0.5f, 1.f });
    const Image b = a;
    a.Pixels()[4 * (3 * 8 + 5) + 1] = bad; // pixel (5, 3), green
    a.Pixels()[4 * (4 * 8 + 1)] = bad;
    for (const bool first : { true, false })
    {
      try
      {
        first ? art::CompareImages(a, b) : art::CompareImages(b, a);
        ADD_FAILURE() << "compared an image holding " << bad;
      }
      catch (const art::Error& e)
      {
        const std::string m = e.what();
        EXPECT_NE(m.find(first ? "the first image" : "the second image"), std::string::npos) << m;
        EXPECT_NE(m.find("holds 2 NaN or infinite channel values, the first at pixel (5, 3)"), std::string::npos) << m;
      }
    }
    EXPECT_THROW(art::PSNR(a, b), art::Error);
    EXPECT_THROW(art::SSIM(a, b), art::Error);
  }
}

// Rendered images are compared as written: composited over their background, over RGB, and
// over the object's pixels alone. A 10 x 10 black frame holding a 2 x 5 patch that differs by
// 0.1 in every channel: whole-frame RMSE sqrt(10/100) * 0.1, object RMSE 0.1 over 10 pixels.
TEST(ImageMetrics, ObjectFiguresCountOnlyTheCoveredPixels)
{
  Image a(10, 10, { 0.f, 0.f, 0.f, 0.f }), b(10, 10, { 0.f, 0.f, 0.f, 0.f });
  for (int y = 3; y < 5; ++y)
  {
    for (int x = 2; x < 7; ++x)
    {
      float* pa = a.Pixel(x, y);
      float* pb = b.Pixel(x, y);
      pa[0] = pa[1] = pa[2] = 0.3f, pa[3] = 1.f;
      pb[0] = pb[1] = pb[2] = 0.4f, pb[3] = 1.f;
    }
  }
  const auto r = art::CompareOnBackground(a, b);
  EXPECT_EQ(r.channels, 3);
  EXPECT_EQ(r.objectPixels, 10);
  EXPECT_NEAR(r.rmse, 0.1 * std::sqrt(0.1), 1e-7);
  EXPECT_NEAR(r.objectRmse, 0.1, 1e-7);
  EXPECT_NEAR(r.objectPsnr, 20.0, 1e-5);
  EXPECT_NEAR(r.psnr, 30.0, 1e-5);
  EXPECT_LT(r.objectSsim, r.ssim); // the empty frame around it agrees perfectly
  // On a white background the transparent pixels are white, and the patch stays the object.
  const auto w = art::CompareOnBackground(a, b, { 1.f, 1.f, 1.f });
  EXPECT_EQ(w.objectPixels, 10);
  EXPECT_NEAR(w.objectRmse, 0.1, 1e-7);
}

// Half-covered pixels are composited before they are compared, as in the written image: a
// premultiplied 0.2 at alpha 0.5 over a background of 0.2 is 0.2 + 0.5 * 0.2 = 0.3.
TEST(ImageMetrics, CompositesOverTheBackgroundFirst)
{
  Image a(4, 4, { 0.2f, 0.2f, 0.2f, 0.5f });
  Image b(4, 4, { 0.3f, 0.3f, 0.3f, 1.f });
  const auto r = art::CompareOnBackground(a, b, { 0.2f, 0.2f, 0.2f });
  EXPECT_NEAR(r.rmse, 0.0, 1e-7);
  EXPECT_EQ(r.objectPixels, 16);
}
