#include "VoxelReferenceCaster.h"

#include "Error.h"
#include "ExactIntegrator.h"
#include "IsoSurfaceHit.h"
#include "ParallelTiles.h"
#include "Progress.h"
#include "ValueMagnitude.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkMatrix3x3.h>
#include <vtkPointData.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace art
{
VoxelReferenceCaster::VoxelReferenceCaster(std::vector<double> values, const int dims[3], const Vec3& origin,
  const Vec3& spacing, TransferFunction tf, const int first[3])
  : V(std::move(values)), D{ dims[0], dims[1], dims[2] }, O(origin), H(spacing), TF(std::move(tf))
{
  if (D[0] < 2 || D[1] < 2 || D[2] < 2 || V.size() != static_cast<std::size_t>(D[0]) * D[1] * D[2])
  {
    throw Error("reference caster needs at least 2 x 2 x 2 voxels");
  }
  const int zero[3] = { 0, 0, 0 };
  RequireFiniteVoxels(V, D, first ? first : zero, {});
  Box = Box3(O, O + Vec3((D[0] - 1) * H.x, (D[1] - 1) * H.y, (D[2] - 1) * H.z));
}

VoxelReferenceCaster VoxelReferenceCaster::FromVTK(vtkImageData* image, TransferFunction tf, const std::string& file)
{
  vtkDataArray* s = image ? image->GetPointData()->GetScalars() : nullptr;
  if (!s)
  {
    throw Error("volume has no point scalars", file);
  }
  int d[3];
  double o[3], h[3];
  image->GetDimensions(d);
  image->GetSpacing(h);
  // The caster's origin is the first voxel's position (an extent need not start at 0); the
  // direction then turns the axes about it.
  const int* e = image->GetExtent();
  image->TransformContinuousIndexToPhysicalPoint(e[0], e[2], e[4], o);
  std::vector<double> v(s->GetNumberOfTuples());
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    v[i] = s->GetComponent(static_cast<vtkIdType>(i), 0);
  }
  try
  {
    const int first[3] = { e[0], e[2], e[4] };
    VoxelReferenceCaster rc(std::move(v), d, Vec3(o), Vec3(h), std::move(tf), first);
    if (vtkMatrix3x3* m = image->GetDirectionMatrix())
    {
      rc.SetDirection(m->GetData());
    }
    return rc;
  }
  catch (const Error& e)
  {
    throw Error(e.problem(), file);
  }
}

VoxelReferenceCaster VoxelReferenceCaster::FromVTK(vtkImageData* image, const RenderSettings& s, const std::string& file)
{
  VoxelReferenceCaster rc = FromVTK(image, s.tf, file);
  rc.SetMaxIntensity(s.mode == RenderSettings::Mode::MaxIntensity);
  rc.SetIsoSurfaces(s.isos, s.ambient, s.diffuse);
  rc.SetClipPlanes(s.clipPlanes);
  return rc;
}

void VoxelReferenceCaster::SetDirection(const double r[9])
{
  // The inverse by cofactors; a matrix whose columns are (nearly) dependent flattens the volume.
  const double c[9] = { r[4] * r[8] - r[5] * r[7], r[2] * r[7] - r[1] * r[8], r[1] * r[5] - r[2] * r[4],
    r[5] * r[6] - r[3] * r[8], r[0] * r[8] - r[2] * r[6], r[2] * r[3] - r[0] * r[5],
    r[3] * r[7] - r[4] * r[6], r[1] * r[6] - r[0] * r[7], r[0] * r[4] - r[1] * r[3] };
  const double det = r[0] * c[0] + r[1] * c[3] + r[2] * c[6];
  double scale = 0;
  for (int i = 0; i < 9; ++i)
  {
    scale = std::max(scale, std::fabs(r[i]));
  }
  if (!(std::fabs(det) > 1e-12 * scale * scale * scale))
  {
    throw Error("the volume's direction matrix is singular (its axes are not independent)");
  }
  for (int i = 0; i < 9; ++i)
  {
    Inv[i] = c[i] / det;
  }
  Turned = false;
  for (int i = 0; i < 9; ++i)
  {
    Turned |= r[i] != (i % 4 == 0 ? 1.0 : 0.0);
  }
}

double VoxelReferenceCaster::Sample(const Vec3& p) const
{
  double f[3];
  int i[3];
  for (int a = 0; a < 3; ++a)
  {
    // Clamped so that a NaN position lands on voxel 0 instead of an undefined index.
    const double q = (p[a] - O[a]) / H[a], top = double(D[a] - 1);
    const double u = q > 0.0 ? (q < top ? q : top) : 0.0;
    i[a] = std::min(static_cast<int>(u), D[a] - 2);
    f[a] = u - i[a];
  }
  const std::size_t sx = 1, sy = D[0], sz = static_cast<std::size_t>(D[0]) * D[1];
  const double* v = V.data() + i[0] + i[1] * sy + i[2] * sz;
  const double c00 = v[0] + f[0] * (v[sx] - v[0]);
  const double c10 = v[sy] + f[0] * (v[sy + sx] - v[sy]);
  const double c01 = v[sz] + f[0] * (v[sz + sx] - v[sz]);
  const double c11 = v[sz + sy] + f[0] * (v[sz + sy + sx] - v[sz + sy]);
  const double c0 = c00 + f[1] * (c10 - c00), c1 = c01 + f[1] * (c11 - c01);
  return c0 + f[2] * (c1 - c0);
}

Vec3 VoxelReferenceCaster::Gradient(const Vec3& p) const
{
  const double h = 0.5 * std::min(H.x, std::min(H.y, H.z));
  Vec3 g;
  for (int a = 0; a < 3; ++a)
  {
    Vec3 lo = p, hi = p;
    lo[a] = std::max(p[a] - h, Box.lo[a]);
    hi[a] = std::min(p[a] + h, Box.hi[a]);
    g[a] = hi[a] > lo[a] ? (Sample(hi) - Sample(lo)) / (hi[a] - lo[a]) : 0.0;
  }
  return g;
}

RenderStats VoxelReferenceCaster::Render(const Camera& cam, Image& img, Progress* progress) const
{
  const auto start = std::chrono::steady_clock::now();
  img = Image(cam.Width(), cam.Height());
  const double step = std::min(H.x, std::min(H.y, H.z)) / PerVoxel;
  const ExactIntegrator rule = ExactIntegrator::Precise(TF);
  if (progress)
  {
    progress->Begin("reference", double(cam.Width()) * cam.Height()); // ForEachTile counts pixels
  }
  // A step from sa to sb with the iso crossings on it (half-open, as the tet caster counts them).
  // r is in the volume's frame; `view` is the world ray's unit direction and len its length per
  // unit of t (the frame may shear, so both are taken from the world ray).
  auto IntegrateWithIsos = [&](const Ray& r, const Vec3& view, double ta, double dt, double len, double sa,
                             double sb, const ExactIntegrator& rule, RayAccum& acc) {
    const IsoCrossings hits(Isos, sa, sb);
    double fa = 0.0, s0 = sa;
    for (int k = 0; k < hits.n; ++k)
    {
      const IsoSurface& iso = Isos[hits.index[k]];
      rule.Integrate(s0, iso.value, (hits.fraction[k] - fa) * dt * len, acc);
      fa = hits.fraction[k];
      s0 = iso.value;
      // The world gradient is Inv^T times the frame's.
      const Vec3 gl0 = Gradient(r.At(ta + fa * dt));
      Vec3 g;
      for (int a = 0; a < 3; ++a)
      {
        g[a] = Inv[a] * gl0.x + Inv[3 + a] * gl0.y + Inv[6 + a] * gl0.z;
      }
      const double gl = Length(g);
      CompositeIsoHit(iso, Ambient + Diffuse * (gl > 0 ? std::fabs(Dot(g, view)) / gl : 1.0), acc);
    }
    rule.Integrate(s0, sb, (1.0 - fa) * dt * len, acc);
  };
  RenderStats st;
  st.counters = ForEachTile(cam.Width(), cam.Height(), 16,
    [&](const Tile& tile, Counters& c) {
      for (int y = tile.y0; y < tile.y1; ++y)
      {
        for (int x = tile.x0; x < tile.x1; ++x)
        {
          ++c.rays;
          Ray r = cam.Generate(x, y);
          double c0 = r.tmin, c1 = r.tmax; // the planes' interval, in world coordinates
          if (!r.IsValid() || !ClipToPlanes(Planes, r, c0, c1))
          {
            continue;
          }
          // Into the volume's own frame, an affine map that keeps t: world lengths (len) and the
          // view come from the world ray, the sample spacing from the frame's (lenFrame).
          const double len = Length(r.dir);
          const Vec3 view = r.dir / len;
          if (Turned)
          {
            const Vec3 q = r.org - O, d = r.dir;
            for (int a = 0; a < 3; ++a)
            {
              r.org[a] = O[a] + Inv[3 * a] * q.x + Inv[3 * a + 1] * q.y + Inv[3 * a + 2] * q.z;
              r.dir[a] = Inv[3 * a] * d.x + Inv[3 * a + 1] * d.y + Inv[3 * a + 2] * d.z;
            }
          }
          double t0, t1;
          if (!Box.Clip(r, t0, t1) || !((t1 = std::min(t1, c1)) > (t0 = std::max(t0, c0))))
          {
            continue;
          }
          ++c.hits;
          const double lenFrame = Length(r.dir);
          const int n = std::max(1, static_cast<int>(std::ceil((t1 - t0) * lenFrame / step)));
          const double dt = (t1 - t0) / n;
          RayAccum acc;
          double sa = Sample(r.At(t0)), smax = sa;
          for (int k = 1; k <= n; ++k)
          {
            const double sb = Sample(r.At(k == n ? t1 : t0 + k * dt));
            if (Mip)
            {
              smax = std::max(smax, sb);
            }
            else if (Isos.empty())
            {
              rule.Integrate(sa, sb, dt * len, acc);
            }
            else
            {
              IntegrateWithIsos(r, view, t0 + (k - 1) * dt, dt, len, sa, sb, rule, acc);
            }
            sa = sb;
          }
          c.voxelsVisited += n;
          if (Mip)
          {
            double rgb[3], tau;
            TF.Evaluate(smax, rgb, tau);
            const double a = TF.Alpha(smax);
            img.Set(x, y, { float(rgb[0] * a), float(rgb[1] * a), float(rgb[2] * a), float(a) });
          }
          else
          {
            img.Set(x, y, { float(acc.rgb[0]), float(acc.rgb[1]), float(acc.rgb[2]), float(acc.Alpha()) });
          }
        }
      }
    },
    progress);
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return st;
}
} // namespace art
