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
  Words.clear();
  Rank.clear();
  Entries.clear();
  Lists = CellLists(S->Size());
  Refs = 0;
  Grids = 0;
  for (int a = 0; a < 3; ++a)
  {
    TopLo[a] = Root.lo[a];
    TopN[a] = dims[a];
    SubN[a] = std::max(sub, 1);
    Cs[0][a] = (Root.hi[a] - Root.lo[a]) / dims[a];
    for (int d = 1; d < MaxLevels; ++d)
    {
      Cs[d][a] = Cs[d - 1][a] / SubN[a];
    }
    for (int d = 0; d < MaxLevels; ++d)
    {
      InvCs[d][a] = 1.0 / Cs[d][a];
    }
  }
  MaxDepthBuilt = 0;
  BuildGrid(0, TopLo, PlaneOrder(*S), 0);
  Lists.ShrinkToFit();
  Words.shrink_to_fit();
  Rank.shrink_to_fit();
  Entries.shrink_to_fit();
}

void RecursiveGrid::BuildGrid(int depth, const double lo[3], const std::vector<std::uint32_t>& ids, int stuck)
{
  const int* dims = Dims(depth);
  const double *cs = Cs[depth], *ics = InvCs[depth];
  const size_t ncell = static_cast<size_t>(dims[0]) * dims[1] * dims[2];
  ++Grids;
  // Bin: (cell, id) pairs, each triangle into every voxel its exact overlap test accepts.
  std::vector<std::uint32_t> count(ncell + 1, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  pairs.reserve(ids.size() * 2);
  Vec3 half;
  for (int a = 0; a < 3; ++a)
  {
    half[a] = 0.5 * cs[a] * (1.0 + 2 * Pad);
  }
  for (std::uint32_t id : ids)
  {
    const TriangleBox b = S->RecordBox(id);
    int from[3], to[3];
    for (int a = 0; a < 3; ++a)
    {
      const double slack = Pad * cs[a];
      from[a] = std::max(0, int(std::floor((double(b.lo[a]) - slack - lo[a]) * ics[a])));
      to[a] = std::min(dims[a] - 1, int(std::floor((double(b.hi[a]) + slack - lo[a]) * ics[a])));
    }
    const bool single = from[0] == to[0] && from[1] == to[1] && from[2] == to[2];
    const Vec3 v0 = S->Vertex(id, 0), v1 = S->Vertex(id, 1), v2 = S->Vertex(id, 2);
    for (int z = from[2]; z <= to[2]; ++z)
    {
      for (int y = from[1]; y <= to[1]; ++y)
      {
        for (int x = from[0]; x <= to[0]; ++x)
        {
          if (!single)
          {
            const Vec3 c(lo[0] + (x + 0.5) * cs[0], lo[1] + (y + 0.5) * cs[1], lo[2] + (z + 0.5) * cs[2]);
            if (!TriBoxOverlap(c, half, v0, v1, v2))
            {
              continue;
            }
          }
          const std::uint32_t cell = static_cast<std::uint32_t>((size_t(z) * dims[1] + y) * dims[0] + x);
          pairs.emplace_back(cell, id);
          ++count[cell];
        }
      }
    }
  }
  // Counting sort by cell; ids keep their plane order, so coplanar triangles stay neighbours.
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

  // This grid's occupancy words and entries, before any subgrid takes its own.
  const std::uint32_t block = static_cast<std::uint32_t>(Words.size());
  const size_t nwords = (ncell + 63) / 64;
  Words.resize(Words.size() + nwords, 0);
  Rank.resize(Rank.size() + nwords, 0);
  const std::uint32_t first = static_cast<std::uint32_t>(Entries.size());
  std::uint32_t entry = first;
  for (size_t c = 0; c < ncell; ++c)
  {
    if (c % 64 == 0)
    {
      Rank[block + c / 64] = entry;
    }
    if (count[c] > 0)
    {
      Words[block + c / 64] |= 1ull << (c % 64);
      ++entry;
    }
  }
  Entries.resize(entry, 0);
  entry = first;

  std::vector<std::uint32_t> sub;
  for (size_t c = 0; c < ncell; ++c)
  {
    const std::uint32_t n = count[c];
    if (n == 0)
    {
      continue;
    }
    const std::uint32_t at = entry++;
    // A voxel that kept every triangle of its parent is `stuck` once more: where more triangles meet
    // at a vertex than the threshold allows, splitting never separates them (N=2: 2 tries, else 1).
    const int cellStuck = depth != 0 && n == ids.size() ? stuck + 1 : 0;
    const bool split = Sub >= 2 && n > std::uint32_t(Thr) && depth < MaxDepth && Refs < IdBudget &&
      cellStuck <= (Sub == 2 ? 1 : 0);
    if (split)
    {
      // A subgrid of Sub^3 over this voxel; kept only if it separates something.
      const int idx[3] = { int(c % dims[0]), int((c / dims[0]) % dims[1]), int(c / (size_t(dims[0]) * dims[1])) };
      double clo[3];
      for (int a = 0; a < 3; ++a)
      {
        clo[a] = lo[a] + idx[a] * cs[a];
      }
      const double* ccs = Cs[depth + 1];
      // Does any triangle fail to reach every subvoxel? If all do, splitting only multiplies work.
      bool separates = false;
      for (std::uint32_t k = start[c]; k < start[c + 1] && !separates; ++k)
      {
        const TriangleBox b = S->RecordBox(sorted[k]);
        for (int a = 0; a < 3 && !separates; ++a)
        {
          separates = double(b.lo[a]) > clo[a] + ccs[a] || double(b.hi[a]) < clo[a] + (Sub - 1) * ccs[a];
        }
      }
      if (separates)
      {
        MaxDepthBuilt = std::max(MaxDepthBuilt, depth + 1);
        Entries[at] = static_cast<std::uint32_t>(Words.size()) | Child;
        sub.assign(sorted.begin() + start[c], sorted.begin() + start[c + 1]);
        BuildGrid(depth + 1, clo, sub, cellStuck);
        continue;
      }
    }
    Entries[at] = Lists.Append(sorted.data() + start[c], n);
    Refs += n;
  }
}

size_t RecursiveGrid::MemoryBytes() const
{
  return Words.size() * sizeof(std::uint64_t) + Rank.size() * sizeof(std::uint32_t) +
    Entries.size() * sizeof(std::uint32_t) + Lists.MemoryBytes();
}

void RecursiveGrid::VoxelBoxes(int level, std::vector<Box3>& boxes) const
{
  boxes.clear();
  if (!Words.empty())
  {
    CollectBoxes(0, 0, TopLo, level, boxes);
  }
}

void RecursiveGrid::CollectBoxes(
  std::uint32_t block, int depth, const double lo[3], int level, std::vector<Box3>& boxes) const
{
  const int* n = Dims(depth);
  const double* cs = Cs[depth];
  for (int z = 0; z < n[2]; ++z)
  {
    for (int y = 0; y < n[1]; ++y)
    {
      for (int x = 0; x < n[0]; ++x)
      {
        const std::uint32_t e = EntryOf(block, (std::uint64_t(z) * n[1] + y) * n[0] + x);
        if (e == Empty)
        {
          continue;
        }
        const double clo[3] = { lo[0] + x * cs[0], lo[1] + y * cs[1], lo[2] + z * cs[2] };
        if (e & Child && depth < level)
        {
          CollectBoxes(e & ~Child, depth + 1, clo, level, boxes);
        }
        else
        {
          boxes.emplace_back(Vec3(clo[0], clo[1], clo[2]), Vec3(clo[0] + cs[0], clo[1] + cs[1], clo[2] + cs[2]));
        }
      }
    }
  }
}

std::string RecursiveGrid::Name() const
{
  char buf[128];
  std::snprintf(buf, sizeof buf, "R[%d,%d]%s top %dx%dx%d depth %d", Thr, Sub, TopGrid ? "" : " no-top", TopN[0],
    TopN[1], TopN[2], MaxDepthBuilt);
  return buf;
}
} // namespace art
