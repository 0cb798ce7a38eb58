#include "mesh/point_gradients.hpp"

#include <gtest/gtest.h>

#include "mesh/mesh_test_support.hpp"

namespace vri {
namespace {

double linear(double x, double y, double z) { return 0.3 * x - 0.2 * y + 0.45 * z + 1; }

TEST(PointGradients, LinearFieldGivesItsGradientEverywhere) {
  // Every tetrahedron has the field's gradient, so every average is it too,
  // and so is every interpolation inside a tetrahedron (anisotropic spacing).
  const GridVolume grid = test::volume_from({5, 4, 6}, linear, {1, 1.5, 0.75}, {-2, 0, 1});
  const Vec3 expected{0.3, -0.2, 0.45};
  for (int per_cell : {5, 6}) {
    const TetMesh mesh = tetrahedralize(grid, per_cell);
    const PointGradients g(mesh);
    for (std::size_t i = 0; i < mesh.points().size(); ++i)
      for (int a = 0; a < 3; ++a) ASSERT_NEAR(g.at_point(std::int32_t(i))[a], expected[a], 1e-5) << i;
    for (std::size_t t = 0; t < mesh.size(); t += 7) {
      const auto& v = mesh.tets()[t];
      const Vec3 p = 0.1 * mesh.points()[v[0]] + 0.2 * mesh.points()[v[1]] + 0.3 * mesh.points()[v[2]] +
                     0.4 * mesh.points()[v[3]];
      for (int a = 0; a < 3; ++a) ASSERT_NEAR(g.sample(std::int32_t(t), p)[a], expected[a], 1e-5);
    }
  }
}

TEST(PointGradients, VolumeWeightedAverageAndLinearInside) {
  // Two tetrahedra sharing the face (1,0,0), (0,1,0), (0,0,1): the unit one
  // (volume 1/6, s = x + 2y + 3z there, gradient (1, 2, 3)) and one with apex
  // (2,2,2) (volume 5/6: height 5/sqrt(3) over the shared face against
  // 1/sqrt(3)), where s(apex) = 0 gives it another gradient.
  const TetMesh m({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 2, 2}}, {{0, 1, 2, 3}, {4, 1, 2, 3}},
                  {0, 1, 2, 3, 0});
  const Vec3 g1{1, 2, 3};
  const auto& t1 = m.tets()[1];  // possibly reoriented
  const auto& sc = m.scalars();
  const Vec3 g2 = tet_gradient(m, 1, {sc[t1[0]], sc[t1[1]], sc[t1[2]], sc[t1[3]]});
  // Along (1,0,0) -> (2,2,2) etc. the second one falls back to 0: g2 . (1, 2, 2) = -1.
  EXPECT_NEAR(dot(g2, Vec3{1, 2, 2}), -1, 1e-12);
  const PointGradients g(m);
  const Vec3 shared = (1.0 / 6 * g1 + 5.0 / 6 * g2) * (1 / (1.0 / 6 + 5.0 / 6));
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(g.at_point(0)[a], g1[a], 1e-12);
    EXPECT_NEAR(g.at_point(4)[a], g2[a], 1e-12);
    EXPECT_NEAR(g.at_point(2)[a], shared[a], 1e-12);
    // The centroid of the unit tetrahedron: the mean of its point gradients.
    EXPECT_NEAR(g.sample(0, {0.25, 0.25, 0.25})[a], 0.25 * g1[a] + 0.75 * shared[a], 1e-12);
  }
  EXPECT_DOUBLE_EQ(g.flat_threshold(), 3e-6);
}

}  // namespace
}  // namespace vri
