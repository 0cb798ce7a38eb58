#include "classify.hpp"

#include <cmath>

namespace vri {

namespace {

double orient(Point2 a, Point2 b, Point2 c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

}  // namespace

TetProjection classify(const std::array<Point2, 4>& p) {
  // Class 2: some pair of opposite edges crosses properly (each separates the other's ends).
  constexpr int kPairs[3][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2}};
  for (const auto& q : kPairs) {
    const Point2 a0 = p[q[0]], a1 = p[q[1]], b0 = p[q[2]], b1 = p[q[3]];
    const double o1 = orient(a0, a1, b0), o2 = orient(a0, a1, b1);
    const double o3 = orient(b0, b1, a0), o4 = orient(b0, b1, a1);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0))) {
      TetProjection r;
      r.kind = 2;
      r.edge_a = {q[0], q[1]};
      r.edge_b = {q[2], q[3]};
      r.u = o3 / (o3 - o4);  // where b0-b1's line cuts a0-a1
      r.v = o1 / (o1 - o2);
      return r;
    }
  }
  // Class 1: the vertex inside the triangle of the other three; with no proper
  // crossing one always is (up to rounding: take the least outside).
  TetProjection best;
  best.kind = 1;
  double best_min = -INFINITY;
  for (int i = 0; i < 4; ++i) {
    std::array<int, 3> o;
    for (int k = 0, n = 0; k < 4; ++k)
      if (k != i) o[n++] = k;
    const double area = orient(p[o[0]], p[o[1]], p[o[2]]);
    std::array<double, 3> b{0, 0, 0};
    if (area != 0) {
      b[0] = orient(p[i], p[o[1]], p[o[2]]) / area;
      b[1] = orient(p[o[0]], p[i], p[o[2]]) / area;
      b[2] = 1 - b[0] - b[1];
    } else {
      b = {-INFINITY, -INFINITY, -INFINITY};
    }
    const double m = std::fmin(b[0], std::fmin(b[1], b[2]));
    if (m > best_min) {
      best_min = m;
      best.inner = i;
      best.others = o;
      best.bary = b;
    }
  }
  if (best_min == -INFINITY) {  // all four on one line: nothing to draw
    best.inner = 0;
    best.others = {1, 2, 3};
    best.bary = {1, 0, 0};
  }
  for (double& b : best.bary) b = std::fmax(b, 0.0);
  return best;
}

}  // namespace vri
