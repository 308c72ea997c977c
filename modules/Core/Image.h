// Image: a float RGBA image in row-major order, row 0 at the top (as image files store it).
// Colour values are display values in [0, 1] (VTK's transfer functions are written that way);
// alpha is coverage/opacity. The renderers produce premultiplied colour and composite over a
// background before writing, so what is stored here is what is shown.
#ifndef art_Image_h
#define art_Image_h

#include "AdaptiveRTCoreModule.h"

#include <array>
#include <cstddef>
#include <vector>

namespace art
{
class ADAPTIVERTCORE_EXPORT Image
{
public:
  using RGBA = std::array<float, 4>;

  Image() = default;
  Image(int width, int height, const RGBA& fill = { 0.f, 0.f, 0.f, 0.f });

  int Width() const { return W; }
  int Height() const { return H; }
  bool Empty() const { return W == 0 || H == 0; }

  float* Pixel(int x, int y) { return Data.data() + 4 * (static_cast<size_t>(y) * W + x); }
  const float* Pixel(int x, int y) const { return Data.data() + 4 * (static_cast<size_t>(y) * W + x); }
  void Set(int x, int y, const RGBA& c);
  RGBA Get(int x, int y) const;

  std::vector<float>& Pixels() { return Data; }
  const std::vector<float>& Pixels() const { return Data; }

  /// Premultiplied colour over an opaque background: rgb + (1 - a) * bg, alpha becomes 1.
  void CompositeOver(const std::array<float, 3>& background);

private:
  int W = 0, H = 0;
  std::vector<float> Data;
};
} // namespace art

#endif
