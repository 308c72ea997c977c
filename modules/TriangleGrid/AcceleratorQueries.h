// AcceleratorQueries: closest, any and all-hits queries written once over any traversal.
// A structure supplies Walk(prep, t0, t1, visitor): it calls visitor(ids, count, tExit) for each
// voxel the ray enters, front to back, and stops when the visitor returns true. A voxel's
// triangles not met before (mailbox) go to the triangle test, one at a time or, for a voxel of
// many, as a batch (TriangleKernels.h). Closest and All first drop triangles on a plane the ray
// crosses outside the interval wanted (PlaneCull). Closest keeps the nearest hit so far and stops
// once it lies before the current voxel's exit; Any stops at the first hit; All sorts and merges
// its hits once the walk ends.
// Point queries: a structure supplies Near(x, prune2, visitor, c), calling visitor(ids, count) for
// the voxels that may hold a triangle within sqrt(prune2) of x, nearest first where it can, and
// re-reading prune2 (which the visitor shrinks) before each; and Overlap(box, visitor) for the
// voxels that touch a box.
#ifndef art_AcceleratorQueries_h
#define art_AcceleratorQueries_h

#include "Accelerator.h"
#include "Box3.h"
#include "ClosestPoint.h"
#include "OrderedHits.h"
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

  /// Voxels and batches of fewer triangles are tested inline one at a time: filling the wide
  /// kernel's lanes costs more than it saves (tests/benchmarks/triangles-results/README.md).
  static constexpr int WideBatch = 8;
  bool Wide(std::uint32_t n) const { return n >= WideBatch && Kernel->width > 1; }

  bool Closest(const Ray& r, Hit& hit, Counters& c) const override
  {
    ++c.rays;
    hit = Hit();
    if (!r.IsValid() || !(r.tmin <= r.tmax))
    {
      return false;
    }
    const RayPrep p(r);
    PlaneCull cull(*S, p);
    Mailbox mb;
    NearestSoFar best{ r.tmax, 0, 0, -1 };
    auto visit = [&](const auto* ids, std::uint32_t n, double tExit) {
      if (!Wide(n))
      {
        for (std::uint32_t k = 0; k < n; ++k)
        {
          const std::uint32_t id = ids[k];
          if (!mb.Seen(id) && !cull.Outside(S->Record(id).plane, r.tmin, best.t))
          {
            ++c.trianglesTested;
            ClosestOfBatch(p.s, S->Data(), S->Vertices(), &id, 1, r.tmin, best);
          }
        }
        return best.record >= 0 && best.t <= tExit;
      }
      std::uint32_t batch[64];
      int m = 0;
      for (std::uint32_t k = 0; k < n; ++k)
      {
        const std::uint32_t id = ids[k];
        // A repeat is skipped before its record is touched; a plane beyond the nearest hit so far
        // (or before tmin) culls all its triangles with one distance.
        if (mb.Seen(id) || cull.Outside(S->Record(id).plane, r.tmin, best.t))
        {
          continue;
        }
        batch[m++] = id;
        if (m == 64)
        {
          TestClosest(p.s, batch, m, r.tmin, best);
          c.trianglesTested += m;
          m = 0;
        }
      }
      if (m > 0)
      {
        TestClosest(p.s, batch, m, r.tmin, best);
        c.trianglesTested += m;
      }
      // Done once the nearest hit lies in this voxel: a hit found here but lying further on
      // could still be beaten by a triangle of a later voxel.
      return best.record >= 0 && best.t <= tExit;
    };
    static_cast<const Derived*>(this)->Walk(p, r.tmin, r.tmax, visit, c);
    if (best.record < 0)
    {
      return false;
    }
    hit.t = best.t;
    hit.u = best.u;
    hit.v = best.v;
    hit.record = best.record;
    hit.triangle = S->OriginalIndex(static_cast<size_t>(best.record));
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
    Mailbox mb;
    bool found = false;
    auto visit = [&](const auto* ids, std::uint32_t n, double) {
      if (!Wide(n))
      {
        for (std::uint32_t k = 0; k < n; ++k)
        {
          const std::uint32_t id = ids[k];
          if (!mb.Seen(id))
          {
            ++c.trianglesTested;
            if (AnyOfBatch(p.s, S->Data(), S->Vertices(), &id, 1, r.tmin, r.tmax))
            {
              return found = true;
            }
          }
        }
        return false;
      }
      std::uint32_t batch[64];
      int m = 0;
      for (std::uint32_t k = 0; k < n && !found; ++k)
      {
        const std::uint32_t id = ids[k];
        if (mb.Seen(id))
        {
          continue;
        }
        batch[m++] = id;
        if (m == 64)
        {
          found = TestAny(p.s, batch, m, r.tmin, r.tmax);
          c.trianglesTested += m;
          m = 0;
        }
      }
      if (m > 0 && !found)
      {
        found = TestAny(p.s, batch, m, r.tmin, r.tmax);
        c.trianglesTested += m;
      }
      return found; // the first hit ends the walk
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
    Mailbox mb;
    BatchHits found;
    auto keep = [&](int k) {
      for (int i = 0; i < k; ++i)
      {
        Hit h;
        h.t = found.t[i];
        h.u = found.u[i];
        h.v = found.v[i];
        h.record = found.record[i];
        hits.push_back(h);
      }
    };
    auto visit = [&](const auto* ids, std::uint32_t n, double) {
      std::uint32_t batch[64];
      int m = 0;
      for (std::uint32_t k = 0; k < n; ++k)
      {
        const std::uint32_t id = ids[k];
        if (mb.Seen(id))
        {
          continue;
        }
        if (!Wide(n))
        {
          ++c.trianglesTested;
          keep(AllOfBatch(p.s, S->Data(), S->Vertices(), &id, 1, r.tmin, r.tmax, found));
          continue;
        }
        batch[m++] = id;
        if (m == 64)
        {
          keep(Kernel->all(p.s, Words(), S->Vertices(), batch, m, r.tmin, r.tmax, found));
          c.trianglesTested += m;
          m = 0;
        }
      }
      if (m > 0)
      {
        keep(Wide(static_cast<std::uint32_t>(m)) ? Kernel->all(p.s, Words(), S->Vertices(), batch, m, r.tmin, r.tmax, found)
                                                 : AllOfBatch(p.s, S->Data(), S->Vertices(), batch, m, r.tmin, r.tmax, found));
        c.trianglesTested += m;
      }
      return false;
    };
    static_cast<const Derived*>(this)->Walk(p, r.tmin, r.tmax, visit, c);
    SortAndMergeHits(*S, hits, 1e-7 * S->Bounds().Diagonal() * p.InvLength());
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

private:
  void TestClosest(const ShearedRay& r, const std::uint32_t* ids, int m, double tmin, NearestSoFar& best) const
  {
    if (Wide(static_cast<std::uint32_t>(m)))
    {
      Kernel->closest(r, Words(), S->Vertices(), ids, m, tmin, best);
      return;
    }
    ClosestOfBatch(r, S->Data(), S->Vertices(), ids, m, tmin, best);
  }
  bool TestAny(const ShearedRay& r, const std::uint32_t* ids, int m, double tmin, double tmax) const
  {
    return Wide(static_cast<std::uint32_t>(m)) ? Kernel->any(r, Words(), S->Vertices(), ids, m, tmin, tmax)
                                               : AnyOfBatch(r, S->Data(), S->Vertices(), ids, m, tmin, tmax);
  }
  const std::uint32_t* Words() const { return reinterpret_cast<const std::uint32_t*>(S->Data()); }
};
} // namespace art

#endif
