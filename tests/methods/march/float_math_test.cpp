// The float paths' elementary functions (float_math.hpp) against the C
// library's, in ulps.
#include "methods/march/float_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace vri {
namespace {

TEST(FloatMath, ExpNegIsWithinTwoUlpsOfExp) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> x(0, 87);
  double worst = 0;
  for (int i = 0; i < 100000; ++i) {
    const float v = i < 1000 ? i * 1e-4f : x(rng);
    const double want = std::exp(-static_cast<double>(v));
    const double ulp = std::nextafter(static_cast<float>(want), 1.0f) - static_cast<float>(want);
    worst = std::max(worst, std::abs(detail::exp_neg(v) - want) / ulp);
  }
  EXPECT_LE(worst, 2.0);
  EXPECT_EQ(detail::exp_neg(0), 1.0f);  // zero opacity stays exactly zero
  EXPECT_LT(detail::exp_neg(1e4f), 1e-37f);
  EXPECT_GE(detail::exp_neg(1e4f), 0.0f);
}

TEST(FloatMath, LogPosIsWithinTwoUlpsOfLog) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0, 1), exponent(-120, 120);
  double worst = 0;
  for (int i = 0; i < 100000; ++i) {
    const float v = i % 2 ? unit(rng) : std::exp2(exponent(rng));
    const double want = std::log(static_cast<double>(v));
    if (std::abs(want) < 1e-3) continue;  // near 1 the absolute error is what matters (below)
    const double ulp = std::abs(std::nextafter(static_cast<float>(want), 0.0f) - static_cast<float>(want));
    worst = std::max(worst, std::abs(detail::log_pos(v) - want) / ulp);
  }
  EXPECT_LE(worst, 2.0);
  for (float v : {0.999f, 1.0f, 1.001f}) EXPECT_NEAR(detail::log_pos(v), std::log(double(v)), 1e-7) << v;
}

// x^p of a cosine: within 1e-6 of std::pow, 0^0 = 1, 0^p = 0.
TEST(FloatMath, PowUnitFollowsPow) {
  for (float p : {0.0f, 1.0f, 7.5f, 32.0f, 128.0f})
    for (int i = 0; i <= 1000; ++i) {
      const float x = i / 1000.0f;
      EXPECT_NEAR(detail::pow_unit(x, p), std::pow(double(x), double(p)), 1e-6) << x << " " << p;
    }
  EXPECT_EQ(detail::pow_unit(0, 0), 1.0f);
  EXPECT_LT(detail::pow_unit(0, 32), 1e-37f);
}

}  // namespace
}  // namespace vri
