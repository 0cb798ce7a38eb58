// ClipRegion::cut (SPEC §12 "clip"): the part of a ray a region keeps,
// against where the ray crosses each plane and the box in closed form.
#include "vri/geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace vri {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ClipRegion, NoPlanesNoBoxKeepsEverything) {
  const ClipRegion none;
  EXPECT_FALSE(none.active());
  double t0 = 0.25, t1 = 7;
  EXPECT_TRUE(none.cut({{0, 0, 0}, {1, 0, 0}}, t0, t1));
  EXPECT_EQ(t0, 0.25);
  EXPECT_EQ(t1, 7);
}

TEST(ClipRegion, APlaneKeepsTheSideItsNormalPointsTo) {
  // x >= 2 (n = (2, 0, 0), d = -4: any length of normal): the ray along +x
  // keeps t >= 3 from x = -1; the ray along -x keeps t <= 3 from x = 5.
  const ClipRegion keep_x{{{{2, 0, 0}, -4}}, {}};
  double t0 = 0, t1 = kInf;
  ASSERT_TRUE(keep_x.cut({{-1, 0, 0}, {1, 0, 0}}, t0, t1));
  EXPECT_DOUBLE_EQ(t0, 3);
  EXPECT_EQ(t1, kInf);
  t0 = 0, t1 = kInf;
  ASSERT_TRUE(keep_x.cut({{5, 0, 0}, {-1, 0, 0}}, t0, t1));
  EXPECT_DOUBLE_EQ(t0, 0);
  EXPECT_DOUBLE_EQ(t1, 3);
}

TEST(ClipRegion, ObliquePlaneCutsWhereTheRayCrossesIt) {
  // x + y + z = 1 crossed by a ray from the origin along (1, 2, 2)/3 at
  // t = 3/5: kept beyond it (n = (1, 1, 1), d = -1).
  const ClipRegion region{{{{1, 1, 1}, -1}}, {}};
  double t0 = 0, t1 = 10;
  ASSERT_TRUE(region.cut({{0, 0, 0}, {1.0 / 3, 2.0 / 3, 2.0 / 3}}, t0, t1));
  EXPECT_NEAR(t0, 0.6, 1e-15);
  EXPECT_EQ(t1, 10);
}

TEST(ClipRegion, ParallelRaysAreKeptWholeOnTheKeptSideAndOnThePlane) {
  const ClipRegion keep_y{{{{0, 1, 0}, -1}}, {}};  // y >= 1
  double t0 = 0, t1 = 5;
  EXPECT_TRUE(keep_y.cut({{0, 1, 0}, {1, 0, 0}}, t0, t1));  // on the plane
  EXPECT_EQ(t0, 0);
  EXPECT_EQ(t1, 5);
  EXPECT_FALSE(keep_y.cut({{0, 0.999, 0}, {1, 0, 0}}, t0, t1));  // just below it
}

TEST(ClipRegion, PlanesFacingEachOtherKeepTheSlabBetweenThem) {
  const ClipRegion slab{{{{0, 0, 1}, -1}, {{0, 0, -1}, 2.5}}, {}};  // 1 <= z <= 2.5
  double t0 = 0, t1 = kInf;
  ASSERT_TRUE(slab.cut({{0, 0, 0}, {0, 0, 1}}, t0, t1));
  EXPECT_DOUBLE_EQ(t0, 1);
  EXPECT_DOUBLE_EQ(t1, 2.5);
  const ClipRegion apart{{{{0, 0, 1}, -2}, {{0, 0, -1}, 1}}, {}};  // z >= 2 and z <= 1: nothing
  t0 = 0, t1 = kInf;
  EXPECT_FALSE(apart.cut({{0, 0, 0}, {0, 0, 1}}, t0, t1));
}

TEST(ClipRegion, TheBoxIntersectsWithThePlanes) {
  ClipRegion region{{{{1, 0, 0}, -1.5}}, Box{{1, -1, -1}, {4, 1, 1}}};  // x >= 1.5, inside the box
  double t0 = 0, t1 = kInf;
  ASSERT_TRUE(region.cut({{0, 0, 0}, {1, 0, 0}}, t0, t1));
  EXPECT_DOUBLE_EQ(t0, 1.5);
  EXPECT_DOUBLE_EQ(t1, 4);
  region.planes.clear();
  t0 = 2, t1 = 3;  // an interval already inside the box stays as it is
  ASSERT_TRUE(region.cut({{0, 0, 0}, {1, 0, 0}}, t0, t1));
  EXPECT_EQ(t0, 2);
  EXPECT_EQ(t1, 3);
  EXPECT_FALSE(region.cut({{0, 2, 0}, {1, 0, 0}}, t0, t1));  // passes beside the box
}

TEST(ClipRegion, AFlatBoxOrACutToAPointKeepsNothing) {
  const ClipRegion flat{{}, Box{{0, 0, 1}, {1, 1, 1}}};
  double t0 = 0, t1 = kInf;
  EXPECT_FALSE(flat.cut({{0.5, 0.5, 0}, {0, 0, 1}}, t0, t1));
  const ClipRegion at{{{{1, 0, 0}, -2}, {{-1, 0, 0}, 2}}, {}};  // x >= 2 and x <= 2
  t0 = 0, t1 = kInf;
  EXPECT_FALSE(at.cut({{0, 0, 0}, {1, 0, 0}}, t0, t1));
}

}  // namespace
}  // namespace vri
