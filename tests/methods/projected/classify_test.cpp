#include "methods/projected/classify.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace vri {
namespace {

// Class 1: each vertex in turn inside the triangle of the other three.
TEST(Classify, InnerVertexGivesClassOneWithItsBarycentrics) {
  const Point2 tri[3] = {{0, 0}, {6, 0}, {0, 6}};
  const Point2 inner{1, 2};  // barycentrics (1 - 1/6 - 2/6, 1/6, 2/6) = (0.5, 1/6, 1/3)
  for (int i = 0; i < 4; ++i) {
    std::array<Point2, 4> p;
    for (int k = 0, n = 0; k < 4; ++k) p[k] = k == i ? inner : tri[n++];
    const TetProjection r = classify(p);
    ASSERT_EQ(r.kind, 1) << i;
    EXPECT_EQ(r.inner, i);
    EXPECT_NEAR(r.bary[0], 0.5, 1e-15);
    EXPECT_NEAR(r.bary[1], 1.0 / 6, 1e-15);
    EXPECT_NEAR(r.bary[2], 1.0 / 3, 1e-15);
  }
}

// Class 2: each of the three pairings of opposite edges as the crossing diagonals.
TEST(Classify, CrossingDiagonalsGiveClassTwoAndTheCrossing) {
  // Diagonals (0,0)-(4,4) and (4,0)-(0,2): they cross at (4/3, 4/3), a third
  // of the way along the first and two thirds along the second.
  const Point2 a0{0, 0}, a1{4, 4}, b0{4, 0}, b1{0, 2};
  const int layouts[3][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}};
  for (const auto& l : layouts) {
    std::array<Point2, 4> p;
    p[l[0]] = a0;
    p[l[1]] = a1;
    p[l[2]] = b0;
    p[l[3]] = b1;
    const TetProjection r = classify(p);
    ASSERT_EQ(r.kind, 2);
    const Point2 e0 = p[r.edge_a[0]], e1 = p[r.edge_a[1]], f0 = p[r.edge_b[0]], f1 = p[r.edge_b[1]];
    EXPECT_NEAR(e0.x + r.u * (e1.x - e0.x), 4.0 / 3, 1e-14);
    EXPECT_NEAR(e0.y + r.u * (e1.y - e0.y), 4.0 / 3, 1e-14);
    EXPECT_NEAR(f0.x + r.v * (f1.x - f0.x), 4.0 / 3, 1e-14);
    EXPECT_NEAR(f0.y + r.v * (f1.y - f0.y), 4.0 / 3, 1e-14);
    // The crossing edges are the pair given as diagonals, in some order.
    std::array<int, 4> got = {r.edge_a[0], r.edge_a[1], r.edge_b[0], r.edge_b[1]};
    std::sort(got.begin(), got.end());
    EXPECT_EQ(got, (std::array<int, 4>{0, 1, 2, 3}));
    EXPECT_TRUE((std::min(r.edge_a[0], r.edge_a[1]) == std::min(l[0], l[1])) ||
                (std::min(r.edge_a[0], r.edge_a[1]) == std::min(l[2], l[3])));
  }
}

TEST(Classify, DegenerateProjectionsFallBackToClassOne) {
  // A vertex exactly on an edge of the others' triangle (the tetrahedron seen edge-on).
  const TetProjection on_edge = classify({Point2{0, 0}, {4, 0}, {0, 4}, {2, 0}});
  EXPECT_EQ(on_edge.kind, 1);
  EXPECT_EQ(on_edge.inner, 3);
  EXPECT_NEAR(on_edge.bary[0] + on_edge.bary[1] + on_edge.bary[2], 1, 1e-15);
  EXPECT_GE(std::min({on_edge.bary[0], on_edge.bary[1], on_edge.bary[2]}), 0);
  // Two vertices projecting onto one point (an edge along the view direction).
  const TetProjection coincident = classify({Point2{0, 0}, {4, 0}, {0, 4}, {4, 0}});
  EXPECT_EQ(coincident.kind, 1);
  // All four on a line: nothing to draw, but no failure.
  EXPECT_EQ(classify({Point2{0, 0}, {1, 1}, {2, 2}, {3, 3}}).kind, 1);
}

}  // namespace
}  // namespace vri
