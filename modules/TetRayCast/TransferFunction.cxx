// TransferFunction's own table: the union of control points with colour and extinction per
// node, per-interval slopes and the opacity lookup (what the segment rules read).
#include "TransferFunction.h"

#include "Error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace art
{
namespace
{
double TauOf(double alpha, double unit)
{
  const double a = std::min(std::max(alpha, 0.0), 1.0 - 1e-6);
  return -std::log1p(-a) / unit;
}
} // namespace

TransferFunction::TransferFunction(std::vector<Node> nodes, double unitDistance)
  : Unit(unitDistance)
{
  if (nodes.empty())
  {
    throw Error("transfer function has no control points");
  }
  if (!(unitDistance > 0.0) || !std::isfinite(unitDistance))
  {
    throw Error("transfer function unit distance must be positive");
  }
  std::stable_sort(nodes.begin(), nodes.end(), [](const Node& a, const Node& b) { return a.s < b.s; });
  for (Node& n : nodes)
  {
    if (!std::isfinite(n.s) || !std::isfinite(n.alpha))
    {
      throw Error("transfer function has a non-finite control point");
    }
    for (double& c : n.rgb)
    {
      c = std::min(std::max(c, 0.0), 1.0);
    }
    n.alpha = std::min(std::max(n.alpha, 0.0), 1.0);
    n.tau = TauOf(n.alpha, Unit);
    if (!N.empty() && N.back().s == n.s)
    {
      N.back() = n;
    }
    else
    {
      N.push_back(n);
    }
  }
  // Locate's table spreads the nodes' span over its buckets: a span of denormals (nodes 1e-310
  // apart) gave an infinite scale and negative buckets (a crash), one past 1e308 a NaN scale.
  const double span = N.back().s - N.front().s;
  if (N.size() >= 2 && !(std::isfinite(span) && std::isfinite(Buckets / span)))
  {
    std::ostringstream ss;
    ss << "transfer function's control points span " << N.front().s << " .. " << N.back().s
       << (std::isfinite(span) ? ", too close together to tell apart" : ", too wide a span")
       << " in double precision; rescale the data and the transfer function";
    throw Error(ss.str());
  }
  BuildTable();
}

void TransferFunction::BuildTable()
{
  // Locate's table: the interval holding the start of each bucket.
  T0 = N.front().s;
  TScale = N.size() < 2 ? 0.0 : Buckets / (N.back().s - N.front().s);
  Table.assign(Buckets + 1, 0);
  int i = 0;
  for (int k = 0; N.size() >= 2 && k <= Buckets; ++k)
  {
    const double s = T0 + k / TScale;
    while (i + 1 < static_cast<int>(N.size()) && N[i + 1].s <= s)
    {
      ++i;
    }
    Table[k] = i;
  }
  // A bucket is opaque when any interval it touches has extinction at either end; outside the
  // nodes the end values hold.
  auto opaque = [&](int first, int last) {
    for (int j = std::max(first, 0); j <= last && j < static_cast<int>(N.size()); ++j)
    {
      if (N[j].tau > 0)
      {
        return true;
      }
    }
    return false;
  };
  OpaqueBuckets.assign(Buckets + 3, 0);
  for (int j = 0; j < Buckets + 2; ++j)
  {
    bool o;
    if (j == 0)
    {
      o = N.front().tau > 0;
    }
    else if (j == Buckets + 1 || N.size() < 2)
    {
      o = N.back().tau > 0;
    }
    else
    {
      const int k = j - 1;
      o = opaque(Table[k], std::min(Table[k + 1] + 1, static_cast<int>(N.size()) - 1));
    }
    OpaqueBuckets[j + 1] = OpaqueBuckets[j] + (o ? 1 : 0);
  }
  const int n = static_cast<int>(N.size());
  Slopes.assign(static_cast<std::size_t>(std::max(n - 1, 0)), Slope{});
  for (int i = 0; i + 1 < n; ++i)
  {
    const double ds = N[i + 1].s - N[i].s;
    for (int k = 0; k < 3; ++k)
    {
      Slopes[i].rgb[k] = (N[i + 1].rgb[k] - N[i].rgb[k]) / ds;
    }
    Slopes[i].tau = (N[i + 1].tau - N[i].tau) / ds;
  }
  OpaqueIntervals.assign(static_cast<std::size_t>(n + 2), 0);
  for (int i = -1; i < n; ++i)
  {
    const bool o = i < 0 ? N.front().tau > 0 : (i + 1 >= n ? N.back().tau > 0 : N[i].tau > 0 || N[i + 1].tau > 0);
    OpaqueIntervals[i + 2] = OpaqueIntervals[i + 1] + (o ? 1 : 0);
  }
  Bounds.resize(static_cast<std::size_t>(n + 1));
  for (int i = -1; i < n; ++i)
  {
    Bounds[i + 1] = { i < 0 ? -HUGE_VAL : N[i].s, i + 1 < n ? N[i + 1].s : HUGE_VAL };
  }
}

double TransferFunction::Alpha(double s) const
{
  const int i = Locate(s);
  if (i < 0 || i + 1 >= static_cast<int>(N.size()))
  {
    return (i < 0 ? N.front() : N.back()).alpha;
  }
  const Node &a = N[i], &b = N[i + 1];
  return a.alpha + (s - a.s) / (b.s - a.s) * (b.alpha - a.alpha);
}
} // namespace art
