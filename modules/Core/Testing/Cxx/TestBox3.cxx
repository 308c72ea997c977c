#include "Box3.h"

#include <gtest/gtest.h>

#include <cmath>

using art::Box3;
using art::Ray;
using art::Vec3;

namespace
{
Ray MakeRay(Vec3 o, Vec3 d)
{
  Ray r;
  r.org = o;
  r.dir = d;
  return r;
}
}

TEST(Box3, ClipsDiagonalRayAtAnalyticParameters)
{
  const Box3 b({ 0, 0, 0 }, { 2, 2, 2 });
  double t0, t1;
  ASSERT_TRUE(b.Clip(MakeRay({ -1, -1, -1 }, { 1, 1, 1 }), t0, t1));
  EXPECT_DOUBLE_EQ(t0, 1.0);
  EXPECT_DOUBLE_EQ(t1, 3.0);
}

TEST(Box3, AxisParallelRayWithSignedZeroComponents)
{
  const Box3 b({ 0, 0, 0 }, { 1, 1, 1 });
  double t0, t1;
  ASSERT_TRUE(b.Clip(MakeRay({ 0.5, 0.5, -2 }, { 0.0, -0.0, 1 }), t0, t1));
  EXPECT_DOUBLE_EQ(t0, 2.0);
  EXPECT_DOUBLE_EQ(t1, 3.0);
  // Same ray offset outside the x slab: a miss, not a NaN interval.
  EXPECT_FALSE(b.Clip(MakeRay({ 1.5, 0.5, -2 }, { -0.0, 0.0, 1 }), t0, t1));
}

TEST(Box3, RayAlongABoxFaceIsInside)
{
  const Box3 b({ 0, 0, 0 }, { 1, 1, 1 });
  double t0, t1;
  ASSERT_TRUE(b.Clip(MakeRay({ 0, 0, -1 }, { 0, 0, 1 }), t0, t1)); // along an edge
  EXPECT_DOUBLE_EQ(t0, 1.0);
  EXPECT_DOUBLE_EQ(t1, 2.0);
}

TEST(Box3, MissAndInvalidRay)
{
  const Box3 b({ 0, 0, 0 }, { 1, 1, 1 });
  double t0, t1;
  EXPECT_FALSE(b.Clip(MakeRay({ -1, 5, 0.5 }, { 1, 0, 0 }), t0, t1));
  EXPECT_FALSE(MakeRay({ 0, 0, 0 }, { 0, 0, 0 }).IsValid());
  EXPECT_FALSE(MakeRay({ 0, 0, 0 }, { NAN, 0, 1 }).IsValid());
  EXPECT_TRUE(MakeRay({ 0, 0, 0 }, { 0, 0, -1 }).IsValid());
}
