#include "volume/gradient_field.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"

namespace vri {
namespace {

TEST(GradientField, CentralDifferencesDividedBySpacing) {
  // Quadratic in x: central differences are exact inside, one-sided on the border.
  const auto vol = test::volume_from({6, 3, 4}, [](double x, double y, double z) { return x * x + 3 * y - 2 * z; },
                                     {0.5, 2, 1});
  const GradientField g(vol);
  EXPECT_NEAR(g.at(2, 1, 1).x, 2 * 1.0, 1e-5);  // x = 1
  EXPECT_NEAR(g.at(2, 1, 1).y, 3, 1e-5);
  EXPECT_NEAR(g.at(2, 1, 1).z, -2, 1e-5);
  EXPECT_NEAR(g.at(0, 0, 0).x, (0.25 - 0) / 0.5, 1e-5);      // one-sided: (f(0.5) - f(0)) / 0.5
  EXPECT_NEAR(g.at(5, 2, 3).x, (6.25 - 4) / 0.5, 1e-5);      // (f(2.5) - f(2)) / 0.5
}

TEST(GradientField, TrilinearBetweenGridPoints) {
  const auto vol = test::volume_from({5, 5, 5}, [](double x, double y, double z) { return x * x + y * z; });
  const GradientField g(vol);
  // inside, the grid-point gradients are (2x, z, y) exactly, and trilinear
  // interpolation of these linear functions is exact too
  const Vec3 p{1.3, 2.6, 1.7};
  const Vec3 v = g.sample(p);
  EXPECT_NEAR(v.x, 2 * 1.3, 1e-5);
  EXPECT_NEAR(v.y, 1.7, 1e-5);
  EXPECT_NEAR(v.z, 2.6, 1e-5);
  const auto corners = g.cell_corners(0, {1, 2, 1});
  EXPECT_NEAR(corners[0], 2 * 1, 1e-5);
  EXPECT_NEAR(corners[7], 2 * 2, 1e-5);
}

}  // namespace
}  // namespace vri
