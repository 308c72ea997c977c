#include "ScalarStatistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace
{
art::ScalarStatistics Of(const std::vector<double>& v, bool integers)
{
  return art::Summarize(static_cast<long long>(v.size()), [&](long long i) { return v[i]; }, integers);
}
} // namespace

// An MRI-like volume: 60% background at 0 with a little noise, tissue between 80 and 160, and
// a few bright outliers at 255 that must not stretch the window.
TEST(ScalarStatistics, FindsAnMriBackgroundAndARobustWindow)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> tissue(80, 160), noise(0, 2);
  std::vector<double> v;
  for (int i = 0; i < 60000; ++i)
  {
    v.push_back(std::round(noise(rng)));
  }
  for (int i = 0; i < 39900; ++i)
  {
    v.push_back(std::round(tissue(rng)));
  }
  for (int i = 0; i < 100; ++i)
  {
    v.push_back(255);
  }
  const auto s = Of(v, true);
  EXPECT_EQ(s.lo, 0);
  EXPECT_EQ(s.hi, 255);
  ASSERT_TRUE(s.hasBackground);
  EXPECT_GE(s.backgroundTop, 2.0);
  EXPECT_LT(s.backgroundTop, 10.0);
  EXPECT_NEAR(s.windowLow, 80.8, 1.5);  // 1% into 80..160
  EXPECT_NEAR(s.windowHigh, 160, 1.5);  // 99.5%: below the 0.25% of outliers
  EXPECT_FALSE(s.labels);               // 160 distinct integers
}

// Values spread evenly with no pile at the bottom: no background, the window is the percentiles.
TEST(ScalarStatistics, AnEvenRampHasNoBackground)
{
  std::vector<double> v;
  for (int i = 0; i <= 10000; ++i)
  {
    v.push_back(i * 0.01);
  }
  const auto s = Of(v, false);
  EXPECT_FALSE(s.hasBackground);
  EXPECT_NEAR(s.windowLow, 1.0, 0.05);
  EXPECT_NEAR(s.windowHigh, 99.5, 0.05);
}

// A segmentation: integers 0 (most of it), 1, 2 and 5 are labels.
TEST(ScalarStatistics, FewIntegersAreLabels)
{
  std::vector<double> v(1000, 0.0);
  for (int i = 0; i < 100; ++i)
  {
    v[i] = 1, v[100 + i] = 2, v[200 + i] = 5;
  }
  const auto s = Of(v, true);
  ASSERT_TRUE(s.labels);
  EXPECT_EQ(s.labelValues, (std::vector<double>{ 0, 1, 2, 5 }));
  EXPECT_TRUE(s.hasBackground);
  EXPECT_FALSE(Of(v, false).labels); // the same values stored as float are not taken for labels
}

TEST(ScalarStatistics, ConstantAndEmptyAndNaN)
{
  const auto c = Of(std::vector<double>(10, 3.0), false);
  EXPECT_EQ(c.lo, 3.0);
  EXPECT_EQ(c.windowLow, 3.0);
  EXPECT_EQ(c.windowHigh, 3.0);
  EXPECT_FALSE(c.hasBackground);
  const auto e = Of({}, false);
  EXPECT_EQ(e.samples, 0);
  const auto n = Of({ std::nan(""), 1.0, 2.0 }, false);
  EXPECT_EQ(n.samples, 2);
  EXPECT_EQ(n.lo, 1.0);
  EXPECT_EQ(n.hi, 2.0);
}
