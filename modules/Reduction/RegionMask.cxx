#include "RegionMask.h"

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numeric>

namespace art
{
namespace
{
// Union-find over voxel indices with path halving.
struct Pieces
{
  std::vector<int64_t> Parent;
  int64_t Find(int64_t i)
  {
    while (Parent[i] != i)
    {
      Parent[i] = Parent[Parent[i]];
      i = Parent[i];
    }
    return i;
  }
  void Join(int64_t a, int64_t b)
  {
    a = Find(a), b = Find(b);
    if (a != b)
    {
      Parent[std::max(a, b)] = std::min(a, b);
    }
  }
};

// Joins every voxel with key[i] != 0 to its 26-neighbours of the same key (the 13 that come
// before it in index order); returns each voxel's root, -1 where key is 0.
template <class Key>
std::vector<int64_t> ConnectedPieces(const int d[3], const std::vector<Key>& key)
{
  const int64_t nx = d[0], ny = d[1], nz = d[2], n = nx * ny * nz;
  Pieces p;
  p.Parent.resize(static_cast<size_t>(n));
  std::iota(p.Parent.begin(), p.Parent.end(), int64_t(0));
  for (int64_t k = 0; k < nz; ++k)
    for (int64_t j = 0; j < ny; ++j)
      for (int64_t i = 0; i < nx; ++i)
      {
        const int64_t v = i + nx * (j + ny * k);
        if (!key[v])
        {
          continue;
        }
        // The 13 neighbours earlier in scan order: (dk, dj, di) lexicographically before 0.
        for (int dk = -1; dk <= 0; ++dk)
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di)
            {
              if (dk == 0 && (dj > 0 || (dj == 0 && di >= 0)))
              {
                continue;
              }
              const int64_t a = i + di, b = j + dj, c = k + dk;
              if (a < 0 || a >= nx || b < 0 || b >= ny || c < 0)
              {
                continue;
              }
              const int64_t u = a + nx * (b + ny * c);
              if (key[u] == key[v])
              {
                p.Join(u, v);
              }
            }
      }
  std::vector<int64_t> root(static_cast<size_t>(n), -1);
  for (int64_t v = 0; v < n; ++v)
  {
    root[v] = key[v] ? p.Find(v) : -1;
  }
  return root;
}

std::vector<long long> PieceSizes(const std::vector<int64_t>& root)
{
  std::vector<long long> size(root.size(), 0);
  for (int64_t r : root)
  {
    if (r >= 0)
    {
      ++size[static_cast<size_t>(r)];
    }
  }
  return size;
}

// A small piece of a label map takes the label most of its voxels' face neighbours outside it
// have (the background too); ties go to the smaller slot.
void AbsorbIsland(const int d[3], const std::vector<int64_t>& root, int64_t piece, const std::vector<int64_t>& members,
  std::vector<int32_t>& slot)
{
  const int64_t nx = d[0], ny = d[1], nz = d[2];
  std::map<int32_t, long long> votes;
  for (int64_t v : members)
  {
    const int64_t i = v % nx, j = (v / nx) % ny, k = v / (nx * ny);
    const int64_t nb[6][3] = { { i - 1, j, k }, { i + 1, j, k }, { i, j - 1, k }, { i, j + 1, k }, { i, j, k - 1 },
      { i, j, k + 1 } };
    for (const auto& q : nb)
    {
      if (q[0] < 0 || q[0] >= nx || q[1] < 0 || q[1] >= ny || q[2] < 0 || q[2] >= nz)
      {
        continue;
      }
      const int64_t u = q[0] + nx * (q[1] + ny * q[2]);
      if (root[u] != piece)
      {
        ++votes[slot[u]];
      }
    }
  }
  int32_t best = 0;
  long long most = -1;
  for (const auto& [s, c] : votes)
  {
    if (c > most)
    {
      best = s, most = c;
    }
  }
  for (int64_t v : members)
  {
    slot[v] = best;
  }
}
} // namespace

long long DefaultMinIslandVoxels(long long voxels)
{
  return std::max<long long>(27, static_cast<long long>(std::ceil(1e-4 * static_cast<double>(voxels))));
}

RegionMask MaskByRange(const VoxelVolume& volume, double lo, double hi, long long minIsland)
{
  if (!(lo <= hi))
  {
    char msg[160];
    std::snprintf(msg, sizeof msg, "the region %g:%g is empty (its low end is above its high end)", lo, hi);
    throw Error(msg, volume.File);
  }
  const long long n = volume.NumberOfVoxels();
  RegionMask m;
  m.Inside.assign(static_cast<size_t>(n), 0);
  long long inRange = 0;
  for (long long i = 0; i < n; ++i)
  {
    const double v = volume.Value(i);
    m.Inside[i] = v >= lo && v <= hi ? 1 : 0;
    inRange += m.Inside[i];
  }
  if (inRange == 0)
  {
    char msg[200];
    std::snprintf(msg, sizeof msg, "no voxel lies in the region %g:%g (the values span %g .. %g)", lo, hi,
      volume.Range[0], volume.Range[1]);
    throw Error(msg, volume.File);
  }
  m.MinIslandVoxels = minIsland >= 0 ? minIsland : DefaultMinIslandVoxels(inRange);
  const std::vector<int64_t> root = ConnectedPieces(volume.Dims, m.Inside);
  const std::vector<long long> size = PieceSizes(root);
  for (long long i = 0; i < n; ++i)
  {
    if (root[i] == i)
    {
      const bool keep = size[i] >= m.MinIslandVoxels;
      m.Pieces += keep ? 1 : 0;
      m.IslandsDropped += keep ? 0 : 1;
      m.IslandVoxels += keep ? 0 : size[i];
    }
  }
  for (long long i = 0; i < n; ++i)
  {
    if (m.Inside[i] && size[static_cast<size_t>(root[i])] < m.MinIslandVoxels)
    {
      m.Inside[i] = 0;
    }
    m.Voxels += m.Inside[i];
  }
  if (m.Voxels == 0)
  {
    throw Error("every piece of the region is an island below " + std::to_string(m.MinIslandVoxels) +
        " voxels (the largest has " + std::to_string(*std::max_element(size.begin(), size.end())) +
        "); give a smaller island threshold",
      volume.File);
  }
  return m;
}

RegionMask MaskByLabels(const VoxelVolume& volume, long long background, long long minIsland)
{
  const long long n = volume.NumberOfVoxels();
  std::vector<long long> labels;
  for (long long i = 0; i < n; ++i)
  {
    const double v = volume.Value(i);
    if (v != std::floor(v) || std::fabs(v) > 2147483647.0)
    {
      char msg[200];
      std::snprintf(msg, sizeof msg, "is not a label map: voxel %lld holds %g, not an integer (labels are integers)", i, v);
      throw Error(msg, volume.File);
    }
  }
  {
    std::map<long long, long long> count;
    for (long long i = 0; i < n; ++i)
    {
      ++count[static_cast<long long>(volume.Value(i))];
      if (count.size() > 65535)
      {
        throw Error("holds more than 65535 distinct labels: not a label map", volume.File);
      }
    }
    for (const auto& [l, c] : count)
    {
      if (l != background)
      {
        labels.push_back(l);
      }
    }
  }
  if (labels.empty())
  {
    throw Error("every voxel holds the background label " + std::to_string(background) + ": nothing to mesh",
      volume.File);
  }
  RegionMask m;
  m.Labels = labels;
  m.Slot.assign(static_cast<size_t>(n), 0);
  long long meshed = 0;
  for (long long i = 0; i < n; ++i)
  {
    const long long l = static_cast<long long>(volume.Value(i));
    if (l != background)
    {
      m.Slot[i] = 1 + static_cast<int32_t>(std::lower_bound(labels.begin(), labels.end(), l) - labels.begin());
      ++meshed;
    }
  }
  m.MinIslandVoxels = minIsland >= 0 ? minIsland : DefaultMinIslandVoxels(meshed);
  const std::vector<int64_t> root = ConnectedPieces(volume.Dims, m.Slot);
  const std::vector<long long> size = PieceSizes(root);
  std::map<int64_t, std::vector<int64_t>> small;
  for (long long i = 0; i < n; ++i)
  {
    if (root[i] >= 0 && size[static_cast<size_t>(root[i])] < m.MinIslandVoxels)
    {
      small[root[i]].push_back(i);
    }
    m.Pieces += root[i] == i ? 1 : 0;
  }
  for (const auto& [piece, members] : small)
  {
    AbsorbIsland(volume.Dims, root, piece, members, m.Slot);
    ++m.IslandsDropped;
    m.IslandVoxels += static_cast<long long>(members.size());
  }
  m.Pieces -= m.IslandsDropped;
  m.Inside.assign(static_cast<size_t>(n), 0);
  m.LabelVoxels.assign(labels.size(), 0);
  for (long long i = 0; i < n; ++i)
  {
    if (m.Slot[i] > 0)
    {
      m.Inside[i] = 1;
      ++m.Voxels;
      ++m.LabelVoxels[static_cast<size_t>(m.Slot[i] - 1)];
    }
  }
  if (m.Voxels == 0)
  {
    throw Error("every piece of every label is an island below " + std::to_string(m.MinIslandVoxels) +
        " voxels; give a smaller island threshold",
      volume.File);
  }
  return m;
}
} // namespace art
