#include "core/f64x4.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace vri {
namespace {

// The adaptive integrators' exponential: within 2 ulp of the C library's over
// the range their optical depths take, exact at 0, and clamped at e^-708.
TEST(F64x4Exp, WithinTwoUlpOfTheLibrary) {
  std::mt19937_64 rng(7);
  const double ranges[][2] = {{-1, 1}, {0, 2}, {0, 50}, {50, 708}};
  for (const auto& r : ranges) {
    std::uniform_real_distribution<double> x(r[0], r[1]);
    for (int i = 0; i < 20000; ++i) {
      const f64x4::V v = {x(rng), x(rng), x(rng), x(rng)};
      const f64x4::V e = f64x4::exp_neg(v);
      for (int l = 0; l < 4; ++l) {
        const double want = std::exp(-v[l]);
        ASSERT_LE(std::abs(e[l] - want), 2 * std::ldexp(1.0, std::ilogb(want) - 52)) << "x = " << v[l];
      }
    }
  }
}

TEST(F64x4Exp, ExactAtZeroAndClampedFarOut) {
  const f64x4::V e = f64x4::exp_neg(f64x4::V{0.0, -0.0, 1e4, 709.5});
  EXPECT_EQ(e[0], 1.0);
  EXPECT_EQ(e[1], 1.0);
  EXPECT_GT(e[2], 0.0);
  EXPECT_NEAR(e[2], std::exp(-708.0), 2 * std::ldexp(1.0, std::ilogb(std::exp(-708.0)) - 52));
  EXPECT_EQ(e[3], e[2]);
  // Across the exponents, growing as well as decaying (2^n from its bits).
  for (double x = -700; x <= 700; x += 13.7) {
    const double want = std::exp(-x);
    EXPECT_LE(std::abs(f64x4::exp_neg(f64x4::splat(x))[0] - want), 2 * std::ldexp(1.0, std::ilogb(want) - 52)) << x;
  }
}

}  // namespace
}  // namespace vri
