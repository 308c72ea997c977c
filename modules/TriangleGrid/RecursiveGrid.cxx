#include "RecursiveGrid.h"

#include "TriBoxOverlap.h"

#include <cstdio>

namespace art
{
namespace
{
constexpr double Pad = 1e-5; // insertion slack, as a fraction of a voxel: covers DDA rounding
}

Box3 RecursiveGrid::PaddedBounds() const
{
  Box3 b = S->Bounds();
  if (b.Empty())
  {
    return Box3(Vec3(0, 0, 0), Vec3(1, 1, 1));
  }
  const double diag = b.Diagonal();
  const double pad = diag > 0 ? 1e-6 * diag : 1e-6 * std::max(1.0, std::fabs(b.lo.x));
  b.lo -= Vec3(pad, pad, pad);
  b.hi += Vec3(pad, pad, pad);
  return b;
}

void RecursiveGrid::ChooseDims(const Box3& box, double cells, int dims[3])
{
  const Vec3 e = box.Size();
  const double emax = std::max({ e.x, e.y, e.z });
  double prod = 1;
  int m = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (e[a] > 1e-3 * emax)
    {
      prod *= e[a];
      ++m;
    }
  }
  cells = std::min(std::max(cells, 1.0), double(1 << 24));
  const double k = m > 0 ? std::pow(cells / prod, 1.0 / m) : 1.0;
  for (int a = 0; a < 3; ++a)
  {
    dims[a] = e[a] > 1e-3 * emax ? static_cast<int>(std::min(1024.0, std::max(1.0, std::round(e[a] * k)))) : 1;
  }
}

RecursiveGrid::RecursiveGrid(std::shared_ptr<const TriangleStore> s, const AcceleratorOptions& o)
  : WalkingAccelerator<RecursiveGrid>(std::move(s))
{
  const int thr = o.voxelThreshold > 0 ? o.voxelThreshold : 12;
  const int sub = o.subdivisions > 0 ? o.subdivisions : 4;
  TopGrid = o.topLevelGrid;
  int dims[3] = { 1, 1, 1 };
  const size_t n = S->Size();
  if (TopGrid && n > 0)
  {
    // Uniformity of the scene: how evenly triangles spread over the occupied cells of a coarse
    // histogram (1 = perfectly even). An even scene gets the uniform grid's resolution at the top,
    // an uneven one a coarser top grid and lets the subdivision adapt.
    const Box3 box = PaddedBounds();
    int h[3];
    ChooseDims(box, std::min<double>(4096.0, double(n)), h);
    std::vector<double> hist(static_cast<size_t>(h[0]) * h[1] * h[2], 0.0);
    for (size_t t = 0; t < n; ++t)
    {
      const TriangleBox b = S->RecordBox(t);
      int idx[3];
      for (int a = 0; a < 3; ++a)
      {
        const double cen = 0.5 * (double(b.lo[a]) + double(b.hi[a]));
        idx[a] = std::min(h[a] - 1, std::max(0, int((cen - box.lo[a]) / (box.hi[a] - box.lo[a]) * h[a])));
      }
      hist[(size_t(idx[2]) * h[1] + idx[1]) * h[0] + idx[0]] += 1.0;
    }
    double s1 = 0, s2 = 0;
    size_t occ = 0;
    for (double v : hist)
    {
      s1 += v;
      s2 += v * v;
      occ += v > 0;
    }
    Uniform = occ > 0 && s2 > 0 ? s1 * s1 / (double(occ) * s2) : 1.0;
    ChooseDims(box, Uniform * 2.0 * double(n) / std::sqrt(double(thr)), dims);
  }
  Build(dims, thr, sub);
}

void RecursiveGrid::Build(const int dims[3], int thr, int sub)
{
  Thr = thr;
  Sub = sub;
  MaxDepth = sub >= 2 ? std::min(MaxLevels - 1, int(std::floor(std::log(4096.0) / std::log(double(sub)) + 1e-9))) : 0;
  Root = PaddedBounds();
  IdBudget = 64 * std::max<size_t>(S->Size(), 1024);
  Nodes.clear();
  Cells.clear();
  Ids.clear();
  Node top;
  for (int a = 0; a < 3; ++a)
  {
    top.lo[a] = Root.lo[a];
    top.n[a] = dims[a];
    top.cs[a] = (Root.hi[a] - Root.lo[a]) / dims[a];
    top.invCs[a] = 1.0 / top.cs[a];
  }
  top.depth = 0;
  top.firstCell = 0;
  Nodes.push_back(top);
  Cells.resize(static_cast<size_t>(dims[0]) * dims[1] * dims[2], Cell{ 0, 0 });
  MaxDepthBuilt = 0;
  for (int d = 0; d < MaxLevels; ++d)
  {
    for (int a = 0; a < 3; ++a)
    {
      LevelCell[d][a] = top.cs[a] / std::pow(double(std::max(sub, 1)), d);
    }
  }
  BuildNode(0, PlaneOrder(*S), 0);
  Ids.shrink_to_fit();
}

void RecursiveGrid::BuildNode(std::uint32_t node, const std::vector<std::uint32_t>& ids, int stuck)
{
  const Node G = Nodes[node]; // copy: Nodes grows below
  const size_t ncell = static_cast<size_t>(G.n[0]) * G.n[1] * G.n[2];
  // Bin: (cell, id) pairs, each triangle into every voxel its exact overlap test accepts.
  std::vector<std::uint32_t> count(ncell + 1, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(ids.size() * 2);
  Vec3 half;
  for (int a = 0; a < 3; ++a)
  {
    half[a] = 0.5 * G.cs[a] * (1.0 + 2 * Pad);
  }
  for (std::uint32_t id : ids)
  {
    const TriangleBox b = S->RecordBox(id);
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a)
    {
      const double slack = Pad * G.cs[a];
      lo[a] = std::max(0, int(std::floor((double(b.lo[a]) - slack - G.lo[a]) * G.invCs[a])));
      hi[a] = std::min(G.n[a] - 1, int(std::floor((double(b.hi[a]) + slack - G.lo[a]) * G.invCs[a])));
    }
    const bool single = lo[0] == hi[0] && lo[1] == hi[1] && lo[2] == hi[2];
    const Vec3 v0 = S->Vertex(id, 0), v1 = S->Vertex(id, 1), v2 = S->Vertex(id, 2);
    for (int z = lo[2]; z <= hi[2]; ++z)
    {
      for (int y = lo[1]; y <= hi[1]; ++y)
      {
        for (int x = lo[0]; x <= hi[0]; ++x)
        {
          if (!single)
          {
            const Vec3 c(G.lo[0] + (x + 0.5) * G.cs[0], G.lo[1] + (y + 0.5) * G.cs[1], G.lo[2] + (z + 0.5) * G.cs[2]);
            if (!TriBoxOverlap(c, half, v0, v1, v2))
            {
              continue;
            }
          }
          const std::uint32_t cell = static_cast<std::uint32_t>((size_t(z) * G.n[1] + y) * G.n[0] + x);
          pairs.emplace_back(cell, id);
          ++count[cell];
        }
      }
    }
  }
  // Counting sort by cell; ids stay in store order, so coplanar triangles stay neighbours.
  std::vector<std::uint32_t> start(ncell + 1, 0);
  for (size_t c = 0; c < ncell; ++c)
  {
    start[c + 1] = start[c] + count[c];
  }
  std::vector<std::uint32_t> sorted(pairs.size());
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (const auto& pr : pairs)
    {
      sorted[fill[pr.first]++] = pr.second;
    }
  }
  pairs.clear();
  pairs.shrink_to_fit();

  std::vector<std::uint32_t> sub;
  for (size_t c = 0; c < ncell; ++c)
  {
    const std::uint32_t n = count[c];
    Cell cell{ 0, 0 };
    // A voxel that kept every triangle of its parent is `stuck` once more: where more triangles meet
    // at a vertex than the threshold allows, splitting never separates them (N=2: 2 tries, else 1).
    const int cellStuck = node != 0 && n == ids.size() ? stuck + 1 : 0;
    const bool split = Sub >= 2 && n > std::uint32_t(Thr) && G.depth < MaxDepth && Ids.size() < IdBudget &&
      cellStuck <= (Sub == 2 ? 1 : 0);
    if (split)
    {
      // A child grid of Sub^3 over this voxel; kept only if it separates something.
      Node ch;
      const int x = int(c % G.n[0]), y = int((c / G.n[0]) % G.n[1]), z = int(c / (size_t(G.n[0]) * G.n[1]));
      const int idx[3] = { x, y, z };
      for (int a = 0; a < 3; ++a)
      {
        ch.lo[a] = G.lo[a] + idx[a] * G.cs[a];
        ch.n[a] = Sub;
        ch.cs[a] = G.cs[a] / Sub;
        ch.invCs[a] = 1.0 / ch.cs[a];
      }
      ch.depth = G.depth + 1;
      // Does any triangle fail to reach every subvoxel? If all do, splitting only multiplies work.
      bool separates = false;
      for (std::uint32_t k = start[c]; k < start[c + 1] && !separates; ++k)
      {
        const TriangleBox b = S->RecordBox(sorted[k]);
        for (int a = 0; a < 3 && !separates; ++a)
        {
          separates = double(b.lo[a]) > ch.lo[a] + ch.cs[a] || double(b.hi[a]) < ch.lo[a] + (Sub - 1) * ch.cs[a];
        }
      }
      if (separates)
      {
        ch.firstCell = static_cast<std::uint32_t>(Cells.size());
        const std::uint32_t childIndex = static_cast<std::uint32_t>(Nodes.size());
        Nodes.push_back(ch);
        Cells.resize(Cells.size() + size_t(Sub) * Sub * Sub, Cell{ 0, 0 });
        MaxDepthBuilt = std::max(MaxDepthBuilt, ch.depth);
        sub.assign(sorted.begin() + start[c], sorted.begin() + start[c + 1]);
        BuildNode(childIndex, sub, cellStuck);
        cell = Cell{ childIndex, Child };
        Cells[G.firstCell + c] = cell;
        continue;
      }
    }
    if (n > 0)
    {
      cell.begin = static_cast<std::uint32_t>(Ids.size());
      cell.count = n;
      Ids.insert(Ids.end(), sorted.begin() + start[c], sorted.begin() + start[c + 1]);
    }
    Cells[G.firstCell + c] = cell;
  }
}

size_t RecursiveGrid::MemoryBytes() const
{
  return Nodes.size() * sizeof(Node) + Cells.size() * sizeof(Cell) + Ids.size() * sizeof(std::uint32_t);
}

void RecursiveGrid::VoxelBoxes(int level, std::vector<Box3>& boxes) const
{
  boxes.clear();
  if (!Nodes.empty())
  {
    CollectBoxes(0, level, boxes);
  }
}

void RecursiveGrid::CollectBoxes(std::uint32_t node, int level, std::vector<Box3>& boxes) const
{
  const Node& G = Nodes[node];
  for (int z = 0; z < G.n[2]; ++z)
  {
    for (int y = 0; y < G.n[1]; ++y)
    {
      for (int x = 0; x < G.n[0]; ++x)
      {
        const Cell& c = Cells[G.firstCell + (size_t(z) * G.n[1] + y) * G.n[0] + x];
        if (c.count == Child && G.depth < level)
        {
          CollectBoxes(c.begin, level, boxes);
        }
        else if (c.count != 0)
        {
          const Vec3 lo(G.lo[0] + x * G.cs[0], G.lo[1] + y * G.cs[1], G.lo[2] + z * G.cs[2]);
          boxes.emplace_back(lo, lo + Vec3(G.cs[0], G.cs[1], G.cs[2]));
        }
      }
    }
  }
}

std::string RecursiveGrid::Name() const
{
  char buf[128];
  std::snprintf(buf, sizeof buf, "R[%d,%d]%s top %dx%dx%d depth %d", Thr, Sub, TopGrid ? "" : " no-top",
    Nodes.empty() ? 0 : Nodes[0].n[0], Nodes.empty() ? 0 : Nodes[0].n[1], Nodes.empty() ? 0 : Nodes[0].n[2],
    MaxDepthBuilt);
  return buf;
}
} // namespace art
