// SegmentCompositor: what the face-to-face walk does with each tet it crosses (Grosso, Luerig &
// Ertl 1997, sec. 5): the ray's segment in the tet, cut where the ray starts (a clipping plane or
// a ray from inside the box) or ends (opaque geometry in the scene), then composited front to
// back by the segment rule, with the iso-surfaces it crosses and the volume shaded (Phong with a
// headlight through the tet's own gradient, as VTK's ShadeOn), or its largest scalar kept for a
// maximum-intensity projection; false ends the walk (early ray termination, the ray's end). The
// modes are template parameters, so the walk carries no test for a mode it is not in.
#ifndef art_SegmentCompositor_h
#define art_SegmentCompositor_h

#include "FaceWalk.h"
#include "IsoSurfaceHit.h"
#include "Ray.h"
#include "SegmentRule.h"
#include "TetMesh.h"
#include "TetRayCaster.h"

#include <algorithm>
#include <cmath>

namespace art
{
enum class CompositeMode
{
  Volume,     ///< emission-absorption
  VolumeLit,  ///< emission-absorption with iso-surfaces, volume shading or both
  Maximum     ///< maximum intensity
};

template <class Rule, CompositeMode Mode>
class SegmentCompositor
{
public:
  /// For ray r, integrated from `from` on (in its t) and up to r.tmax.
  SegmentCompositor(const TetMesh& m, const RenderSettings& s, const Rule& rule, const Ray& r, double from,
    RayResult& res)
    : M(m), S(s), R(rule), Org(r.org), Dir(r.dir), DirLen(Length(r.dir)), View(r.dir / DirLen), From(from),
      TMax(r.tmax), Ert(s.earlyTermination), Res(res)
  {
  }

  /// The walk's visit: tet t from crossing `enter` to crossing `whole`.
  ART_ALWAYS_INLINE bool operator()(int t, const FaceCrossing& enter, const FaceCrossing& whole)
  {
    FaceCrossing in = enter, ex = whole;
    if (__builtin_expect(in.t < From, 0) && !CutBeforeOrigin(in, whole))
    {
      return true;
    }
    const bool ends = whole.t > TMax;
    if (ends)
    {
      CutAtRayEnd(in, whole, ex);
    }
    if constexpr (Mode == CompositeMode::Maximum)
    {
      Res.maxScalar = std::max(Res.maxScalar, std::max(in.s, ex.s));
      return !ends;
    }
    else
    {
      const double len = (ex.t - in.t) * DirLen;
      if constexpr (Mode == CompositeMode::VolumeLit)
      {
        WithIsoHits(t, in, ex, len);
      }
      else
      {
        R.Integrate(in.s, ex.s, len, Acc);
      }
      if (ends || EarlyTerminated(Acc, Ert))
      {
        Stop = true;
        return false;
      }
      return true;
    }
  }

  /// The walk ended the ray (early termination or its end), so no later piece is walked.
  bool Stopped() const { return Stop; }
  const RayAccum& Accumulated() const { return Acc; }

private:
  /// A ray traced from before its origin adds nothing before it: the segment is cut there, its
  /// scalar interpolated. False when the whole segment lies before it.
  bool CutBeforeOrigin(FaceCrossing& in, const FaceCrossing& whole) const
  {
    if (whole.t <= From)
    {
      return false;
    }
    in.s += (From - in.t) / (whole.t - in.t) * (whole.s - in.s);
    in.t = From;
    return true;
  }

  /// The ray ends inside this tet (at opaque geometry in front of the exit): the segment is cut
  /// there, the scalar interpolated linearly along it, and the walk stops.
  void CutAtRayEnd(const FaceCrossing& in, const FaceCrossing& whole, FaceCrossing& ex)
  {
    const double f = whole.t > in.t ? std::max(0.0, (TMax - in.t) / (whole.t - in.t)) : 0.0;
    ex.t = std::max(in.t, TMax);
    ex.s = in.s + f * (whole.s - in.s);
    Stop = true;
  }

  /// The volume up to each iso-surface crossed, the surface shaded by the vertex gradients
  /// interpolated at the hit (Gouraud style), then the rest of the segment.
  void WithIsoHits(int t, const FaceCrossing& in, const FaceCrossing& ex, double len)
  {
    const IsoCrossings hits(S.isos, in.s, ex.s);
    double fa = 0.0, sa = in.s;
    for (int k = 0; k < hits.n; ++k)
    {
      const IsoSurface& iso = S.isos[hits.index[k]];
      Lit(t, sa, iso.value, len * (hits.fraction[k] - fa));
      fa = hits.fraction[k];
      sa = iso.value;
      const double tHit = in.t + fa * (ex.t - in.t);
      double bw[4];
      M.Barycentric(t, Org + Dir * tHit, bw);
      const auto& tv = M.Tet(t);
      Vec3 g;
      for (int i = 0; i < 4; ++i)
      {
        g += M.VertexGradient(tv[i]) * bw[i];
      }
      CompositeIsoHit(iso, S.ambient + S.diffuse * std::fabs(Dot(Normalize(g), View)), Acc);
      if (Res.firstIso < 0)
      {
        Res.firstIso = tHit;
      }
    }
    Lit(t, sa, ex.s, len * (1.0 - fa));
  }

  /// The segment from scalar s0 to s1 in tet t, shaded when asked. The tet's gradient is one
  /// vector, so the light's factors are constant over the segment: its colour is
  /// (ka + kd |n.v|) C + ks |n.v|^p W, whose integral is that factor times the unlit segment's
  /// colour plus the specular weight times the opacity it adds (exact under either rule). A tet
  /// with no gradient (a constant field) gets the ambient term only.
  void Lit(int t, double s0, double s1, double len)
  {
    if (!S.shading.on)
    {
      R.Integrate(s0, s1, len, Acc);
      return;
    }
    const double rgb0[3] = { Acc.rgb[0], Acc.rgb[1], Acc.rgb[2] }, T0 = Acc.T;
    R.Integrate(s0, s1, len, Acc);
    const auto& ip = M.Interpolant(t);
    const Vec3 g(ip[1], ip[2], ip[3]);
    const double gl = Length(g);
    const double nv = gl > 0.0 ? std::fabs(Dot(g, View)) / gl : 0.0; // the light is at the eye
    const RenderSettings::Shading& sh = S.shading;
    const double a = sh.ambient + sh.diffuse * nv;
    const double spec = nv > 0.0 ? sh.specular * std::pow(nv, sh.power) * (T0 - Acc.T) : 0.0;
    for (int k = 0; k < 3; ++k)
    {
      Acc.rgb[k] = rgb0[k] + a * (Acc.rgb[k] - rgb0[k]) + spec;
    }
  }

  const TetMesh& M;
  const RenderSettings& S;
  const Rule& R;
  const Vec3 Org, Dir;
  const double DirLen;
  const Vec3 View;
  const double From, TMax, Ert;
  RayResult& Res;
  RayAccum Acc;
  bool Stop = false;
};
} // namespace art

#endif
