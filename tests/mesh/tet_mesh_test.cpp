#include "vri/volume.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mesh/mesh_test_support.hpp"
#include "vri/error.hpp"

namespace vri {
namespace {

double signed_volume(const TetMesh& m, std::size_t t) {
  const auto& v = m.tets()[t];
  const auto& p = m.points();
  return dot(p[v[1]] - p[v[0]], cross(p[v[2]] - p[v[0]], p[v[3]] - p[v[0]])) / 6;
}

void expect_error(auto&& make, const std::string& fragment) {
  try {
    make();
    FAIL() << "expected an error containing '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

TEST(TetMesh, ReorientsInvertedTetrahedra) {
  const TetMesh m({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 2, 1, 3}}, {0, 1, 2, 3});
  EXPECT_NEAR(signed_volume(m, 0), 1.0 / 6, 1e-15);
  // Every face normal points away from the opposite vertex.
  for (int f = 0; f < 4; ++f) {
    const auto v = m.face(0, f);
    const auto& p = m.points();
    const Vec3 n = cross(p[v[1]] - p[v[0]], p[v[2]] - p[v[0]]);
    EXPECT_LT(dot(n, p[m.tets()[0][f]] - p[v[0]]), 0) << f;
  }
}

TEST(TetMesh, DropsDegenerateTetrahedra) {
  // The second tetrahedron is flat (all in z = 0), the third repeats a point.
  const TetMesh m({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}},
                  {{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 1, 1, 3}}, {0, 0, 0, 0, 0});
  EXPECT_EQ(m.size(), 1u);
  EXPECT_EQ(m.dropped(), 2u);
  expect_error([] { TetMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {{0, 1, 2, 3}}, {0, 0, 0, 0}); },
               "only degenerate");
}

TEST(TetMesh, RefusesBadInput) {
  const std::vector<Vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  expect_error([&] { TetMesh(p, {{0, 1, 2, 4}}, {0, 0, 0, 0}); }, "tetrahedron 0 refers to point 4");
  expect_error([&] { TetMesh(p, {{0, 1, -1, 3}}, {0, 0, 0, 0}); }, "refers to point -1");
  expect_error([&] { TetMesh(p, {{0, 1, 2, 3}}, {0, 0, std::nanf(""), 0}); }, "point 2 has a non-finite scalar");
  expect_error([&] { TetMesh(p, {{0, 1, 2, 3}}, {0, 0, 0}); }, "4 points but 3 scalars");
  expect_error([&] { TetMesh(p, {}, {0, 0, 0, 0}); }, "no tetrahedra");
  auto q = p;
  q[1].y = std::numeric_limits<double>::infinity();
  expect_error([&] { TetMesh(q, {{0, 1, 2, 3}}, {0, 0, 0, 0}); }, "non-finite coordinate");
  // Three tetrahedra on the face (0, 1, 2).
  expect_error([] {
    TetMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {0.2, 0.2, 2}},
            {{0, 1, 2, 3}, {0, 1, 2, 4}, {0, 1, 2, 5}}, {0, 0, 0, 0, 0, 0});
  }, "shared by 3");
}

TEST(TetMesh, FindsNeighboursAcrossSharedFaces) {
  const TetMesh m({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}}, {{0, 1, 2, 3}, {0, 2, 1, 4}},
                  {0, 1, 2, 3, 4});
  int shared = 0;
  for (int f = 0; f < 4; ++f) {
    if (m.neighbor(0, f) == 1) {
      ++shared;
      EXPECT_EQ(m.tets()[0][f], 3);  // the face opposite point 3 is (0, 1, 2)
    } else {
      EXPECT_EQ(m.neighbor(0, f), -1);
    }
  }
  EXPECT_EQ(shared, 1);
}

TEST(TetMesh, MeasuresEdgesBoundsAndRange) {
  const TetMesh m = test::unit_tet({5, -1, 2, 3});
  EXPECT_NEAR(m.mean_edge_length(), (3 + 3 * std::sqrt(2.0)) / 6, 1e-15);
  EXPECT_NEAR(m.max_edge_length(), std::sqrt(2.0), 1e-15);
  EXPECT_EQ(m.min_value(), -1);
  EXPECT_EQ(m.max_value(), 5);
  EXPECT_EQ(m.box_hi().z, 1);
}

}  // namespace
}  // namespace vri
