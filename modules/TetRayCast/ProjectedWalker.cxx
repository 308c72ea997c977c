#include "ProjectedWalker.h"

#include "ParallelTiles.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace art
{
ProjectedView::ProjectedView(const TetMesh& m, const Camera& cam)
  : M(m), V(m.NumberOfPoints()), Eye(cam.Position()), Fwd(cam.Forward()), Parallel(cam.IsParallel())
{
  // Any right-handed frame around the view direction will do: the rays' own pixel positions are
  // taken in the same frame (ProjectedWalker), so the camera's up vector is not needed.
  const Vec3 a = std::fabs(Fwd.x) < 0.6 ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  R = Normalize(Cross(a, Fwd));
  U = Cross(Fwd, R);
  // Vertices this close to the eye's plane would make 1/z blow up; they are rare (a camera at the
  // mesh) and the 3-D walker handles them.
  const double nearZ = 1e-6 * std::max(m.Bounds().Diagonal(), 1e-300);
  std::atomic<bool> bad{ false };
  constexpr long long grain = 1 << 14; // chunks start at multiples of it: one extent slot each
  std::vector<double> extent(static_cast<std::size_t>((V.size() + grain - 1) / grain), 0.0);
  const Vec3* P = m.PointsArray().data();
  const double* F = m.Scalars().data();
  ForEachRange(static_cast<long long>(V.size()), grain, [&](long long b, long long e, Counters&) {
    bool near = false;
    double a = 0;
    for (long long i = b; i < e; ++i)
    {
      const Vec3 q = P[i] - Eye;
      const double x = Dot(q, R), y = Dot(q, U), z = Dot(q, Fwd);
      if (Parallel)
      {
        V[i] = { x, y, z, F[i] };
        a = std::max(a, std::fabs(x) + std::fabs(y) + std::fabs(z));
        continue;
      }
      near = near || !(z > nearZ);
      const double w = 1.0 / z;
      V[i] = { x * w, y * w, w, F[i] * w };
      a = std::max(a, std::fabs(x * w) + std::fabs(y * w));
    }
    extent[static_cast<std::size_t>(b / grain)] = a;
    if (near)
    {
      bad = true;
    }
  });
  for (double a : extent)
  {
    Amax = std::max(Amax, a);
  }
  // A vertex at a grazing angle (|x/z| beyond 1000) would make the rounding bound of every
  // product large and send most of them to the 3-D fallback: the 3-D walker does better.
  Ok = !bad && IsFinite(R) && IsFinite(U) && (Parallel || Amax < 1e3);
}
} // namespace art
