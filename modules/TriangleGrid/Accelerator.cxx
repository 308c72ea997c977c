#include "Accelerator.h"

#include "BruteForce.h"
#include "Error.h"
#include "Octree.h"
#include "ParallelTiles.h"
#include "RecursiveGrid.h"
#include "UniformGrid.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace art
{
Counters Accelerator::ClosestBatch(const std::vector<Ray>& rays, std::vector<Hit>& hits) const
{
  hits.assign(rays.size(), Hit());
  return ForEachRange(static_cast<long long>(rays.size()), 1024, [&](long long b, long long e, Counters& c) {
    for (long long i = b; i < e; ++i)
    {
      Closest(rays[i], hits[i], c);
    }
  });
}

Counters Accelerator::ClosestPointBatch(const std::vector<Vec3>& xs, std::vector<NearestPoint>& out) const
{
  out.assign(xs.size(), NearestPoint());
  return ForEachRange(static_cast<long long>(xs.size()), 256, [&](long long b, long long e, Counters& c) {
    for (long long i = b; i < e; ++i)
    {
      ClosestPoint(xs[i], std::numeric_limits<double>::infinity(), out[i], c);
    }
  });
}

Counters Accelerator::AnyBatch(const std::vector<Ray>& rays, std::vector<unsigned char>& occluded) const
{
  occluded.assign(rays.size(), 0);
  return ForEachRange(static_cast<long long>(rays.size()), 1024, [&](long long b, long long e, Counters& c) {
    for (long long i = b; i < e; ++i)
    {
      occluded[i] = Any(rays[i], c) ? 1 : 0;
    }
  });
}

namespace
{
bool ShareVertex(const TriangleStore& s, const TriangleRecord& a, const TriangleRecord& b)
{
  // By position, not index: polygon soups repeat points for each face.
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
} // namespace

void SortAndMergeHits(const TriangleStore& s, std::vector<Hit>& hits, double tol)
{
  std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) {
    return a.t < b.t || (a.t == b.t && a.record < b.record);
  });
  std::vector<Hit> out;
  out.reserve(hits.size());
  for (const Hit& h : hits)
  {
    bool repeat = false;
    // Compare with every kept hit within tol (a vertex may be shared by many triangles).
    for (auto it = out.rbegin(); it != out.rend() && h.t - it->t <= tol; ++it)
    {
      if (it->record == h.record ||
        ShareVertex(s, s.Record(static_cast<size_t>(it->record)), s.Record(static_cast<size_t>(h.record))))
      {
        repeat = true;
        break;
      }
    }
    if (!repeat)
    {
      out.push_back(h);
    }
  }
  for (Hit& h : out)
  {
    h.triangle = s.OriginalIndex(static_cast<size_t>(h.record));
  }
  hits.swap(out);
}

std::vector<std::uint32_t> PlaneOrder(const TriangleStore& s)
{
  std::vector<std::uint32_t> ids(s.Size());
  std::iota(ids.begin(), ids.end(), 0u);
  std::stable_sort(ids.begin(), ids.end(),
    [&s](std::uint32_t a, std::uint32_t b) { return s.Record(a).plane < s.Record(b).plane; });
  return ids;
}

std::unique_ptr<Accelerator> MakeAccelerator(std::shared_ptr<const TriangleStore> store, const AcceleratorOptions& o)
{
  if (!store)
  {
    throw Error("no triangle store given");
  }
  switch (o.kind)
  {
    case AcceleratorKind::BruteForce:
      return std::unique_ptr<Accelerator>(new BruteForce(std::move(store)));
    case AcceleratorKind::UniformGrid:
      return std::unique_ptr<Accelerator>(new UniformGrid(std::move(store), o));
    case AcceleratorKind::RecursiveGrid:
      return std::unique_ptr<Accelerator>(new RecursiveGrid(std::move(store), o));
    case AcceleratorKind::Octree:
      return std::unique_ptr<Accelerator>(new Octree(std::move(store), o));
  }
  throw Error("unknown accelerator kind");
}

AcceleratorKind AcceleratorKindFromName(const std::string& n)
{
  if (n == "brute" || n == "bruteforce")
  {
    return AcceleratorKind::BruteForce;
  }
  if (n == "uniform" || n == "grid")
  {
    return AcceleratorKind::UniformGrid;
  }
  if (n == "recursive" || n == "R")
  {
    return AcceleratorKind::RecursiveGrid;
  }
  if (n == "octree" || n == "O")
  {
    return AcceleratorKind::Octree;
  }
  throw Error("unknown accelerator '" + n + "' (brute, uniform, recursive, octree)");
}
} // namespace art
