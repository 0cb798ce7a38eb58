#include "volume/builtin_volumes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "test_support.hpp"

namespace vri {
namespace {

TEST(MarschnerLobb, MatchesTheFormulaAtKnownPoints) {
  const auto vol = marschner_lobb();  // 41^3, f_M = 6, alpha = 0.25
  // Centre (x=y=z=0): rho_r(0) = cos(12 pi) = 1 -> (1 - 0 + 0.25 * 2) / 2.5 = 0.6
  EXPECT_NEAR(vol.at(20, 20, 20), 0.6, 1e-6);
  // z = 1 (k = 40), x = y = 0: (1 - 1 + 0.5) / 2.5 = 0.2
  EXPECT_NEAR(vol.at(20, 20, 40), 0.2, 1e-6);
  // corner x = y = -1, z = -1: r = sqrt 2, rho_r = cos(12 pi cos(pi sqrt2 / 2))
  const double r = std::sqrt(2.0);
  const double rho = std::cos(12 * std::numbers::pi * std::cos(std::numbers::pi * r / 2));
  EXPECT_NEAR(vol.at(0, 0, 0), (2 + 0.25 * (1 + rho)) / 2.5, 1e-6);
  EXPECT_GE(vol.min_value(), 0);
  EXPECT_LE(vol.max_value(), 1);
}

TEST(SphereDistance, SignedDistanceFromTheCentre) {
  const auto vol = sphere_distance({33, 33, 33}, 10);
  EXPECT_NEAR(vol.at(16, 16, 16), -10, 1e-6);
  EXPECT_NEAR(vol.at(26, 16, 16), 0, 1e-6);
  EXPECT_NEAR(vol.at(0, 16, 16), 6, 1e-6);
}

TEST(RandomField, DeterministicUniformAndSeeded) {
  const auto a = random_field({16, 16, 16}, 7), b = random_field({16, 16, 16}, 7), c = random_field({16, 16, 16}, 8);
  EXPECT_EQ(test::floats(a), test::floats(b));
  EXPECT_NE(test::floats(a), test::floats(c));
  double mean = 0;
  for (float v : test::floats(a)) {
    ASSERT_GE(v, 0.f);
    ASSERT_LT(v, 1.f);
    mean += v;
  }
  mean /= a.size();
  EXPECT_NEAR(mean, 0.5, 0.02);  // 4096 samples: sigma of the mean is 0.0045
}

// A part (distributed rendering's brick) holds the whole grid's values at its points.
TEST(BuiltinVolumes, PartsHoldTheWholeGridsValues) {
  const GridRegion region{{3, 0, 5}, {9, 6, 11}};
  const auto pick = [&](std::array<int, 3>) { return region; };
  const std::array<int, 3> dims{13, 9, 12};
  for (const auto& [whole, part] : {std::pair{marschner_lobb(dims), marschner_lobb(dims, 6, 0.25, pick)},
                                    std::pair{sphere_distance(dims), sphere_distance(dims, 0, pick)},
                                    std::pair{random_field(dims, 9), random_field(dims, 9, pick)}}) {
    ASSERT_TRUE(part.brick());
    EXPECT_EQ(part.brick()->offset, region.lo);
    EXPECT_EQ(test::floats(part), test::floats(cut_region(whole, region)));
  }
}

}  // namespace
}  // namespace vri
