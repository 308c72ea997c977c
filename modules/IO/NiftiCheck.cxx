#include "NiftiCheck.h"
#include "AtomicFile.h"
#include "Error.h"

#include <vtk_zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <map>

namespace art
{
namespace
{
// The datatypes VTK reads, with their bits per voxel.
const std::map<int, int> Types = { { 2, 8 }, { 4, 16 }, { 8, 32 }, { 16, 32 }, { 32, 64 }, { 64, 64 }, { 128, 24 },
  { 256, 8 }, { 512, 16 }, { 768, 32 }, { 1024, 64 }, { 1280, 64 }, { 1792, 128 }, { 2304, 32 } };

template <class T>
T Get(const unsigned char* b, int at, bool swap)
{
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, b + at, sizeof(T));
  if (swap)
  {
    std::reverse(bytes, bytes + sizeof(T));
  }
  T v;
  std::memcpy(&v, bytes, sizeof(T));
  return v;
}
} // namespace

void CheckNifti(const std::string& path)
{
  unsigned char b[540] = {};
  gzFile f = gzopen(path.c_str(), "rb"); // reads plain files as they are
  if (!f)
  {
    throw Error("cannot open file", path);
  }
  const int got = gzread(f, b, sizeof b);
  gzclose(f);
  const std::int32_t size = Get<std::int32_t>(b, 0, false);
  const bool swap = size == 0x5C010000 || size == 0x1C020000; // 348 or 540, other byte order
  const std::int32_t hdr = swap ? Get<std::int32_t>(b, 0, true) : size;
  const bool magic1 = got >= 348 && (std::memcmp(b + 344, "n+1", 4) == 0 || std::memcmp(b + 344, "ni1", 4) == 0);
  const bool magic2 = got >= 12 && (std::memcmp(b + 4, "n+2", 3) == 0 || std::memcmp(b + 4, "ni2", 3) == 0);
  if ((hdr != 348 && hdr != 540) && (magic1 || magic2))
  {
    // VTK's reader went on with such a header and crashed reading it.
    throw Error("NIfTI header size (sizeof_hdr) is " + std::to_string(size) + ", expected 348 or 540", path);
  }
  if ((hdr != 348 && hdr != 540) || got < hdr)
  {
    return; // not a NIfTI header: VTK's reader says so
  }
  const bool two = hdr == 540;
  const int datatype = Get<std::int16_t>(b, two ? 12 : 70, swap);
  long long dim[8];
  double pixdim[8], voxOffset;
  for (int i = 0; i < 8; ++i)
  {
    dim[i] = two ? Get<std::int64_t>(b, 16 + 8 * i, swap) : Get<std::int16_t>(b, 40 + 2 * i, swap);
    pixdim[i] = two ? Get<double>(b, 104 + 8 * i, swap) : Get<float>(b, 76 + 4 * i, swap);
  }
  voxOffset = two ? double(Get<std::int64_t>(b, 168, swap)) : Get<float>(b, 108, swap);

  const auto type = Types.find(datatype);
  if (type == Types.end())
  {
    throw Error("NIfTI datatype " + std::to_string(datatype) +
        " is not one VTK reads (8 to 64-bit integers, float32/64, complex64/128, RGB24, RGBA32)",
      path);
  }
  const int bitpix = Get<std::int16_t>(b, two ? 14 : 72, swap);
  if (bitpix != type->second)
  {
    throw Error("NIfTI bitpix " + std::to_string(bitpix) + " does not match datatype " + std::to_string(datatype) +
        " (" + std::to_string(type->second) + " bits)",
      path);
  }
  if (dim[0] < 1 || dim[0] > 7)
  {
    throw Error("NIfTI dim[0] is " + std::to_string(dim[0]) + ", expected 1 to 7 dimensions", path);
  }
  unsigned long long voxels = 1;
  for (int i = 1; i <= dim[0]; ++i)
  {
    if (dim[i] < 1)
    {
      throw Error("NIfTI size of dimension " + std::to_string(i) + " is " + std::to_string(dim[i]), path);
    }
    if (static_cast<unsigned long long>(dim[i]) > (1ULL << 50) / voxels)
    {
      throw Error("NIfTI sizes overflow (more than 2^50 voxels)", path);
    }
    voxels *= static_cast<unsigned long long>(dim[i]);
  }
  const int sformCode = two ? Get<std::int32_t>(b, 348, swap) : Get<std::int16_t>(b, 254, swap);
  for (int i = 1; i <= std::min<long long>(dim[0], 3); ++i)
  {
    if (!std::isfinite(pixdim[i]))
    {
      throw Error("NIfTI spacing pixdim[" + std::to_string(i) + "] is not a finite number", path);
    }
    // VTK's reader reads a zero spacing as 1 without a word; only an sform places the voxels
    // without it.
    if (pixdim[i] == 0 && dim[i] > 1 && sformCode <= 0)
    {
      throw Error("NIfTI spacing pixdim[" + std::to_string(i) + "] is 0 and no sform gives the spacing", path);
    }
  }
  // An uncompressed file must hold every voxel after vox_offset (a .nii.gz is checked as VTK reads it).
  if (LowerExtension(path) == ".nii")
  {
    std::error_code ec;
    const double have = double(std::filesystem::file_size(path, ec)) - std::max(voxOffset, double(hdr));
    const double need = double(voxels) * type->second / 8.0;
    if (!ec && have < need)
    {
      char text[160];
      std::snprintf(text, sizeof text, "truncated: the header promises %.0f data bytes, the file holds %.0f", need,
        std::max(0.0, have));
      throw Error(text, path);
    }
  }
}
} // namespace art
