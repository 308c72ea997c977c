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

  /// Nearest-point walk (see AcceleratorQueries.h): rings of growing radius around x's cell.
  template <class Visitor>
  void Near(const Vec3& x, const double& prune2, Visitor& visit, Counters& c) const
  {
    if (!Nodes.empty())
    {
      NearNode(0, x, prune2, visit, c);
    }
  }

  /// The leaves of every voxel that touches the closed box.
  template <class Visitor>
  void Overlap(const Box3& b, Visitor& visit) const
  {
    if (!Nodes.empty())
    {
      OverlapNode(0, b, visit);
    }
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

  /// floor(v) clamped to [0, n - 1] (NaN gives 0), without a call to floor.
  static int CellOf(double v, int n)
  {
    if (!(v >= 0.0))
    {
      return 0;
    }
    return v >= n ? n - 1 : static_cast<int>(v);
  }

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
      const int k = CellOf((x - G.lo[a]) * G.invCs[a], G.n[a]);
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

  // Searches the grid node g ring by ring (Chebyshev rings of cells around the cell nearest x): a
  // ring can hold nothing nearer than the nearest of its faces' slabs, so the rings stop once that
  // bound passes the best distance so far; within a ring, cells beyond it are skipped too.
  template <class Visitor>
  void NearNode(std::uint32_t g, const Vec3& x, const double& prune2, Visitor& visit, Counters& c) const
  {
    const Node& G = Nodes[g];
    const Cell* cells = Cells.data() + G.firstCell;
    int ci[3], maxR = 0;
    double out2[3];
    for (int a = 0; a < 3; ++a)
    {
      const double hi = G.lo[a] + G.n[a] * G.cs[a];
      const double o = x[a] < G.lo[a] ? G.lo[a] - x[a] : (x[a] > hi ? x[a] - hi : 0.0);
      out2[a] = o * o;
      const double f = std::floor((x[a] - G.lo[a]) * G.invCs[a]);
      ci[a] = f < 0 ? 0 : (f >= G.n[a] ? G.n[a] - 1 : static_cast<int>(f));
      maxR = std::max(maxR, std::max(ci[a], G.n[a] - 1 - ci[a]));
    }
    auto cell = [&](int i, int j, int k) {
      const double lo[3] = { G.lo[0] + i * G.cs[0], G.lo[1] + j * G.cs[1], G.lo[2] + k * G.cs[2] };
      const double hi[3] = { lo[0] + G.cs[0], lo[1] + G.cs[1], lo[2] + G.cs[2] };
      if (BoxDistance2(lo, hi, x) > prune2)
      {
        return;
      }
      ++c.voxelsVisited;
      const Cell& cl = cells[(static_cast<long long>(k) * G.n[1] + j) * G.n[0] + i];
      if (cl.count == Child)
      {
        NearNode(cl.begin, x, prune2, visit, c);
      }
      else if (cl.count != 0)
      {
        visit(Ids.data() + cl.begin, cl.count);
      }
    };
    cell(ci[0], ci[1], ci[2]);
    for (int r = 1; r <= maxR; ++r)
    {
      double face2[3][2], gap2[3][2];
      double ring2 = std::numeric_limits<double>::infinity();
      for (int a = 0; a < 3; ++a)
      {
        for (int s = 0; s < 2; ++s)
        {
          const int idx = ci[a] + (s ? r : -r);
          face2[a][s] = std::numeric_limits<double>::infinity();
          if (idx < 0 || idx >= G.n[a])
          {
            continue;
          }
          const double gap = std::max(0.0, s ? G.lo[a] + idx * G.cs[a] - x[a] : x[a] - (G.lo[a] + (idx + 1) * G.cs[a]));
          gap2[a][s] = gap * gap;
          face2[a][s] = gap2[a][s] + out2[(a + 1) % 3] + out2[(a + 2) % 3];
          ring2 = std::min(ring2, face2[a][s]);
        }
      }
      if (ring2 > prune2)
      {
        break; // every further ring lies further still
      }
      // Face (a, s) of the ring: axis a at ci[a] -+ r, axes before a strictly inside the ring,
      // axes after it across the whole ring, so each cell of the ring is visited once.
      for (int a = 0; a < 3; ++a)
      {
        for (int s = 0; s < 2; ++s)
        {
          const int idx = ci[a] + (s ? r : -r);
          if (idx < 0 || idx >= G.n[a] || face2[a][s] > prune2)
          {
            continue;
          }
          int lo[3], hi[3];
          for (int b = 0; b < 3; ++b)
          {
            if (b == a)
            {
              lo[b] = hi[b] = idx;
              continue;
            }
            const int in = b < a ? 1 : 0;
            lo[b] = std::max(ci[b] - r + in, 0);
            hi[b] = std::min(ci[b] + r - in, G.n[b] - 1);
            // Along b a cell can hold something nearer only within this reach of x: the face's own
            // distance along a and x's distance outside the grid along the third axis are spent.
            const double reach = std::sqrt(std::max(0.0, prune2 - gap2[a][s] - out2[3 - a - b]));
            if (reach < std::numeric_limits<double>::infinity())
            {
              const double l = std::floor((x[b] - reach - G.lo[b]) * G.invCs[b]);
              const double h = std::floor((x[b] + reach - G.lo[b]) * G.invCs[b]);
              lo[b] = l > lo[b] ? static_cast<int>(std::min(l, double(G.n[b]))) : lo[b];
              hi[b] = h < hi[b] ? static_cast<int>(std::max(h, -1.0)) : hi[b];
            }
          }
          for (int k = lo[2]; k <= hi[2]; ++k)
          {
            for (int j = lo[1]; j <= hi[1]; ++j)
            {
              for (int i = lo[0]; i <= hi[0]; ++i)
              {
                cell(i, j, k);
              }
            }
          }
        }
      }
    }
  }

  template <class Visitor>
  void OverlapNode(std::uint32_t g, const Box3& b, Visitor& visit) const
  {
    const Node& G = Nodes[g];
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a)
    {
      // A little wider than the box: a triangle in a voxel face was put in both voxels, and the
      // exact test follows anyway.
      const double l = std::floor((b.lo[a] - G.lo[a]) * G.invCs[a] - 1e-6);
      const double h = std::floor((b.hi[a] - G.lo[a]) * G.invCs[a] + 1e-6);
      if (h < 0 || l >= G.n[a])
      {
        return;
      }
      lo[a] = l < 0 ? 0 : static_cast<int>(l);
      hi[a] = h >= G.n[a] ? G.n[a] - 1 : static_cast<int>(h);
    }
    const Cell* cells = Cells.data() + G.firstCell;
    for (int k = lo[2]; k <= hi[2]; ++k)
    {
      for (int j = lo[1]; j <= hi[1]; ++j)
      {
        for (int i = lo[0]; i <= hi[0]; ++i)
        {
          const Cell& cl = cells[(static_cast<long long>(k) * G.n[1] + j) * G.n[0] + i];
          if (cl.count == Child)
          {
            OverlapNode(cl.begin, b, visit);
          }
          else if (cl.count != 0)
          {
            visit(Ids.data() + cl.begin, cl.count);
          }
        }
      }
    }
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
