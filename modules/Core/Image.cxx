#include "Image.h"

#include <algorithm>

namespace art
{
Image::Image(int width, int height, const RGBA& fill)
  : W(std::max(0, width))
  , H(std::max(0, height))
  , Data(static_cast<size_t>(W) * H * 4)
{
  for (size_t i = 0; i < Data.size(); i += 4)
  {
    std::copy(fill.begin(), fill.end(), Data.begin() + i);
  }
}

void Image::Set(int x, int y, const RGBA& c)
{
  std::copy(c.begin(), c.end(), Pixel(x, y));
}

Image::RGBA Image::Get(int x, int y) const
{
  const float* p = Pixel(x, y);
  return { p[0], p[1], p[2], p[3] };
}

void Image::CompositeOver(const std::array<float, 3>& bg)
{
  for (size_t i = 0; i < Data.size(); i += 4)
  {
    const float t = 1.f - Data[i + 3];
    for (int c = 0; c < 3; ++c)
    {
      Data[i + c] += t * bg[c];
    }
    Data[i + 3] = 1.f;
  }
}
} // namespace art
