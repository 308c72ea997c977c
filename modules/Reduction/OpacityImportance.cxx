#include "OpacityImportance.h"

#include "Error.h"
#include "ParallelTiles.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace art
{
OpacityImportance::OpacityImportance(std::vector<std::pair<double, double>> nodes)
  : N(std::move(nodes))
{
  if (N.empty())
  {
    throw Error("the scalar-opacity function has no nodes");
  }
  for (size_t i = 0; i < N.size(); ++i)
  {
    if (!std::isfinite(N[i].first) || !std::isfinite(N[i].second))
    {
      throw Error("the scalar-opacity function holds a NaN or infinite value");
    }
    if (N[i].second < 0)
    {
      throw Error("the scalar-opacity function has a negative opacity (" + std::to_string(N[i].second) + ")");
    }
    if (i > 0 && !(N[i].first > N[i - 1].first))
    {
      throw Error("the scalar-opacity function's scalars must strictly increase (" +
        std::to_string(N[i - 1].first) + " then " + std::to_string(N[i].first) + ")");
    }
  }
}

double OpacityImportance::Opacity(double s) const
{
  if (s <= N.front().first)
  {
    return N.front().second;
  }
  if (s >= N.back().first)
  {
    return N.back().second;
  }
  const auto it = std::upper_bound(N.begin(), N.end(), s, [](double v, const auto& n) { return v < n.first; });
  const auto& a = *(it - 1);
  const auto& b = *it;
  return a.second + (b.second - a.second) * (s - a.first) / (b.first - a.first);
}

double OpacityImportance::MaxOpacity(double lo, double hi) const
{
  // Piecewise linear: the maximum is at an end or at a node inside.
  double a = std::max(Opacity(lo), Opacity(hi));
  for (const auto& n : N)
  {
    if (n.first > lo && n.first < hi)
    {
      a = std::max(a, n.second);
    }
  }
  return a;
}

void OpacityImportance::SetIsoValues(std::vector<double> values)
{
  for (double v : values)
  {
    if (!std::isfinite(v))
    {
      throw Error("an iso-value is NaN or infinite");
    }
  }
  std::sort(values.begin(), values.end());
  Iso = std::move(values);
}

double OpacityImportance::MaxSlope(double lo, double hi) const
{
  const auto iso = std::lower_bound(Iso.begin(), Iso.end(), lo);
  double g = iso != Iso.end() && *iso <= hi ? GIso : 0.0;
  for (size_t k = 0; k + 1 < N.size(); ++k)
  {
    // Closed intervals: a voxel exactly at a node sees the slopes on both sides.
    if (N[k].first <= hi && N[k + 1].first >= lo)
    {
      g = std::max(g, std::fabs(N[k + 1].second - N[k].second) / (N[k + 1].first - N[k].first));
    }
  }
  return g;
}

void OpacityImportance::Prepare(
  const VoxelVolume& vol, double floor, int radius, const std::function<void(double)>& done)
{
  if (!(floor > 0 && floor <= 1))
  {
    throw Error("the importance floor must be in (0, 1], got " + std::to_string(floor));
  }
  radius = std::max(0, radius);
  const long long n = vol.NumberOfVoxels();
  const int* d = vol.Dims;
  std::vector<float> lo(static_cast<size_t>(n)), hi(static_cast<size_t>(n));
  for (long long i = 0; i < n; ++i)
  {
    lo[i] = hi[i] = static_cast<float>(vol.Value(i));
  }
  // Separable min / max filter, one axis at a time, each line independent.
  std::vector<float> tlo(lo.size()), thi(hi.size());
  const long long stride[3] = { 1, d[0], static_cast<long long>(d[0]) * d[1] };
  for (int axis = 0; axis < 3 && radius > 0; ++axis)
  {
    const int len = d[axis];
    const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
    const long long lines = static_cast<long long>(d[u]) * d[v];
    ForEachRange(lines, 64, [&](long long l0, long long l1, Counters&) {
      for (long long l = l0; l < l1; ++l)
      {
        const long long base = (l % d[u]) * stride[u] + (l / d[u]) * stride[v];
        for (int i = 0; i < len; ++i)
        {
          float a = lo[base + i * stride[axis]], b = hi[base + i * stride[axis]];
          for (int j = std::max(0, i - radius), e = std::min(len - 1, i + radius); j <= e; ++j)
          {
            a = std::min(a, lo[base + j * stride[axis]]);
            b = std::max(b, hi[base + j * stride[axis]]);
          }
          tlo[base + i * stride[axis]] = a;
          thi[base + i * stride[axis]] = b;
        }
      }
    });
    lo.swap(tlo);
    hi.swap(thi);
    if (done)
    {
      done(0.25 * (axis + 1));
    }
  }
  Lo = std::move(lo);
  Hi = std::move(hi);
  Fl = floor;
  GMax = 0;
  for (size_t k = 0; k + 1 < N.size(); ++k)
  {
    GMax = std::max(GMax, std::fabs(N[k + 1].second - N[k].second) / (N[k + 1].first - N[k].first));
  }
  GIso = Iso.empty() ? 0.0 : (GMax > 0 ? GMax : 1.0);
  GMax = std::max(GMax, GIso);
  if (!(GMax > 0))
  {
    Fl = 1.0; // constant opacity and no iso-surface: every voxel matters alike
  }
  // The weight of a voxel whose fit stays inside its neighbourhood's range, as most do: the
  // reduction asks for it at every voxel of every level.
  W0.resize(Lo.size());
  PL.resize(Lo.size());
  PH.resize(Lo.size());
  const float inf = std::numeric_limits<float>::infinity();
  ForEachRange(static_cast<long long>(W0.size()), 4096, [&](long long i0, long long i1, Counters&) {
    for (long long i = i0; i < i1; ++i)
    {
      const double g0 = MaxSlope(Lo[i], Hi[i]);
      W0[i] = static_cast<float>(Scaled(g0));
      // MaxSlope(min(Lo, u), max(Hi, u)) stays g0 until u reaches a segment steeper than g0:
      // below Lo, the highest end of one; above Hi, the lowest start of one (open bounds).
      double pl = -std::numeric_limits<double>::infinity(), ph = std::numeric_limits<double>::infinity();
      for (size_t k = 0; k + 1 < N.size(); ++k)
      {
        const double g = std::fabs(N[k + 1].second - N[k].second) / (N[k + 1].first - N[k].first);
        if (g > g0 && N[k + 1].first < Lo[i])
        {
          pl = std::max(pl, N[k + 1].first);
        }
        if (g > g0 && N[k].first > Hi[i])
        {
          ph = std::min(ph, N[k].first);
        }
      }
      for (double v : Iso) // zero-width segments of slope GIso
      {
        if (GIso > g0 && v < Lo[i])
        {
          pl = std::max(pl, v);
        }
        if (GIso > g0 && v > Hi[i])
        {
          ph = std::min(ph, v);
        }
      }
      // Floats rounded inwards, so that the open interval never holds a fit of another weight.
      float fl = static_cast<float>(pl), fh = static_cast<float>(ph);
      fl = std::isinf(pl) ? -inf : (fl < pl ? std::nextafter(fl, inf) : fl);
      fh = std::isinf(ph) ? inf : (fh > ph ? std::nextafter(fh, -inf) : fh);
      PL[i] = std::min(fl, Lo[i]);
      PH[i] = std::max(fh, Hi[i]);
    }
  });
  if (done)
  {
    done(1.0);
  }
}

} // namespace art
