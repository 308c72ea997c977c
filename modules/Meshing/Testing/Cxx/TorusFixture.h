// A torus (ring radius R about the z axis, tube radius r) as a closed triangle surface whose
// vertices lie on it, and the analytic figures the meshing tests compare against.
#ifndef art_TorusFixture_h
#define art_TorusFixture_h

#include "SurfaceCheck.h"

#include <cmath>

namespace fixtures
{
struct Torus
{
  double R = 1.0, r = 0.4;
  int nu = 128, nv = 48; ///< quads around the ring and around the tube

  double Volume() const { return 2.0 * M_PI * M_PI * R * r * r; }
  /// Distance from p to the tube's centre circle (<= r inside).
  double TubeDistance(const double p[3]) const
  {
    const double rho = std::hypot(p[0], p[1]);
    return std::hypot(rho - R, p[2]);
  }
  /// Largest distance of a flat triangle's points beyond the smooth torus (chord sag).
  double Sag() const { return (R + r) * (1 - std::cos(M_PI / nu)) + r * (1 - std::cos(M_PI / nv)); }

  art::TriangleSurface Surface() const
  {
    art::TriangleSurface s;
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j)
      {
        const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
        s.Points.insert(s.Points.end(),
          { (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v) });
      }
    auto id = [&](int i, int j) { return (i % nu) * nv + (j % nv); };
    for (int i = 0; i < nu; ++i)
      for (int j = 0; j < nv; ++j)
      {
        s.Triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
        s.Triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
      }
    return s;
  }
};
} // namespace fixtures

#endif
