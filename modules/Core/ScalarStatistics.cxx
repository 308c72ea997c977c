#include "ScalarStatistics.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace art
{
namespace
{
constexpr int Bins = 4096;

int BinOf(double v, double lo, double scale)
{
  return std::clamp(static_cast<int>((v - lo) * scale), 0, Bins - 1);
}

// The value below which `fraction` of the counted samples lie, from the histogram's bins
// [first, Bins), linear within a bin.
double Percentile(const std::vector<long long>& h, int first, double fraction, double lo, double width)
{
  long long total = 0;
  for (int b = first; b < Bins; ++b)
  {
    total += h[b];
  }
  const double want = fraction * static_cast<double>(total);
  double seen = 0;
  for (int b = first; b < Bins; ++b)
  {
    if (h[b] > 0 && seen + static_cast<double>(h[b]) >= want)
    {
      const double inside = (want - seen) / static_cast<double>(h[b]);
      return lo + (b + inside) * width;
    }
    seen += static_cast<double>(h[b]);
  }
  return lo + Bins * width;
}
} // namespace

ScalarStatistics Summarize(long long n, const std::function<double(long long)>& value, bool integers)
{
  ScalarStatistics s;
  double lo = INFINITY, hi = -INFINITY;
  std::set<double> distinct;
  bool fewIntegers = integers;
  for (long long i = 0; i < n; ++i)
  {
    const double v = value(i);
    if (std::isnan(v))
    {
      continue;
    }
    ++s.samples;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    if (fewIntegers && distinct.insert(v).second && static_cast<int>(distinct.size()) > ScalarStatistics::MaxLabels)
    {
      fewIntegers = false;
    }
  }
  if (s.samples == 0)
  {
    return s;
  }
  s.lo = lo, s.hi = hi;
  s.windowLow = lo, s.windowHigh = hi;
  if (fewIntegers && distinct.size() >= 2)
  {
    s.labels = true;
    s.labelValues.assign(distinct.begin(), distinct.end());
  }
  if (!(hi > lo))
  {
    return s;
  }
  const double width = (hi - lo) / Bins, scale = Bins / (hi - lo);
  std::vector<long long> h(Bins, 0);
  for (long long i = 0; i < n; ++i)
  {
    const double v = value(i);
    if (!std::isnan(v))
    {
      ++h[BinOf(v, lo, scale)];
    }
  }
  // The background: the fullest bin of a coarse histogram (a bin per value of 8-bit data, so
  // integer noise around an MRI's zero fills neighbouring bins), if it sits at the bottom of the
  // range and holds a good share; it ends where the bins after it fall below a tenth of its count.
  constexpr int Coarse = 256, PerCoarse = Bins / Coarse;
  std::vector<long long> c(Coarse, 0);
  for (int b = 0; b < Bins; ++b)
  {
    c[b / PerCoarse] += h[b];
  }
  const int top = static_cast<int>(std::max_element(c.begin(), c.end()) - c.begin());
  int first = 0;
  if (top <= static_cast<int>(ScalarStatistics::BackgroundRangeFraction * Coarse) &&
    static_cast<double>(c[top]) >= ScalarStatistics::BackgroundShare * static_cast<double>(s.samples))
  {
    int edge = top;
    while (edge + 1 < Coarse && c[edge + 1] * 10 >= c[top])
    {
      ++edge;
    }
    s.hasBackground = true;
    first = (edge + 1) * PerCoarse;
    s.backgroundTop = lo + first * width;
  }
  long long rest = 0;
  for (int b = first; b < Bins; ++b)
  {
    rest += h[b];
  }
  if (rest > 0)
  {
    s.windowLow = Percentile(h, first, 0.01, lo, width);
    s.windowHigh = std::min(hi, Percentile(h, first, 0.995, lo, width));
    if (!(s.windowHigh > s.windowLow))
    {
      s.windowLow = s.hasBackground ? s.backgroundTop : lo;
      s.windowHigh = hi;
    }
  }
  return s;
}
} // namespace art
