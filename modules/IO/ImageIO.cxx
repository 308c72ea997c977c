#include "ImageIO.h"
#include "AtomicFile.h"
#include "Error.h"

#include <OpenImageIO/imageio.h>

#include <filesystem>

namespace art
{
bool IsImageExtension(const std::string& path)
{
  const std::string e = LowerExtension(path);
  return e == ".png" || e == ".exr" || e == ".tif" || e == ".tiff";
}

void WriteImage(const Image& img, const std::string& path)
{
  if (!IsImageExtension(path))
  {
    throw Error("unknown image type '" + LowerExtension(path) + "' (use .png, .exr or .tif)", path);
  }
  if (img.Empty())
  {
    throw Error("refusing to write an empty image", path);
  }
  AtomicFile file(path);
  auto out = OIIO::ImageOutput::create(file.TempPath());
  if (!out)
  {
    throw Error("cannot create writer: " + OIIO::geterror(), path);
  }
  const std::string ext = LowerExtension(path);
  const OIIO::TypeDesc type = ext == ".png" ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
  OIIO::ImageSpec spec(img.Width(), img.Height(), 4, type);
  spec.attribute("oiio:ColorSpace", ext == ".png" ? "sRGB" : "Linear");
  spec.attribute("Software", "AdaptiveRT");
  if (ext == ".exr")
  {
    spec.attribute("compression", "zip");
  }
  // Colour is stored straight (not premultiplied) so viewers show what the renderer meant.
  spec.attribute("oiio:UnassociatedAlpha", 1);
  if (!out->open(file.TempPath(), spec) ||
    !out->write_image(OIIO::TypeDesc::FLOAT, img.Pixels().data()) || !out->close())
  {
    throw Error("cannot write image: " + out->geterror(), path);
  }
  file.Commit();
}

Image ReadImage(const std::string& path)
{
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
  {
    throw Error("no such file", path);
  }
  if (std::filesystem::is_directory(path, ec))
  {
    throw Error("is a directory, expected an image file", path);
  }
  // Read colour as stored (unassociated), matching what WriteImage wrote.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in)
  {
    throw Error("cannot read image: " + OIIO::geterror(), path);
  }
  const OIIO::ImageSpec& spec = in->spec();
  const int nc = spec.nchannels;
  if (spec.width <= 0 || spec.height <= 0 || nc <= 0)
  {
    throw Error("image has no pixels", path);
  }
  std::vector<float> buf(static_cast<size_t>(spec.width) * spec.height * nc);
  if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, buf.data()))
  {
    throw Error("cannot read image: " + in->geterror(), path);
  }
  in->close();
  Image img(spec.width, spec.height, { 0.f, 0.f, 0.f, 1.f });
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
  return img;
}
} // namespace art
