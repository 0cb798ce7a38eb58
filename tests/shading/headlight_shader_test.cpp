#include "shading/headlight_shader.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"
#include "vri/error.hpp"

namespace vri {
namespace {

TEST(HeadlightShader, TwoSidedBlinnPhongWithTheLightAtTheEye) {
  const auto vol = test::volume_from({4, 4, 4}, [](double x, double, double) { return x; });
  const HeadlightShader sh(Lighting{true, 0.3, 0.7, 0.4, 32, "sampled"}, vol);
  const Vec3 d = normalize({1, 1, 0});
  const double x = std::sqrt(0.5);  // |N . d| for N = (1, 0, 0)
  for (Vec3 g : {Vec3{5, 0, 0}, Vec3{-5, 0, 0}}) {  // two-sided
    const auto t = sh.terms(g, d);
    EXPECT_NEAR(t.a, 0.3 + 0.7 * x, 1e-15);
    EXPECT_NEAR(t.b, 0.4 * std::pow(x, 32), 1e-15);
  }
  EXPECT_NEAR(sh.terms({0, 0, 2}, d).a, 0.3, 1e-15);  // N perpendicular to the view: ambient only
  EXPECT_DOUBLE_EQ(sh.max_brightness(), 1.4);
}

TEST(HeadlightShader, NoNormalBelowTheFlatThreshold) {
  // range 3 over voxel unit 1: threshold 3e-6
  const auto vol = test::volume_from({4, 4, 4}, [](double x, double, double) { return x; });
  const HeadlightShader sh(Lighting{true, 0.3, 0.7, 0.4, 32, "sampled"}, vol);
  EXPECT_NEAR(sh.flat_threshold(), 3e-6, 1e-12);
  const auto t = sh.terms({2e-6, 0, 0}, {1, 0, 0});
  EXPECT_DOUBLE_EQ(t.a, 1.0);
  EXPECT_DOUBLE_EQ(t.b, 0.0);
  EXPECT_THROW(HeadlightShader(Lighting{true, -0.1, 0.7, 0.4, 32, "sampled"}, vol), Error);
}

}  // namespace
}  // namespace vri
