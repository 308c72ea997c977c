#include "Octree.h"

#include "TriBoxOverlap.h"

#include <cstdio>

namespace art
{
namespace
{
constexpr int MaxDepth = 20;
constexpr double Pad = 1e-5; // insertion slack, as a fraction of a voxel
}

Octree::Octree(std::shared_ptr<const TriangleStore> s, const AcceleratorOptions& o)
  : WalkingAccelerator<Octree>(std::move(s))
{
  Thr = o.voxelThreshold > 0 ? o.voxelThreshold : 4;
  Weight = o.planeWeight > 0 ? o.planeWeight : 15;
  Root = S->Bounds();
  if (Root.Empty())
  {
    Root = Box3(Vec3(0, 0, 0), Vec3(1, 1, 1));
  }
  // A cube around the scene keeps voxels cubic, as in the paper.
  const Vec3 c = Root.Center(), e = Root.Size();
  const double h = 0.5 * std::max({ e.x, e.y, e.z }) * (1 + 1e-6) + 1e-300;
  Root = Box3(c - Vec3(h, h, h), c + Vec3(h, h, h));
  IdBudget = 64 * std::max<size_t>(S->Size(), 1024);
  std::vector<std::uint32_t> all = PlaneOrder(*S);
  Lists = CellLists(S->Size());
  Nodes.push_back(ONode{ 0, 0 });
  const double lo[3] = { Root.lo.x, Root.lo.y, Root.lo.z }, hi[3] = { Root.hi.x, Root.hi.y, Root.hi.z };
  BuildNode(0, lo, hi, all, 0, 0);
  Lists.ShrinkToFit();
}

double Octree::Cost(const std::vector<std::uint32_t>& ids) const
{
  // ids are in plane order (PlaneOrder), so coplanar triangles are adjacent.
  double cost = 0;
  std::uint32_t last = ~0u;
  for (std::uint32_t id : ids)
  {
    const std::uint32_t pl = S->Record(id).plane;
    cost += pl == last && pl != TriangleRecord::NoPlane ? 1.0 / Weight : 1.0;
    last = pl;
  }
  return cost;
}

void Octree::BuildNode(std::uint32_t n, const double lo[3], const double hi[3], std::vector<std::uint32_t>& ids, int depth,
  int stuck)
{
  // `stuck` counts the levels in a row that kept every triangle of the parent: around a vertex where
  // more triangles meet than the threshold allows, splitting further never helps (2 such levels end it).
  const bool split = depth < MaxDepth && stuck < 2 && Refs < IdBudget && Cost(ids) > Thr;
  double mid[3];
  for (int a = 0; a < 3; ++a)
  {
    mid[a] = 0.5 * (lo[a] + hi[a]);
  }
  std::vector<std::uint32_t> child[8];
  bool separates = false;
  if (split)
  {
    for (int k = 0; k < 8; ++k)
    {
      Vec3 c, h;
      for (int a = 0; a < 3; ++a)
      {
        const bool high = k & (1 << a);
        const double l = high ? mid[a] : lo[a], u = high ? hi[a] : mid[a];
        c[a] = 0.5 * (l + u);
        h[a] = 0.5 * (u - l) * (1 + 2 * Pad);
      }
      for (std::uint32_t id : ids)
      {
        if (TriBoxOverlap(c, h, S->Vertex(id, 0), S->Vertex(id, 1), S->Vertex(id, 2)))
        {
          child[k].push_back(id);
        }
      }
      separates = separates || child[k].size() < ids.size();
    }
  }
  if (!separates)
  {
    const std::uint32_t count = static_cast<std::uint32_t>(ids.size());
    Nodes[n] = ONode{ count ? Lists.Append(ids.data(), count) : 0, count };
    Refs += count;
    return;
  }
  const size_t parentCount = ids.size();
  ids.clear();
  ids.shrink_to_fit();
  const std::uint32_t first = static_cast<std::uint32_t>(Nodes.size());
  Nodes[n] = ONode{ first, Internal };
  Nodes.resize(Nodes.size() + 8, ONode{ 0, 0 });
  DepthBuilt = std::max(DepthBuilt, depth + 1);
  for (int k = 0; k < 8; ++k)
  {
    double clo[3], chi[3];
    for (int a = 0; a < 3; ++a)
    {
      const bool high = k & (1 << a);
      clo[a] = high ? mid[a] : lo[a];
      chi[a] = high ? hi[a] : mid[a];
    }
    BuildNode(first + k, clo, chi, child[k], depth + 1, child[k].size() == parentCount ? stuck + 1 : 0);
  }
}

void Octree::VoxelBoxes(int level, std::vector<Box3>& boxes) const
{
  boxes.clear();
  CollectBoxes(0, Root.lo, Root.hi, 0, level, boxes);
}

void Octree::CollectBoxes(std::uint32_t n, const Vec3& lo, const Vec3& hi, int depth, int level, std::vector<Box3>& boxes) const
{
  const ONode& node = Nodes[n];
  if (node.count == Internal && depth < level)
  {
    const Vec3 mid = (lo + hi) * 0.5;
    for (int k = 0; k < 8; ++k)
    {
      Vec3 clo, chi;
      for (int a = 0; a < 3; ++a)
      {
        const bool high = k & (1 << a);
        clo[a] = high ? mid[a] : lo[a];
        chi[a] = high ? hi[a] : mid[a];
      }
      CollectBoxes(node.first + k, clo, chi, depth + 1, level, boxes);
    }
  }
  else if (node.count != 0)
  {
    boxes.emplace_back(lo, hi);
  }
}

std::string Octree::Name() const
{
  char buf[96];
  std::snprintf(buf, sizeof buf, "O[%d,%d] depth %d", Thr, Weight, DepthBuilt);
  return buf;
}
} // namespace art
