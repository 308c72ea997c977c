// RecursiveGrid: the regular recursive grid R[VOX_NTRG_THR, N_SUB_VOXELS] (Dmitriev, "Efficiency
// issues on Ray Tracing Machine", section 3): a top-level uniform grid sized from the scene's
// uniformity; a voxel holding more than the threshold splits into N^3 subvoxels, to any depth.
// Traversal is Amanatides & Woo's 3D-DDA at every level; the per-axis steps depend only on the
// depth (all voxels of one depth are equal).
// Layout: a grid's cells are one bit each (occupied or not) in 64-bit words with the rank of
// each word's first occupied cell, so an empty cell costs a bit test in a word that stays in
// cache; an occupied cell has one 32-bit entry, a list offset (CellLists) or a subgrid.
#ifndef art_RecursiveGrid_h
#define art_RecursiveGrid_h

#include "AcceleratorQueries.h"
#include "CellLists.h"

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
  int TopDims(int a) const { return TopN[a]; }
  int Depth() const { return MaxDepthBuilt; }
  /// Grids: the top one and every subdivided voxel's.
  size_t NodeCount() const { return Grids; }
  double Uniformity() const { return Uniform; }
  /// The (padded) box the top-level grid spans.
  Box3 GridBounds() const { return Root; }

  static constexpr int MaxLevels = 16;

  template <class Visitor>
  void Walk(const RayPrep& p, double tmin, double tmax, Visitor& visit, Counters& c) const
  {
    double t0, t1;
    if (Words.empty() || !p.Clip(Root, tmin, tmax, t0, t1))
    {
      return;
    }
    Lists.With([&](const auto* lists) { WalkGrid<0>(lists, 0, 0, TopLo, t0, t1, p, visit, c); });
  }

  /// Nearest-point walk (see AcceleratorQueries.h): rings of growing radius around x's cell.
  template <class Visitor>
  void Near(const Vec3& x, const double& prune2, Visitor& visit, Counters& c) const
  {
    if (!Words.empty())
    {
      Lists.With([&](const auto* lists) { NearGrid(lists, 0, 0, TopLo, x, prune2, visit, c); });
    }
  }

  /// The leaves of every voxel that touches the closed box.
  template <class Visitor>
  void Overlap(const Box3& b, Visitor& visit) const
  {
    if (!Words.empty())
    {
      Lists.With([&](const auto* lists) { OverlapGrid(lists, 0, 0, TopLo, b, visit); });
    }
  }

protected:
  static constexpr std::uint32_t Child = 0x80000000u; ///< entry flag: the rest is a grid's first word
  static constexpr std::uint32_t Empty = 0xffffffffu;

  RecursiveGrid(std::shared_ptr<const TriangleStore> s) : WalkingAccelerator<RecursiveGrid>(std::move(s)) {}
  /// Builds with the given top-level dimensions; voxels over `thr` split into sub^3 (sub < 2: never).
  void Build(const int dims[3], int thr, int sub);
  static void ChooseDims(const Box3& box, double cells, int dims[3]);
  Box3 PaddedBounds() const;

  const int* Dims(int depth) const { return depth == 0 ? TopN : SubN; }

  static int PopCount(std::uint64_t x)
  {
    x = x - ((x >> 1) & 0x5555555555555555ull);
    x = (x & 0x3333333333333333ull) + ((x >> 2) & 0x3333333333333333ull);
    x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0full;
    return static_cast<int>((x * 0x0101010101010101ull) >> 56);
  }

  /// The entry of cell `idx` of the grid whose words start at `block`, or Empty.
  std::uint32_t EntryOf(std::uint32_t block, std::uint64_t idx) const
  {
    const std::uint64_t w = Words[block + (idx >> 6)], bit = 1ull << (idx & 63);
    return w & bit ? Entries[Rank[block + (idx >> 6)] + PopCount(w & (bit - 1))] : Empty;
  }

  /// floor(v) clamped to [0, n - 1] (NaN gives 0), without a call to floor.
  static int CellOf(double v, int n)
  {
    if (!(v >= 0.0))
    {
      return 0;
    }
    return v >= n ? n - 1 : static_cast<int>(v);
  }

  /// The 3D-DDA through one grid (the top one or a voxel's subgrid) from t0 to t1. Per axis the
  /// next crossing, its step in t and in the linear cell index, and how many cells are left
  /// before the grid's side are kept in registers; the axis of the nearest crossing is taken as
  /// tNext[0] < tNext[1] ? (tNext[0] < tNext[2] ? 0 : 2) : (tNext[1] < tNext[2] ? 1 : 2).
  /// Fixed > 0: a subgrid of Fixed^3 cells (the default N = 4), its sizes known to the compiler,
  /// and, being at most 64 cells, its occupancy one word loaded once.
  template <int Fixed, class Id, class Visitor>
  bool WalkGrid(const Id* lists, std::uint32_t block, int depth, const double lo[3], double t0, double t1,
    const RayPrep& p, Visitor& visit, Counters& c) const
  {
    constexpr bool OneWord = Fixed > 0 && Fixed * Fixed * Fixed <= 64;
    const int* dims = Dims(depth);
    const int n[3] = { Fixed > 0 ? Fixed : dims[0], Fixed > 0 ? Fixed : dims[1], Fixed > 0 ? Fixed : dims[2] };
    const double *cs = Cs[depth], *ics = InvCs[depth];
    int i[3], step[3], out[3];
    double tNext[3], tDelta[3];
    for (int a = 0; a < 3; ++a)
    {
      const double d = p.dir[a];
      const int k = CellOf((p.org[a] + d * t0 - lo[a]) * ics[a], n[a]);
      i[a] = k;
      // cs |inv| is |cs inv| exactly, and infinite where d = 0 (inv is then infinite).
      tDelta[a] = cs[a] * std::fabs(p.inv[a]);
      step[a] = d > 0 ? 1 : (d < 0 ? -1 : 0);
      out[a] = d > 0 ? n[a] : -1;
      const double side = (lo[a] + (k + (d > 0 ? 1 : 0)) * cs[a] - p.org[a]) * p.inv[a];
      tNext[a] = d != 0.0 ? side : std::numeric_limits<double>::infinity();
    }
    // The linear cell index moves by a per-axis stride; an empty cell costs a bit test.
    const long long stride[3] = { step[0], static_cast<long long>(step[1]) * n[0],
      static_cast<long long>(step[2]) * n[0] * n[1] };
    long long idx = (static_cast<long long>(i[2]) * n[1] + i[1]) * n[0] + i[0];
    const std::uint64_t* words = Words.data() + block;
    const std::uint32_t* rank = Rank.data() + block;
    const std::uint64_t word0 = OneWord ? words[0] : 0;
    double tEnter = t0;
    std::uint64_t visited = 0;
    bool stop = false;
    for (;;)
    {
      ++visited;
      // The axis of the nearest crossing, tNext[0] < tNext[1] ? (tNext[0] < tNext[2] ? 0 : 2) :
      // (tNext[1] < tNext[2] ? 1 : 2), as two compares and selects (a min and a move), no branch.
      const bool first = tNext[0] < tNext[1];
      const double near01 = first ? tNext[0] : tNext[1];
      const int a = near01 < tNext[2] ? (first ? 0 : 1) : 2;
      const double tExit = std::min(tNext[a], t1);
      const std::uint64_t w = OneWord ? word0 : words[idx >> 6], bit = 1ull << (idx & 63);
      if (w & bit)
      {
        const std::uint32_t e = Entries[(OneWord ? rank[0] : rank[idx >> 6]) + PopCount(w & (bit - 1))];
        if (e & Child)
        {
          const double clo[3] = { lo[0] + i[0] * cs[0], lo[1] + i[1] * cs[1], lo[2] + i[2] * cs[2] };
          if (Sub == 2 ? WalkOctants(lists, e & ~Child, depth + 1, clo, tEnter, tExit, p, visit, c)
                       : Sub == 4 ? WalkGrid<4>(lists, e & ~Child, depth + 1, clo, tEnter, tExit, p, visit, c)
                                  : WalkGrid<0>(lists, e & ~Child, depth + 1, clo, tEnter, tExit, p, visit, c))
          {
            stop = true;
            break;
          }
        }
        else
        {
          std::uint32_t count;
          const Id* ids = CellLists::Read(lists, e, count);
          if (visit(ids, count, tExit))
          {
            stop = true;
            break;
          }
        }
      }
      if (!(tNext[a] < t1))
      {
        break;
      }
      i[a] += step[a];
      if (i[a] == out[a])
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

  template <class Id, class Visitor>
  bool WalkOctants(const Id* lists, std::uint32_t block, int depth, const double lo[3], double t0, double t1,
    const RayPrep& p, Visitor& visit, Counters& c) const
  {
    const double* cs = Cs[depth];
    double tm[3];
    int bits = 0;
    for (int a = 0; a < 3; ++a)
    {
      const double mid = lo[a] + cs[a], d = p.dir[a];
      tm[a] = d != 0.0 ? (mid - p.org[a]) * p.inv[a] : std::numeric_limits<double>::infinity();
      // The cell holding the entry point, decided from the same mid-plane distances the walk uses.
      const bool high = d > 0 ? tm[a] <= t0 : (d < 0 ? !(tm[a] <= t0) : p.org[a] >= mid);
      bits |= high ? (1 << a) : 0;
    }
    const std::uint64_t w = Words[block];
    const std::uint32_t first = Rank[block];
    double tcur = t0;
    for (int k = 0; k < 4; ++k)
    {
      ++c.voxelsVisited;
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
      if ((w >> bits) & 1)
      {
        const double tExit = std::min(tcross, t1);
        const std::uint32_t e = Entries[first + PopCount(w & ((1ull << bits) - 1))];
        bool stop;
        if (e & Child)
        {
          const double clo[3] = { bits & 1 ? lo[0] + cs[0] : lo[0], bits & 2 ? lo[1] + cs[1] : lo[1],
            bits & 4 ? lo[2] + cs[2] : lo[2] };
          stop = WalkOctants(lists, e & ~Child, depth + 1, clo, tcur, tExit, p, visit, c);
        }
        else
        {
          std::uint32_t count;
          const Id* ids = CellLists::Read(lists, e, count);
          stop = visit(ids, count, tExit);
        }
        if (stop)
        {
          return true;
        }
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

  template <class Id, class Visitor>
  void NearGrid(const Id* lists, std::uint32_t block, int depth, const double lo[3], const Vec3& x,
    const double& prune2, Visitor& visit, Counters& c) const;
  template <class Id, class Visitor>
  void OverlapGrid(const Id* lists, std::uint32_t block, int depth, const double lo[3], const Box3& b, Visitor& visit) const;

  std::vector<std::uint64_t> Words; ///< occupancy, one bit per cell; a grid's words are contiguous
  std::vector<std::uint32_t> Rank;  ///< per word: the entry of its first occupied cell
  std::vector<std::uint32_t> Entries;
  CellLists Lists;
  double Cs[MaxLevels][3] = {}, InvCs[MaxLevels][3] = {}; ///< cell size per depth
  double TopLo[3] = { 0, 0, 0 };
  int TopN[3] = { 0, 0, 0 }, SubN[3] = { 0, 0, 0 };
  Box3 Root;
  int Thr = 0, Sub = 0, MaxDepthBuilt = 0;
  bool TopGrid = true;
  double Uniform = 1.0;
  size_t Grids = 0;

private:
  void BuildGrid(int depth, const double lo[3], const std::vector<std::uint32_t>& ids, int stuck);
  void CollectBoxes(std::uint32_t block, int depth, const double lo[3], int level, std::vector<Box3>& boxes) const;
  int MaxDepth = 0;
  size_t IdBudget = 0, Refs = 0;
};
} // namespace art

#include "RecursiveGridSearch.h"

#endif
