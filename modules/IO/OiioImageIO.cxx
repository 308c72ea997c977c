#include "OiioImageIO.h"

#include <OpenImageIO/imageio.h>

#define ART_PLUGIN_EXPORT extern "C" __attribute__((visibility("default")))

ART_PLUGIN_EXPORT bool ArtOiioWriteImage(const art::Image& img, const char* file, const char* ext, std::string& error)
{
  auto out = OIIO::ImageOutput::create(file);
  if (!out)
  {
    error = "cannot create writer: " + OIIO::geterror();
    return false;
  }
  OIIO::ImageSpec spec(img.Width(), img.Height(), 4, OIIO::TypeDesc::FLOAT);
  spec.attribute("oiio:ColorSpace", "Linear");
  spec.attribute("Software", "AdaptiveRT");
  if (std::string(ext) == ".exr")
  {
    spec.attribute("compression", "zip");
  }
  // Colour is stored straight (not premultiplied) so viewers show what the renderer meant.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(file, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, img.Pixels().data()) || !out->close())
  {
    error = "cannot write image: " + out->geterror();
    return false;
  }
  return true;
}

ART_PLUGIN_EXPORT bool ArtOiioReadImage(const char* file, art::Image& img, std::string& error)
{
  // Read colour as stored (unassociated), matching what the writers wrote.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(file, &config);
  if (!in)
  {
    error = "cannot read image: " + OIIO::geterror();
    return false;
  }
  const OIIO::ImageSpec& spec = in->spec();
  const int nc = spec.nchannels;
  if (spec.width <= 0 || spec.height <= 0 || nc <= 0)
  {
    error = "image has no pixels";
    return false;
  }
  std::vector<float> buf(static_cast<size_t>(spec.width) * spec.height * nc);
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, buf.data()))
  {
    error = "cannot read image: " + in->geterror();
    return false;
  }
  in->close();
  img = art::Image(spec.width, spec.height, { 0.f, 0.f, 0.f, 1.f });
  const int alphaIndex = spec.alpha_channel >= 0 ? spec.alpha_channel : (nc == 4 || nc == 2 ? nc - 1 : -1);
  for (int y = 0; y < spec.height; ++y)
  {
    for (int x = 0; x < spec.width; ++x)
    {
      const float* s = buf.data() + (static_cast<size_t>(y) * spec.width + x) * nc;
      float* d = img.Pixel(x, y);
      const bool grey = nc < 3;
      for (int c = 0; c < 3; ++c)
      {
        d[c] = s[grey ? 0 : c];
      }
      d[3] = alphaIndex >= 0 ? s[alphaIndex] : 1.f;
    }
  }
  return true;
}

static_assert(std::is_same_v<decltype(&ArtOiioWriteImage), ArtOiioWrite>, "the loader's signature");
static_assert(std::is_same_v<decltype(&ArtOiioReadImage), ArtOiioRead>, "the loader's signature");
