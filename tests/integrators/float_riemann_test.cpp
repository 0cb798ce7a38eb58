// riemann's float path (float_riemann.hpp): exp_neg against the C library's
// exp, and the float sum in closed form on a homogeneous volume.
#include "integrators/float_riemann.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "vri/integrators/riemann.hpp"
#include "vri/volume/grid_volume.hpp"

namespace vri {
namespace {

TEST(FloatRiemann, ExpNegIsWithinTwoUlpsOfExp) {
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

// A constant field: the sum is exact whatever the step, 1 - exp(-tau L)
// in alpha and c (1 - exp(-tau L)) in colour, to float rounding.
TEST(FloatRiemann, HomogeneousSlabIsClosedForm) {
  const GridVolume volume({5, 5, 9}, std::vector<float>(5 * 5 * 9, 100.0f));
  const TransferFunction tf({{0, 0.2, 0.4, 0.8, 0.3}, {200, 0.2, 0.4, 0.8, 0.3}});
  for (double step : {1.0, 0.7, 0.25}) {
    const RiemannIntegrator riemann(volume, tf, step);
    const Ray ray{{2.3, 1.7, -5}, {0, 0, 1}};  // through z = 0 .. 8: L = 8
    const Rgba v = riemann.integrate(ray);
    const double alpha = 1 - std::exp(-0.3 * 8);
    EXPECT_NEAR(v[3], alpha, 2e-6) << step;
    EXPECT_NEAR(v[0], 0.2 * alpha, 2e-6) << step;
    EXPECT_NEAR(v[2], 0.8 * alpha, 2e-6) << step;
  }
}

}  // namespace
}  // namespace vri
