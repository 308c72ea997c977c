// AcceleratorQueries: closest, any and all-hits queries written once over any traversal.
// A structure supplies Walk(prep, t0, t1, visitor): it calls visitor(ids, count, tExit) for each
// voxel the ray enters, front to back, and stops when the visitor returns true. Closest keeps the
// nearest hit found so far and stops once it lies before the current voxel's exit (so a hit found
// in an earlier voxel but lying further on is never taken for the answer too early).
// Point queries: a structure supplies Near(x, prune2, visitor, c), calling visitor(ids, count) for
// the voxels that may hold a triangle within sqrt(prune2) of x, nearest first where it can, and
// re-reading prune2 (which the visitor shrinks) before each; and Overlap(box, visitor) for the
// voxels that touch a box.
#ifndef art_AcceleratorQueries_h
#define art_AcceleratorQueries_h

#include "Accelerator.h"
#include "Box3.h"
#include "ClosestPoint.h"
#include "TriBoxOverlap.h"
#include "WatertightTest.h"

#include <algorithm>
#include <cmath>

namespace art
{
template <class Derived>
class WalkingAccelerator : public Accelerator
{
public:
  using Accelerator::Accelerator;

  bool Closest(const Ray& r, Hit& hit, Counters& c) const override
  {
    ++c.rays;
    hit = Hit();
    if (!r.IsValid() || !(r.tmin <= r.tmax))
    {
      return false;
    }
    const RayPrep p(r);
    const TriangleRecord* rec = S->Data();
    const float* xyz = S->Vertices();
    const PlaneRecord* planes = S->Planes().data();
    const double planeMargin = 1e-5 * S->Bounds().Diagonal();
    Mailbox mb;
    double best = r.tmax, bu = 0, bv = 0;
    long long bestRec = -1;
    std::uint32_t checkedPlane = ~0u;
    bool planeCulled = false;
    auto visit = [&](const auto* ids, std::uint32_t n, double tExit) {
      for (std::uint32_t k = 0; k < n; ++k)
      {
        const std::uint32_t id = ids[k];
        if (mb.Seen(id))
        {
          continue; // before touching the record: a repeat costs no memory traffic
        }
        const TriangleRecord& t = rec[id];
        if (t.plane != TriangleRecord::NoPlane)
        {
          // Coplanar triangles share a plane: one ray/plane distance culls them all when the
          // plane lies beyond the nearest hit so far (or before tmin).
          if (t.plane != checkedPlane)
          {
            checkedPlane = t.plane;
            const PlaneRecord& pl = planes[t.plane];
            const double den = pl.n[0] * p.dir[0] + pl.n[1] * p.dir[1] + pl.n[2] * p.dir[2];
            const double num = pl.d - (pl.n[0] * p.org[0] + pl.n[1] * p.org[1] + pl.n[2] * p.org[2]);
            planeCulled = false;
            if (den != 0.0)
            {
              const double tp = num / den, margin = planeMargin / std::fabs(den);
              planeCulled = tp > best + margin || tp < r.tmin - margin;
            }
          }
          if (planeCulled)
          {
            continue; // for good: the bound only shrinks
          }
        }
        ++c.trianglesTested;
        double th, u, v;
        // Of hits at equal t the lowest record (the lowest input index) wins, so the answer does
        // not depend on the order a structure meets its triangles in.
        if (IntersectTriangle(p, xyz, t, r.tmin, best, th, u, v) && (th < best || bestRec < 0 || id < bestRec))
        {
          best = th;
          bu = u;
          bv = v;
          bestRec = id;
          checkedPlane = ~0u; // the bound moved: planes must be checked again
        }
      }
      return bestRec >= 0 && best <= tExit;
    };
    static_cast<const Derived*>(this)->Walk(p, r.tmin, r.tmax, visit, c);
    if (bestRec < 0)
    {
      return false;
    }
    hit.t = best;
    hit.u = bu;
    hit.v = bv;
    hit.record = bestRec;
    hit.triangle = S->OriginalIndex(static_cast<size_t>(bestRec));
    ++c.hits;
    return true;
  }

  bool Any(const Ray& r, Counters& c) const override
  {
    ++c.rays;
    if (!r.IsValid() || !(r.tmin <= r.tmax))
    {
      return false;
    }
    const RayPrep p(r);
    const TriangleRecord* rec = S->Data();
    const float* xyz = S->Vertices();
    Mailbox mb;
    bool found = false;
    auto visit = [&](const auto* ids, std::uint32_t n, double) {
      for (std::uint32_t k = 0; k < n; ++k)
      {
        if (mb.Seen(ids[k]))
        {
          continue;
        }
        ++c.trianglesTested;
        double th, u, v;
        if (IntersectTriangle(p, xyz, rec[ids[k]], r.tmin, r.tmax, th, u, v))
        {
          found = true;
          return true;
        }
      }
      return false;
    };
    static_cast<const Derived*>(this)->Walk(p, r.tmin, r.tmax, visit, c);
    c.hits += found ? 1 : 0;
    return found;
  }

  void All(const Ray& r, std::vector<Hit>& hits, Counters& c) const override
  {
    ++c.rays;
    hits.clear();
    if (!r.IsValid() || !(r.tmin <= r.tmax))
    {
      return;
    }
    const RayPrep p(r);
    const TriangleRecord* rec = S->Data();
    const float* xyz = S->Vertices();
    Mailbox mb;
    auto visit = [&](const auto* ids, std::uint32_t n, double) {
      for (std::uint32_t k = 0; k < n; ++k)
      {
        if (mb.Seen(ids[k]))
        {
          continue;
        }
        ++c.trianglesTested;
        Hit h;
        if (IntersectTriangle(p, xyz, rec[ids[k]], r.tmin, r.tmax, h.t, h.u, h.v))
        {
          h.record = ids[k];
          hits.push_back(h);
        }
      }
      return false;
    };
    static_cast<const Derived*>(this)->Walk(p, r.tmin, r.tmax, visit, c);
    SortAndMergeHits(*S, hits, 1e-7 * S->Bounds().Diagonal() * p.invLen);
    c.hits += hits.empty() ? 0 : 1;
  }

  bool ClosestPoint(const Vec3& x, double maxDist2, NearestPoint& out, Counters& c) const override
  {
    out = NearestPoint();
    if (!IsFinite(x) || !(maxDist2 > 0))
    {
      return false;
    }
    const TriangleRecord* rec = S->Data();
    const double slack = FloatSlack(S->Bounds());
    double best2 = maxDist2;
    double prune2 = std::isinf(maxDist2) ? maxDist2 : (std::sqrt(maxDist2) + slack) * (std::sqrt(maxDist2) + slack);
    Mailbox mb;
    auto visit = [&](const auto* ids, std::uint32_t n) {
      for (std::uint32_t k = 0; k < n; ++k)
      {
        const std::uint32_t id = ids[k];
        if (mb.Seen(id))
        {
          continue;
        }
        // The triangle's box first: a lower bound that is cheap (most triangles of a far voxel
        // end here); the float box is within `slack` of the double triangle, as prune2 allows.
        const TriangleBox tb = S->RecordBox(id);
        const double blo[3] = { tb.lo[0], tb.lo[1], tb.lo[2] }, bhi[3] = { tb.hi[0], tb.hi[1], tb.hi[2] };
        if (BoxDistance2(blo, bhi, x) > prune2)
        {
          continue;
        }
        ++c.trianglesTested;
        const TriangleRecord& t = rec[id];
        Vec3 q;
        double u, v;
        const bool in = ClosestPointOnTriangle(x, S->Point(t.v[0]), S->Point(t.v[1]), S->Point(t.v[2]), q, u, v);
        const Vec3 e = x - q;
        const double d2 = Dot(e, e);
        // Ties go to the lowest input index, so every structure gives the same answer.
        if (d2 < best2 || (d2 == best2 && out.record >= 0 && S->OriginalIndex(id) < out.triangle))
        {
          best2 = d2;
          out.dist2 = d2;
          out.point = q;
          out.record = id;
          out.triangle = S->OriginalIndex(id);
          out.u = u;
          out.v = v;
          out.inside = in;
          const double r = std::sqrt(d2) + slack;
          prune2 = r * r;
        }
      }
    };
    static_cast<const Derived*>(this)->Near(x, prune2, visit, c);
    if (out.record < 0)
    {
      out = NearestPoint();
      return false;
    }
    ++c.hits;
    return true;
  }

  void InBox(const Box3& query, std::vector<long long>& out, Counters& c) const override
  {
    out.clear();
    // An infinite side reaches past every triangle: the scene's bounds (padded) stand in for it,
    // as VTK's locators return every cell there (it found none). NaN finds nothing.
    Box3 box = query;
    const Box3 all = S->Bounds();
    for (int a = 0; a < 3; ++a)
    {
      if (std::isinf(box.lo[a]) && box.lo[a] < 0)
      {
        box.lo[a] = std::min(all.lo[a], box.hi[a]) - 1.0;
      }
      if (std::isinf(box.hi[a]) && box.hi[a] > 0)
      {
        box.hi[a] = std::max(all.hi[a], box.lo[a]) + 1.0;
      }
    }
    if (box.Empty() || !IsFinite(box.lo) || !IsFinite(box.hi))
    {
      return;
    }
    std::vector<std::uint32_t> recs;
    auto visit = [&](const auto* ids, std::uint32_t n) {
      ++c.voxelsVisited;
      recs.insert(recs.end(), ids, ids + n);
    };
    static_cast<const Derived*>(this)->Overlap(box, visit);
    std::sort(recs.begin(), recs.end());
    recs.erase(std::unique(recs.begin(), recs.end()), recs.end());
    const Vec3 centre = box.Center(), half = box.Size() * 0.5;
    for (std::uint32_t id : recs)
    {
      ++c.trianglesTested;
      const TriangleRecord& t = S->Record(id);
      if (TriBoxOverlap(centre, half, S->Point(t.v[0]), S->Point(t.v[1]), S->Point(t.v[2])))
      {
        out.push_back(S->OriginalIndex(id));
      }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

  void Candidates(const Ray& r, std::vector<long long>& out, Counters& c) const override
  {
    out.clear();
    if (!r.IsValid() || !(r.tmin <= r.tmax))
    {
      return;
    }
    const RayPrep p(r);
    auto visit = [&](const auto* ids, std::uint32_t n, double) {
      for (std::uint32_t k = 0; k < n; ++k)
      {
        out.push_back(S->OriginalIndex(ids[k]));
      }
      return false;
    };
    static_cast<const Derived*>(this)->Walk(p, r.tmin, r.tmax, visit, c);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }
};
} // namespace art

#endif
