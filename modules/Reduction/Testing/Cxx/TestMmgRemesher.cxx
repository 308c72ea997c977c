// MmgRemesher: MMG3D through libmmg3d keeps the box as the boundary, makes edges of the metric's
// length along each axis, is deterministic, and gives the caller's signal handlers back.
#include "MeshQuality.h"
#include "MmgRemesher.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <vector>

namespace
{
// A Kuhn grid of n^3 boxes over [0, size]^3 with the metric diag(1/hx^2, 1/hy^2, 1/hz^2).
art::MetricMesh Box(int n, double size, double hx, double hy, double hz)
{
  art::MetricMesh m;
  auto id = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
      {
        m.Points.insert(m.Points.end(), { size * i / n, size * j / n, size * k / n });
        m.Metric.insert(m.Metric.end(), { 1 / (hx * hx), 0, 0, 1 / (hy * hy), 0, 1 / (hz * hz) });
      }
  static const int perms[6][3] = { { 0, 1, 2 }, { 0, 2, 1 }, { 1, 0, 2 }, { 1, 2, 0 }, { 2, 0, 1 }, { 2, 1, 0 } };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        for (const auto& p : perms)
        {
          int c[3] = { i, j, k };
          m.Tets.push_back(id(c[0], c[1], c[2]));
          for (int s = 0; s < 3; ++s)
          {
            ++c[p[s]];
            m.Tets.push_back(id(c[0], c[1], c[2]));
          }
        }
  return m;
}

double Volume(const std::vector<double>& p, const std::vector<int>& t)
{
  double v = 0;
  for (size_t i = 0; i < t.size(); i += 4)
  {
    const double* a = &p[3 * t[i]];
    double e[3][3];
    for (int r = 0; r < 3; ++r)
    {
      for (int d = 0; d < 3; ++d)
      {
        e[r][d] = p[3 * t[i + r + 1] + d] - a[d];
      }
    }
    v += std::fabs(e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0])) / 6;
  }
  return v;
}

// The mean edge length along each axis over the mesh's distinct edges.
void MeanAxisExtent(const std::vector<double>& p, const std::vector<int>& t, double out[3])
{
  double s[3] = { 0, 0, 0 };
  long long n = 0;
  for (size_t i = 0; i < t.size(); i += 4)
  {
    for (int a = 0; a < 4; ++a)
    {
      for (int b = a + 1; b < 4; ++b)
      {
        for (int d = 0; d < 3; ++d)
        {
          s[d] += std::fabs(p[3 * t[i + a] + d] - p[3 * t[i + b] + d]);
        }
        ++n;
      }
    }
  }
  for (int d = 0; d < 3; ++d)
  {
    out[d] = s[d] / n;
  }
}

bool Available()
{
  std::string why;
  const bool ok = art::MmgRemesher::Available(&why);
  if (!ok)
  {
    ADD_FAILURE() << "MMG is not available: " << why;
  }
  return ok;
}

const double Lo[3] = { 0, 0, 0 }, Hi[3] = { 12, 12, 12 };

void Handler(int) {}
} // namespace

TEST(MmgRemesher, KeepsTheBoxAsTheBoundary)
{
  ASSERT_TRUE(Available());
  std::vector<double> p;
  std::vector<int> t;
  art::RemeshOptions o;
  o.Hmin = 0.1;
  art::MmgRemesher::Remesh(Box(4, 12, 2, 2, 2), Lo, Hi, o, p, t);
  ASSERT_GT(t.size(), 0u);
  EXPECT_NEAR(Volume(p, t), 12.0 * 12 * 12, 1e-9);
  const auto q = art::MeasureQuality(p.data(), static_cast<long long>(p.size() / 3), t.data(),
    static_cast<long long>(t.size() / 4));
  EXPECT_TRUE(q.Valid()) << q.Summary();
  // An isotropic metric of h = 2: edges about 2 long (MMG aims at 0.7 h .. 1.4 h).
  double e[3];
  MeanAxisExtent(p, t, e);
  for (int d = 0; d < 3; ++d)
  {
    EXPECT_GT(e[d], 0.5) << d;
    EXPECT_LT(e[d], 2.0) << d;
  }
}

TEST(MmgRemesher, MakesEdgesOfTheMetricsLengthAlongEachAxis)
{
  ASSERT_TRUE(Available());
  std::vector<double> p;
  std::vector<int> t;
  art::RemeshOptions o;
  o.Hmin = 0.1;
  // Four times shorter along z than along x and y.
  art::MmgRemesher::Remesh(Box(4, 12, 4, 4, 1), Lo, Hi, o, p, t);
  EXPECT_NEAR(Volume(p, t), 12.0 * 12 * 12, 1e-9);
  double e[3];
  MeanAxisExtent(p, t, e);
  EXPECT_GT(e[0] / e[2], 2.5);
  EXPECT_GT(e[1] / e[2], 2.5);
  // A unit mesh of this metric has about 12^3 / (4 4 1) / (sqrt(2) / 12) = 917 tets: the count
  // stays within a small factor of it, the box faces included.
  const double tets = t.size() / 4.0;
  EXPECT_GT(tets, 917 / 3.0);
  EXPECT_LT(tets, 917 * 3.0);
}

TEST(MmgRemesher, GivesTheSameMeshForTheSameInput)
{
  ASSERT_TRUE(Available());
  std::vector<double> p1, p2;
  std::vector<int> t1, t2;
  art::RemeshOptions o;
  o.Hmin = 0.1;
  const art::MetricMesh in = Box(5, 12, 3, 1.5, 1);
  art::MmgRemesher::Remesh(in, Lo, Hi, o, p1, t1);
  art::MmgRemesher::Remesh(in, Lo, Hi, o, p2, t2);
  EXPECT_EQ(p1, p2);
  EXPECT_EQ(t1, t2);
}

TEST(MmgRemesher, GivesTheCallersSignalHandlersBack)
{
  ASSERT_TRUE(Available());
  struct sigaction mine = {}, before = {}, after = {};
  mine.sa_handler = Handler;
  sigaction(SIGINT, &mine, &before);
  std::vector<double> p;
  std::vector<int> t;
  art::MmgRemesher::Remesh(Box(2, 12, 4, 4, 4), Lo, Hi, {}, p, t);
  sigaction(SIGINT, &before, &after);
  EXPECT_EQ(after.sa_handler, &Handler);
}

TEST(MmgRemesher, RefusesAMeshWithoutAMetricPerVertex)
{
  ASSERT_TRUE(Available());
  art::MetricMesh in = Box(2, 12, 4, 4, 4);
  in.Metric.pop_back();
  std::vector<double> p;
  std::vector<int> t;
  EXPECT_THROW(art::MmgRemesher::Remesh(in, Lo, Hi, {}, p, t), std::exception);
}
