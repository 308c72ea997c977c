// RecursiveGrid: the regular recursive grid R[VOX_NTRG_THR, N_SUB_VOXELS] (Dmitriev, "Efficiency
// issues on Ray Tracing Machine", section 3): a top-level uniform grid sized from the scene's
// uniformity; a voxel holding more than the threshold splits into N^3 subvoxels, to any depth.
// Traversal is Amanatides & Woo's 3D-DDA at every level; the per-axis steps tDelta depend only on
// the depth (all voxels of one depth are equal), so they are computed once per ray and reused in
// every equally subdivided neighbour.
#ifndef art_RecursiveGrid_h
#define art_RecursiveGrid_h

#include "AcceleratorQueries.h"

#include <algorithm>
#include <cmath>

namespace art
{
class ADAPTIVERTTRIANGLEGRID_EXPORT RecursiveGrid : public WalkingAccelerator<RecursiveGrid>
{
public:
  RecursiveGrid(std::shared_ptr<const TriangleStore> s, const AcceleratorOptions& o);

  size_t MemoryBytes() const override;
  std::string Name() const override;
  void VoxelBoxes(int level, std::vector<Box3>& boxes) const override;

  int Threshold() const { return Thr; }
  int Subdivisions() const { return Sub; }
  int TopDims(int a) const { return Nodes.empty() ? 0 : Nodes[0].n[a]; }
  int Depth() const { return MaxDepthBuilt; }
  size_t NodeCount() const { return Nodes.size(); }
  double Uniformity() const { return Uniform; }
  /// The (padded) box the top-level grid spans.
  Box3 GridBounds() const { return Root; }

  static constexpr int MaxLevels = 16;

  template <class Visitor>
  void Walk(const RayPrep& p, double tmin, double tmax, Visitor& visit, Counters& c) const
  {
    if (Nodes.empty())
    {
      return;
    }
    const Ray r = p.Segment(tmin, tmax);
    double t0, t1;
    if (!Root.Clip(r, t0, t1))
    {
      return;
    }
    // The DDA steps of every depth, once per ray.
    double delta[MaxLevels][3];
    for (int d = 0; d <= MaxDepthBuilt; ++d)
    {
      for (int a = 0; a < 3; ++a)
      {
        delta[d][a] = p.dir[a] == 0.0 ? std::numeric_limits<double>::infinity()
                                      : std::fabs(LevelCell[d][a] * p.inv[a]);
      }
    }
    WalkNode(0, p, t0, t1, delta, visit, c);
  }

protected:
  struct Node
  {
    double lo[3], cs[3], invCs[3];
    int n[3];
    std::uint32_t firstCell;
    int depth;
  };
  struct Cell
  {
    std::uint32_t begin, count; ///< count == Child: begin is a node index
  };
  static constexpr std::uint32_t Child = 0xffffffffu;

  RecursiveGrid(std::shared_ptr<const TriangleStore> s) : WalkingAccelerator<RecursiveGrid>(std::move(s)) {}
  /// Builds with the given top-level dimensions; voxels over `thr` split into sub^3 (sub < 2: never).
  void Build(const int dims[3], int thr, int sub);
  static void ChooseDims(const Box3& box, double cells, int dims[3]);
  Box3 PaddedBounds() const;

  template <class Visitor>
  bool WalkNode(std::uint32_t g, const RayPrep& p, double t0, double t1, const double (*delta)[3],
    Visitor& visit, Counters& c) const
  {
    const Node& G = Nodes[g];
    int i[3], step[3];
    double tNext[3], tDelta[3];
    for (int a = 0; a < 3; ++a)
    {
      const double d = p.dir[a];
      const double x = p.org[a] + d * t0;
      int k = static_cast<int>(std::floor((x - G.lo[a]) * G.invCs[a]));
      k = std::min(std::max(k, 0), G.n[a] - 1);
      i[a] = k;
      tDelta[a] = delta[G.depth][a];
      if (d > 0)
      {
        step[a] = 1;
        tNext[a] = (G.lo[a] + (k + 1) * G.cs[a] - p.org[a]) * p.inv[a];
      }
      else if (d < 0)
      {
        step[a] = -1;
        tNext[a] = (G.lo[a] + k * G.cs[a] - p.org[a]) * p.inv[a];
      }
      else
      {
        step[a] = 0;
        tNext[a] = std::numeric_limits<double>::infinity();
      }
    }
    double tEnter = t0;
    const Cell* cells = Cells.data() + G.firstCell;
    // The linear cell index moves by a per-axis stride; empty cells cost one load and a compare.
    const long long stride[3] = { step[0], static_cast<long long>(step[1]) * G.n[0],
      static_cast<long long>(step[2]) * G.n[0] * G.n[1] };
    long long idx = (static_cast<long long>(i[2]) * G.n[1] + i[1]) * G.n[0] + i[0];
    std::uint64_t visited = 0;
    bool stop = false;
    for (;;)
    {
      ++visited;
      const Cell& cell = cells[idx];
      const int a = tNext[0] < tNext[1] ? (tNext[0] < tNext[2] ? 0 : 2) : (tNext[1] < tNext[2] ? 1 : 2);
      const double tExit = std::min(tNext[a], t1);
      if (cell.count == Child)
      {
        if (WalkNode(cell.begin, p, tEnter, tExit, delta, visit, c))
        {
          stop = true;
          break;
        }
      }
      else if (cell.count != 0 && visit(Ids.data() + cell.begin, cell.count, tExit))
      {
        stop = true;
        break;
      }
      if (!(tNext[a] < t1))
      {
        break;
      }
      i[a] += step[a];
      if (i[a] < 0 || i[a] >= G.n[a])
      {
        break;
      }
      idx += stride[a];
      tEnter = tNext[a];
      tNext[a] += tDelta[a];
    }
    c.voxelsVisited += visited;
    return stop;
  }

  std::vector<Node> Nodes;
  std::vector<Cell> Cells;
  std::vector<std::uint32_t> Ids;
  double LevelCell[MaxLevels][3] = {};
  Box3 Root;
  int Thr = 0, Sub = 0, MaxDepthBuilt = 0;
  bool TopGrid = true;
  double Uniform = 1.0;

private:
  void BuildNode(std::uint32_t node, const std::vector<std::uint32_t>& ids, int stuck);
  void CollectBoxes(std::uint32_t node, int level, std::vector<Box3>& boxes) const;
  int MaxDepth = 0;
  size_t IdBudget = 0;
};
} // namespace art

#endif
