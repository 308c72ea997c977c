// IsoSurfaceHit: iso-surfaces inside the emission-absorption integral (Grosso, Luerig & Ertl 1997,
// sec. 5). On a segment where the scalar is linear, an iso-value is crossed where the end values
// bracket it (half-open, so a crossing on a face shared by two segments counts once); the volume
// is integrated up to each crossing and the surface composited there with a constant opacity and
// a headlight shade, ambient + diffuse |n . view|, from the field's gradient at the hit.
#ifndef art_IsoSurfaceHit_h
#define art_IsoSurfaceHit_h

#include "SegmentRule.h"
#include "Vec3.h"

#include <array>
#include <utility>
#include <vector>

namespace art
{
struct IsoSurface
{
  double value;
  std::array<double, 3> rgb{ { 1, 1, 1 } };
  double opacity = 1.0; ///< constant surface opacity
};

/// The iso-values a segment from scalar s0 to s1 crosses, in the order the ray meets them: the
/// fraction along the segment and the iso-surface's index, at most 8.
struct IsoCrossings
{
  int n = 0;
  double fraction[8];
  int index[8];

  IsoCrossings(const std::vector<IsoSurface>& isos, double s0, double s1)
  {
    for (std::size_t k = 0; k < isos.size() && n < 8; ++k)
    {
      const double v = isos[k].value;
      if ((s0 < v) != (s1 < v))
      {
        fraction[n] = (v - s0) / (s1 - s0);
        index[n++] = static_cast<int>(k);
      }
    }
    for (int a = 1; a < n; ++a)
    {
      for (int b = a; b > 0 && fraction[b] < fraction[b - 1]; --b)
      {
        std::swap(fraction[b], fraction[b - 1]);
        std::swap(index[b], index[b - 1]);
      }
    }
  }
};

/// Composites the surface `iso`, shaded by `shade`, behind `acc`.
inline void CompositeIsoHit(const IsoSurface& iso, double shade, RayAccum& acc)
{
  for (int ch = 0; ch < 3; ++ch)
  {
    acc.rgb[ch] += acc.T * iso.opacity * shade * iso.rgb[ch];
  }
  acc.T *= 1.0 - iso.opacity;
}
} // namespace art

#endif
