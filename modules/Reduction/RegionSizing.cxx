#include "RegionSizing.h"

#include <algorithm>
#include <cmath>

namespace art
{
namespace
{
long long NodeIndex(const int n[3], int a, int b, int c)
{
  return a + static_cast<long long>(n[0]) * (b + static_cast<long long>(n[1]) * c);
}
} // namespace

RegionSizing::RegionSizing(
  const art::VoxelVolume& volume, const std::vector<uint8_t>& inside, double voxelsPerNode, double hmin, double hmax)
  : Hmin(hmin)
  , Hmax(std::max(hmin, hmax))
{
  const double s[3] = { std::fabs(volume.Spacing[0]), std::fabs(volume.Spacing[1]), std::fabs(volume.Spacing[2]) };
  Step = voxelsPerNode * std::min({ s[0], s[1], s[2] });
  VoxelSize = s[0] * s[1] * s[2];
  for (int a = 0; a < 3; ++a)
  {
    N[a] = 1 + static_cast<int>(std::ceil((volume.Dims[a] - 1) * s[a] / Step));
  }
  RegionVoxels.assign(static_cast<size_t>(N[0]) * N[1] * N[2], 0.f);
  const int* d = volume.Dims;
  for (int k = 0; k < d[2]; ++k)
    for (int j = 0; j < d[1]; ++j)
      for (int i = 0; i < d[0]; ++i)
      {
        if (inside[i + static_cast<size_t>(d[0]) * (j + static_cast<size_t>(d[1]) * k)])
        {
          const int a = static_cast<int>(std::lround(i * s[0] / Step)), b = static_cast<int>(std::lround(j * s[1] / Step)),
                    c = static_cast<int>(std::lround(k * s[2] / Step));
          RegionVoxels[NodeIndex(N, a, b, c)] += 1.f;
        }
      }
}

double RegionSizing::Density(const SizeGrid& g) const
{
  double sum = 0;
  for (int c = 0; c < N[2]; ++c)
    for (int b = 0; b < N[1]; ++b)
      for (int a = 0; a < N[0]; ++a)
      {
        const float w = RegionVoxels[NodeIndex(N, a, b, c)];
        if (w > 0)
        {
          const double p[3] = { a * Step, b * Step, c * Step };
          const double h = std::max(g.At(p), 1e-12);
          sum += w / (h * h * h);
        }
      }
  return sum * VoxelSize;
}

SizeGrid RegionSizing::Uniform(double tets) const
{
  double region = 0;
  for (float w : RegionVoxels)
  {
    region += w;
  }
  const double h = std::cbrt(K * region * VoxelSize / std::max(tets, 1.0));
  return SizeGrid::Constant(std::clamp(h, Hmin, Hmax));
}

void RegionSizing::Calibrate(const SizeGrid& size, long long tets)
{
  const double d = Density(size);
  if (d > 0 && tets > 0)
  {
    K = static_cast<double>(tets) / d;
  }
}

void RegionSizing::Grade(std::vector<float>& h) const
{
  // Two raster sweeps each way over the 26-neighbours: h(n) <= h(m) + Gradation |n - m|.
  const double g1 = Gradation * Step, g2 = g1 * std::sqrt(2.0), g3 = g1 * std::sqrt(3.0);
  auto sweep = [&](int dir) {
    const int a0 = dir > 0 ? 0 : N[0] - 1, b0 = dir > 0 ? 0 : N[1] - 1, c0 = dir > 0 ? 0 : N[2] - 1;
    for (int c = c0; c >= 0 && c < N[2]; c += dir)
      for (int b = b0; b >= 0 && b < N[1]; b += dir)
        for (int a = a0; a >= 0 && a < N[0]; a += dir)
        {
          float& v = h[NodeIndex(N, a, b, c)];
          for (int dc = -1; dc <= 1; ++dc)
            for (int db = -1; db <= 1; ++db)
              for (int da = -1; da <= 1; ++da)
              {
                const int x = a + da, y = b + db, z = c + dc;
                if ((da | db | dc) == 0 || x < 0 || y < 0 || z < 0 || x >= N[0] || y >= N[1] || z >= N[2])
                {
                  continue;
                }
                const int m = std::abs(da) + std::abs(db) + std::abs(dc);
                const double step = m == 1 ? g1 : (m == 2 ? g2 : g3);
                v = static_cast<float>(std::min<double>(v, h[NodeIndex(N, x, y, z)] + step));
              }
        }
  };
  for (int pass = 0; pass < 2; ++pass)
  {
    sweep(1);
    sweep(-1);
  }
}

SizeGrid RegionSizing::Scaled(const std::vector<double>& shape, double tets) const
{
  SizeGrid g;
  for (int a = 0; a < 3; ++a)
  {
    g.Dims[a] = N[a];
  }
  g.Step = Step;
  g.Values.resize(shape.size());
  // h = C shape, clamped and graded: C found by fixed-point steps on the expected count.
  double sum = 0;
  for (size_t n = 0; n < shape.size(); ++n)
  {
    sum += RegionVoxels[n] / (shape[n] * shape[n] * shape[n]);
  }
  double C = std::cbrt(K * sum * VoxelSize / std::max(tets, 1.0));
  for (int it = 0; it < 8; ++it)
  {
    for (size_t n = 0; n < shape.size(); ++n)
    {
      g.Values[n] = static_cast<float>(std::clamp(C * shape[n], Hmin, Hmax));
    }
    Grade(g.Values);
    const double expected = ExpectedTets(g);
    const double ratio = std::cbrt(expected / std::max(tets, 1.0));
    C *= ratio;
    if (std::fabs(ratio - 1.0) < 0.01)
    {
      break;
    }
  }
  for (size_t n = 0; n < shape.size(); ++n)
  {
    g.Values[n] = static_cast<float>(std::clamp(C * shape[n], Hmin, Hmax));
  }
  Grade(g.Values);
  return g;
}

SizeGrid RegionSizing::Adapted(double tets, const std::vector<double>& points, const std::vector<std::array<int, 4>>& tetIds,
  const std::vector<double>& tetRms, const std::vector<long long>& tetVoxels) const
{
  const size_t nodes = RegionVoxels.size();
  std::vector<double> sumH(nodes, 0.0), sumW(nodes, 0.0);
  const size_t nt = tetIds.size();
  for (size_t t = 0; t < nt; ++t)
  {
    if (tetVoxels[t] <= 0)
    {
      continue;
    }
    const double* p[4];
    for (int a = 0; a < 4; ++a)
    {
      p[a] = &points[3 * static_cast<size_t>(tetIds[t][a])];
    }
    double e[3][3];
    for (int a = 0; a < 3; ++a)
    {
      for (int c = 0; c < 3; ++c)
      {
        e[a][c] = p[a + 1][c] - p[0][c];
      }
    }
    const double six = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
      e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    const double h = std::cbrt(std::sqrt(2.0) * std::fabs(six)); // edge of the regular tet of that volume
    if (!(h > 0))
    {
      continue;
    }
    const double H = tetRms[t] / (h * h);
    const double w = static_cast<double>(tetVoxels[t]);
    // Every node inside the tet's box takes its estimate (the tets are a few nodes across).
    int lo[3], hi[3];
    for (int c = 0; c < 3; ++c)
    {
      double mn = p[0][c], mx = p[0][c];
      for (int a = 1; a < 4; ++a)
      {
        mn = std::min(mn, p[a][c]);
        mx = std::max(mx, p[a][c]);
      }
      lo[c] = std::clamp(static_cast<int>(std::ceil(mn / Step)), 0, N[c] - 1);
      hi[c] = std::clamp(static_cast<int>(std::floor(mx / Step)), 0, N[c] - 1);
      if (lo[c] > hi[c]) // no node inside along this axis: the nearest one
      {
        lo[c] = hi[c] = std::clamp(static_cast<int>(std::lround(0.5 * (mn + mx) / Step)), 0, N[c] - 1);
      }
    }
    for (int c = lo[2]; c <= hi[2]; ++c)
      for (int b = lo[1]; b <= hi[1]; ++b)
        for (int a = lo[0]; a <= hi[0]; ++a)
        {
          const long long n = NodeIndex(N, a, b, c);
          sumH[n] += w * H;
          sumW[n] += w;
        }
  }
  // Nodes no tet reached take their neighbours' mean, spreading outwards.
  std::vector<double> H(nodes, -1.0);
  double meanH = 0, meanW = 0;
  for (size_t n = 0; n < nodes; ++n)
  {
    if (sumW[n] > 0)
    {
      H[n] = sumH[n] / sumW[n];
      meanH += RegionVoxels[n] * H[n];
      meanW += RegionVoxels[n];
    }
  }
  meanH = meanW > 0 ? meanH / meanW : 1.0;
  for (int pass = 0; pass < 64; ++pass)
  {
    bool open = false;
    std::vector<double> next = H;
    for (int c = 0; c < N[2]; ++c)
      for (int b = 0; b < N[1]; ++b)
        for (int a = 0; a < N[0]; ++a)
        {
          const long long n = NodeIndex(N, a, b, c);
          if (H[n] >= 0)
          {
            continue;
          }
          double s = 0;
          int k = 0;
          const int nb[6][3] = { { a - 1, b, c }, { a + 1, b, c }, { a, b - 1, c }, { a, b + 1, c }, { a, b, c - 1 },
            { a, b, c + 1 } };
          for (const auto& q : nb)
          {
            if (q[0] >= 0 && q[1] >= 0 && q[2] >= 0 && q[0] < N[0] && q[1] < N[1] && q[2] < N[2] &&
              H[NodeIndex(N, q[0], q[1], q[2])] >= 0)
            {
              s += H[NodeIndex(N, q[0], q[1], q[2])];
              ++k;
            }
          }
          next[n] = k ? s / k : -1.0;
          open = open || k == 0;
        }
    H.swap(next);
    if (!open)
    {
      break;
    }
  }
  const double floorH = 1e-3 * meanH + 1e-300;
  std::vector<double> shape(nodes);
  for (size_t n = 0; n < nodes; ++n)
  {
    shape[n] = std::pow((H[n] >= 0 ? H[n] : meanH) + floorH, -2.0 / 7.0);
  }
  return Scaled(shape, tets);
}

SizeGrid RegionSizing::DistanceFor(const SizeGrid& size, double fraction, double floor)
{
  SizeGrid d = size;
  for (float& v : d.Values)
  {
    v = static_cast<float>(std::max(floor, fraction * v));
  }
  return d;
}
} // namespace art
