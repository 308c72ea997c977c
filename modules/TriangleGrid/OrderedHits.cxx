#include "OrderedHits.h"

#include <algorithm>
#include <limits>

namespace art
{
namespace
{
bool Before(const Hit& a, const Hit& b)
{
  return a.t < b.t || (a.t == b.t && a.record < b.record);
}
} // namespace

bool ShareVertex(const TriangleStore& s, const TriangleRecord& a, const TriangleRecord& b)
{
  const float* xyz = s.Vertices();
  for (int i = 0; i < 3; ++i)
  {
    const float* p = xyz + 3 * size_t(a.v[i]);
    for (int j = 0; j < 3; ++j)
    {
      const float* q = xyz + 3 * size_t(b.v[j]);
      if (a.v[i] == b.v[j] || (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]))
      {
        return true;
      }
    }
  }
  return false;
}

namespace
{
// Whether h repeats one of the first n hits of `kept` (sorted by t): one within tol on the same
// triangle or on one sharing a vertex with it (a ray through a shared edge or vertex meets
// several). Every kept hit within tol is looked at: a vertex may be shared by many triangles.
bool RepeatsKept(const TriangleStore& s, const std::vector<Hit>& kept, size_t n, const Hit& h, double tol)
{
  for (size_t k = n; k > 0 && h.t - kept[k - 1].t <= tol; --k)
  {
    const Hit& other = kept[k - 1];
    if (other.record == h.record ||
      ShareVertex(s, s.Record(static_cast<size_t>(other.record)), s.Record(static_cast<size_t>(h.record))))
    {
      return true;
    }
  }
  return false;
}
} // namespace

OrderedHits::OrderedHits(const TriangleStore& s, std::vector<Hit>& out, double tol)
  : S(s)
  , Out(out)
  , Tol(tol)
  , Done(-std::numeric_limits<double>::infinity())
{
  Out.clear();
}

bool OrderedHits::Repeat(const Hit& h) const
{
  return RepeatsKept(S, Out, Emitted, h, Tol);
}

void OrderedHits::EndVoxel(double tExit)
{
  if (Out.size() == Emitted)
  {
    Done = std::max(Done, tExit);
    return;
  }
  // The pending hits are few: insertion sort.
  for (size_t i = Emitted + 1; i < Out.size(); ++i)
  {
    const Hit h = Out[i];
    size_t j = i;
    for (; j > Emitted && Before(h, Out[j - 1]); --j)
    {
      Out[j] = Out[j - 1];
    }
    Out[j] = h;
  }
  size_t read = Emitted;
  for (; read < Out.size() && Out[read].t <= tExit; ++read)
  {
    if (!Repeat(Out[read]))
    {
      Out[Emitted++] = Out[read];
    }
  }
  Out.erase(Out.begin() + static_cast<std::ptrdiff_t>(Emitted), Out.begin() + static_cast<std::ptrdiff_t>(read));
  Done = std::max(Done, tExit);
}

void OrderedHits::Finish()
{
  EndVoxel(std::numeric_limits<double>::infinity());
  for (Hit& h : Out)
  {
    h.triangle = S.OriginalIndex(static_cast<size_t>(h.record));
  }
}

void SortAndMergeHits(const TriangleStore& s, std::vector<Hit>& hits, double tol)
{
  // In place, so the caller's vector keeps its capacity from ray to ray: sort, then keep each hit
  // that repeats none kept before it (RepeatsKept, as OrderedHits does with one voxel).
  std::sort(hits.begin(), hits.end(), Before);
  size_t kept = 0;
  for (size_t i = 0; i < hits.size(); ++i)
  {
    const Hit h = hits[i];
    if (!RepeatsKept(s, hits, kept, h, tol))
    {
      hits[kept] = h;
      hits[kept].triangle = s.OriginalIndex(static_cast<size_t>(h.record));
      ++kept;
    }
  }
  hits.resize(kept);
}
} // namespace art
