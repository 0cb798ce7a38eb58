#include "vri/geometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace vri {
namespace {

const Vec3 lo{0, 0, 0}, hi{4, 2, 3};

TEST(ClipToBox, ObliqueRayChordLength) {
  const Vec3 d = normalize({1, 1, 1});
  const auto iv = clip_to_box({{-1, -1, -1}, d}, lo, hi);
  ASSERT_TRUE(iv);
  EXPECT_NEAR(iv->t0, std::sqrt(3.0), 1e-12);  // enters at the corner (0,0,0)
  EXPECT_NEAR(iv->t1, 3 * std::sqrt(3.0), 1e-12);  // leaves through y = 2
}

TEST(ClipToBox, RayAlongAFaceSeesTheMedium) {
  const auto iv = clip_to_box({{-1, 0, 3}, {1, 0, 0}}, lo, hi);  // on y = 0 and z = 3
  ASSERT_TRUE(iv);
  EXPECT_DOUBLE_EQ(iv->t0, 1);
  EXPECT_DOUBLE_EQ(iv->t1, 5);
}

TEST(ClipToBox, ParallelRayOutsideMisses) {
  EXPECT_FALSE(clip_to_box({{-1, 2.0000001, 1}, {1, 0, 0}}, lo, hi));
}

TEST(ClipToBox, OnlyPositiveTCounts) {
  const auto inside = clip_to_box({{1, 1, 1}, {1, 0, 0}}, lo, hi);
  ASSERT_TRUE(inside);
  EXPECT_DOUBLE_EQ(inside->t0, 0);
  EXPECT_DOUBLE_EQ(inside->t1, 3);
  EXPECT_FALSE(clip_to_box({{5, 1, 1}, {1, 0, 0}}, lo, hi));  // box behind the eye
}

TEST(ClipToBox, TouchingAnEdgeAtOnePointIsEmpty) {
  // passes the box's edge x = 0, y = 2 at t = 1 and stays outside otherwise
  EXPECT_FALSE(clip_to_box({{-1, 1, 1}, {1, 1, 0}}, lo, hi));
}

}  // namespace
}  // namespace vri
