#pragma once
// The Shirley & Tuchman (1990) classification of a projected tetrahedron, as
// used by Roettger & Ertl 2002 (Sec. 2): the projection of a tetrahedron is
// either a triangle with one vertex inside it (class 1: 3 triangles fanned
// around that inner vertex) or a quadrilateral whose diagonals cross
// (class 2: 4 triangles fanned around the crossing). The inner vertex or the
// crossing is the "thick vertex": the ray through it has the longest path in
// the tetrahedron; every other projected vertex is a silhouette vertex, where
// the path length is 0.
#include <array>

namespace vri {

struct Point2 {
  double x, y;
};

struct TetProjection {
  int kind;  // 1 or 2
  // Class 1: the inner vertex; the thick ray runs from it to the face of the others.
  int inner = -1;
  // Class 2: the crossing edges (a0, a1) and (b0, b1), and where they cross:
  // a0 + u (a1 - a0) = b0 + v (b1 - b0) in the image.
  std::array<int, 2> edge_a{-1, -1}, edge_b{-1, -1};
  double u = 0, v = 0;
  // Class 1: barycentric coordinates of the inner vertex in the triangle of
  // the other three (listed in `others`).
  std::array<int, 3> others{-1, -1, -1};
  std::array<double, 3> bary{0, 0, 0};
};

// Degenerate projections (a vertex on an edge, all four on a line) come out as
// class 1 with some zero barycentric coordinates, so they still cover the
// image region exactly once.
TetProjection classify(const std::array<Point2, 4>& p);

}  // namespace vri
