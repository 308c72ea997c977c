#include "SurfaceTracer.h"

#include "ParallelTiles.h"
#include "Progress.h"

#include <algorithm>
#include <cmath>

namespace art
{
std::vector<PointLight> HeadAndKeyLights(const Vec3& eye, const Vec3& focalPoint, const Vec3& viewUp)
{
  const Vec3 fwd = focalPoint - eye, u = Normalize(viewUp);
  const Vec3 right = Normalize(Cross(fwd, u));
  const double d = Length(fwd);
  return { { eye, 0.35 }, { eye + u * (0.6 * d) - right * (0.5 * d), 0.6 } };
}

SurfaceTracer::SurfaceTracer(const Accelerator& acc, SurfaceTracerSettings s)
  : Acc(acc)
  , S(std::move(s))
{
  const TriangleStore& st = acc.Store();
  Eps = 1e-5 * std::max(st.Bounds().Diagonal(), 1e-300);
  if (S.smooth)
  {
    // Area-weighted vertex normals, each triangle oriented as it was given.
    Normals.assign(st.PointCount(), Vec3());
    for (size_t i = 0; i < st.Size(); ++i)
    {
      const TriangleRecord& t = st.Record(i);
      const Vec3 n = Cross(st.Vertex(i, 1) - st.Vertex(i, 0), st.Vertex(i, 2) - st.Vertex(i, 0));
      for (int k = 0; k < 3; ++k)
      {
        Normals[t.v[k]] += n;
      }
    }
    for (Vec3& n : Normals)
    {
      n = Normalize(n);
    }
  }
}

double SurfaceTracer::Transmittance(const Vec3& from, const Vec3& to, Counters& c) const
{
  Ray r;
  r.org = from;
  r.dir = to - from;
  r.tmin = 0;
  r.tmax = 1;
  if (S.opacity >= 1.0)
  {
    return Acc.Any(r, c) ? 0.0 : 1.0;
  }
  // The paper's use of the all-hits query: every surface between the point and the light dims it.
  thread_local std::vector<Hit> hits;
  Acc.All(r, hits, c);
  return std::pow(1.0 - S.opacity, double(hits.size()));
}

std::array<float, 3> SurfaceTracer::Shade(const Ray& r, const Hit& h, Counters& c) const
{
  const TriangleStore& st = Acc.Store();
  const size_t rec = static_cast<size_t>(h.record);
  const TriangleRecord& t = st.Record(rec);
  const double w0 = 1.0 - h.u - h.v;
  const Vec3 p = r.At(h.t);
  Vec3 ng = Normalize(Cross(st.Vertex(rec, 1) - st.Vertex(rec, 0), st.Vertex(rec, 2) - st.Vertex(rec, 0)));
  Vec3 n = ng;
  if (S.smooth)
  {
    n = Normalize(Normals[t.v[0]] * w0 + Normals[t.v[1]] * h.u + Normals[t.v[2]] * h.v);
    if (Dot(n, ng) < 0)
    {
      n = -n; // vertex normals of an inconsistently wound mesh
    }
  }
  // Two-sided: shade the side the ray sees.
  if (Dot(ng, r.dir) > 0)
  {
    ng = -ng;
    n = -n;
  }
  std::array<float, 3> base = S.color;
  if (!Colors.empty())
  {
    for (int k = 0; k < 3; ++k)
    {
      base[k] = float(w0 * Colors[t.v[0]][k] + h.u * Colors[t.v[1]][k] + h.v * Colors[t.v[2]][k]);
    }
  }
  double light = S.ambient;
  const Vec3 origin = p + ng * Eps; // leave the surface on the lit side
  for (const PointLight& L : S.lights)
  {
    const Vec3 d = L.position - p;
    const double len = Length(d);
    const double cosine = len > 0 ? Dot(n, d) / len : 0.0;
    if (cosine <= 0 || Dot(ng, d) <= 0)
    {
      continue;
    }
    const double tr = S.shadows ? Transmittance(origin, L.position, c) : 1.0;
    light += L.intensity * cosine * tr;
  }
  return { float(base[0] * light), float(base[1] * light), float(base[2] * light) };
}

Image::RGBA SurfaceTracer::Trace(const Ray& r, Counters& c) const
{
  if (S.opacity >= 1.0)
  {
    Hit h;
    if (!Acc.Closest(r, h, c))
    {
      return { 0.f, 0.f, 0.f, 0.f };
    }
    const auto s = Shade(r, h, c);
    return { std::min(s[0], 1.f), std::min(s[1], 1.f), std::min(s[2], 1.f), 1.f };
  }
  thread_local std::vector<Hit> hits;
  Acc.All(r, hits, c);
  double rgb[3] = { 0, 0, 0 }, a = 0;
  const double alpha = std::max(0.0, S.opacity);
  for (size_t i = 0; i < hits.size() && int(i) < S.maxLayers && a < 0.995; ++i)
  {
    const auto s = Shade(r, hits[i], c);
    for (int k = 0; k < 3; ++k)
    {
      rgb[k] += (1 - a) * alpha * std::min(s[k], 1.f);
    }
    a += (1 - a) * alpha;
  }
  return { float(rgb[0]), float(rgb[1]), float(rgb[2]), float(a) };
}

Image SurfaceTracer::Render(const Camera& cam, Progress* progress, Counters* stats) const
{
  Image img(cam.Width(), cam.Height());
  SurfaceTracer copy = *this; // settings as given; a headlight when there is no light
  if (copy.S.lights.empty())
  {
    copy.S.lights.push_back({ cam.Position(), 0.85 });
  }
  const Counters c = ForEachTile(cam.Width(), cam.Height(), 16, [&](const Tile& t, Counters& cnt) {
    for (int y = t.y0; y < t.y1; ++y)
    {
      for (int x = t.x0; x < t.x1; ++x)
      {
        img.Set(x, y, copy.Trace(cam.Generate(x, y), cnt));
      }
    }
  }, progress);
  if (stats)
  {
    *stats += c;
  }
  return img;
}
} // namespace art
