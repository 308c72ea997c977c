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
  std::unique_ptr<Accelerator> acc;
  switch (o.kind)
  {
    case AcceleratorKind::BruteForce:
      acc.reset(new BruteForce(std::move(store)));
      break;
    case AcceleratorKind::UniformGrid:
      acc.reset(new UniformGrid(std::move(store), o));
      break;
    case AcceleratorKind::RecursiveGrid:
      acc.reset(new RecursiveGrid(std::move(store), o));
      break;
    case AcceleratorKind::Octree:
      acc.reset(new Octree(std::move(store), o));
      break;
    default:
      throw Error("unknown accelerator kind");
  }
  acc->SetTriangleTest(o.triangleTest);
  return acc;
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
