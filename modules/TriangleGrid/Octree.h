// Octree O[VX_THRESHOLD, PLANE_WEIGHT] (Dmitriev, "Efficiency issues on Ray Tracing Machine",
// section 4): a voxel splits in two along each axis while its cost exceeds VX_THRESHOLD, where a
// triangle coplanar with one already counted costs 1/PLANE_WEIGHT (one ray/plane distance serves
// all of a plane's triangles, and no split separates them across the plane). The traversal is the
// N = 2 descent: the three mid-plane distances order the at most four children a ray crosses.
#ifndef art_Octree_h
#define art_Octree_h

#include "AcceleratorQueries.h"
#include "CellLists.h"

#include <cmath>

namespace art
{
class ADAPTIVERTTRIANGLEGRID_EXPORT Octree : public WalkingAccelerator<Octree>
{
public:
  Octree(std::shared_ptr<const TriangleStore> s, const AcceleratorOptions& o);

  size_t MemoryBytes() const override { return Nodes.size() * sizeof(ONode) + Lists.MemoryBytes(); }
  std::string Name() const override;
  void VoxelBoxes(int level, std::vector<Box3>& boxes) const override;
  int Depth() const { return DepthBuilt; }
  size_t NodeCount() const { return Nodes.size(); }

  template <class Visitor>
  void Walk(const RayPrep& p, double tmin, double tmax, Visitor& visit, Counters& c) const
  {
    double t0, t1;
    if (Nodes.empty() || !p.Clip(Root, tmin, tmax, t0, t1))
    {
      return;
    }
    const double lo[3] = { Root.lo.x, Root.lo.y, Root.lo.z }, hi[3] = { Root.hi.x, Root.hi.y, Root.hi.z };
    Lists.With([&](const auto* lists) { WalkNode(lists, 0, lo, hi, p, t0, t1, visit, c); });
  }

  /// Nearest-point walk (see AcceleratorQueries.h): depth first, the nearer children first.
  template <class Visitor>
  void Near(const Vec3& x, const double& prune2, Visitor& visit, Counters& c) const
  {
    const double lo[3] = { Root.lo.x, Root.lo.y, Root.lo.z }, hi[3] = { Root.hi.x, Root.hi.y, Root.hi.z };
    if (!Nodes.empty() && BoxDistance2(lo, hi, x) <= prune2)
    {
      Lists.With([&](const auto* lists) { NearNode(lists, 0, lo, hi, x, prune2, visit, c); });
    }
  }

  /// The leaves that touch the closed box.
  template <class Visitor>
  void Overlap(const Box3& b, Visitor& visit) const
  {
    const double lo[3] = { Root.lo.x, Root.lo.y, Root.lo.z }, hi[3] = { Root.hi.x, Root.hi.y, Root.hi.z };
    if (!Nodes.empty())
    {
      Lists.With([&](const auto* lists) { OverlapNode(lists, 0, lo, hi, b, visit); });
    }
  }

private:
  struct ONode
  {
    std::uint32_t first, count; ///< count == Internal: first is the first of 8 children; else a list offset
  };
  static constexpr std::uint32_t Internal = 0xffffffffu;

  static void ChildBox(const double lo[3], const double hi[3], int bits, double clo[3], double chi[3])
  {
    for (int a = 0; a < 3; ++a)
    {
      const double mid = 0.5 * (lo[a] + hi[a]);
      clo[a] = bits & (1 << a) ? mid : lo[a];
      chi[a] = bits & (1 << a) ? hi[a] : mid;
    }
  }

  template <class Id, class Visitor>
  void NearNode(const Id* lists, std::uint32_t n, const double lo[3], const double hi[3], const Vec3& x, const double& prune2,
    Visitor& visit, Counters& c) const
  {
    ++c.voxelsVisited;
    const ONode node = Nodes[n];
    if (node.count != Internal)
    {
      if (node.count != 0)
      {
        std::uint32_t count;
        const Id* ids = CellLists::Read(lists, node.first, count);
        visit(ids, count);
      }
      return;
    }
    // The eight children by distance (insertion sort), then visited while they can hold a nearer one.
    double d2[8];
    int order[8];
    for (int k = 0; k < 8; ++k)
    {
      double clo[3], chi[3];
      ChildBox(lo, hi, k, clo, chi);
      const double d = BoxDistance2(clo, chi, x);
      int m = k;
      for (; m > 0 && d2[m - 1] > d; --m)
      {
        d2[m] = d2[m - 1];
        order[m] = order[m - 1];
      }
      d2[m] = d;
      order[m] = k;
    }
    for (int m = 0; m < 8 && d2[m] <= prune2; ++m)
    {
      double clo[3], chi[3];
      ChildBox(lo, hi, order[m], clo, chi);
      NearNode(lists, node.first + order[m], clo, chi, x, prune2, visit, c);
    }
  }

  template <class Id, class Visitor>
  void OverlapNode(const Id* lists, std::uint32_t n, const double lo[3], const double hi[3], const Box3& b, Visitor& visit) const
  {
    for (int a = 0; a < 3; ++a)
    {
      const double pad = 1e-6 * (hi[a] - lo[a]); // a triangle in a voxel face is in both voxels
      if (b.hi[a] < lo[a] - pad || b.lo[a] > hi[a] + pad)
      {
        return;
      }
    }
    const ONode node = Nodes[n];
    if (node.count != Internal)
    {
      if (node.count != 0)
      {
        std::uint32_t count;
        const Id* ids = CellLists::Read(lists, node.first, count);
        visit(ids, count);
      }
      return;
    }
    for (int k = 0; k < 8; ++k)
    {
      double clo[3], chi[3];
      ChildBox(lo, hi, k, clo, chi);
      OverlapNode(lists, node.first + k, clo, chi, b, visit);
    }
  }

  template <class Id, class Visitor>
  bool WalkNode(const Id* lists, std::uint32_t n, const double lo[3], const double hi[3], const RayPrep& p, double t0,
    double t1, Visitor& visit, Counters& c) const
  {
    ++c.voxelsVisited;
    const ONode node = Nodes[n];
    if (node.count != Internal)
    {
      if (node.count == 0)
      {
        return false;
      }
      std::uint32_t count;
      const Id* ids = CellLists::Read(lists, node.first, count);
      return visit(ids, count, t1);
    }
    double mid[3], tm[3];
    int bits = 0;
    for (int a = 0; a < 3; ++a)
    {
      mid[a] = 0.5 * (lo[a] + hi[a]);
      const double d = p.dir[a];
      tm[a] = d != 0.0 ? (mid[a] - p.org[a]) * p.inv[a] : std::numeric_limits<double>::infinity();
      // The child holding the entry point, decided from the same mid-plane distances the walk uses.
      const bool high = d > 0 ? tm[a] <= t0 : (d < 0 ? !(tm[a] <= t0) : p.org[a] >= mid[a]);
      bits |= high ? (1 << a) : 0;
    }
    double tcur = t0;
    for (int k = 0; k < 4; ++k)
    {
      double tcross = std::numeric_limits<double>::infinity();
      int axis = -1;
      for (int a = 0; a < 3; ++a)
      {
        const bool high = bits & (1 << a);
        if (((p.dir[a] > 0 && !high) || (p.dir[a] < 0 && high)) && tm[a] < tcross)
        {
          tcross = tm[a];
          axis = a;
        }
      }
      const double tEx = std::min(tcross, t1);
      double clo[3], chi[3];
      for (int a = 0; a < 3; ++a)
      {
        const bool high = bits & (1 << a);
        clo[a] = high ? mid[a] : lo[a];
        chi[a] = high ? hi[a] : mid[a];
      }
      if (WalkNode(lists, node.first + bits, clo, chi, p, tcur, tEx, visit, c))
      {
        return true;
      }
      if (axis < 0 || !(tcross < t1))
      {
        return false;
      }
      bits ^= 1 << axis;
      tcur = std::max(tcur, tcross);
    }
    return false;
  }

  void BuildNode(std::uint32_t n, const double lo[3], const double hi[3], std::vector<std::uint32_t>& ids, int depth,
    int stuck);
  double Cost(const std::vector<std::uint32_t>& ids) const;
  void CollectBoxes(std::uint32_t n, const Vec3& lo, const Vec3& hi, int depth, int level, std::vector<Box3>& boxes) const;

  std::vector<ONode> Nodes;
  CellLists Lists;
  Box3 Root;
  int Thr = 0, Weight = 0, DepthBuilt = 0;
  size_t IdBudget = 0, Refs = 0;
};
} // namespace art

#endif
