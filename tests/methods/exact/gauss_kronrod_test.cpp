#include "methods/exact/gauss_kronrod.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace vri {
namespace {

TEST(GaussKronrod, ExactForPolynomialsUpToDegree22) {
  // K15 integrates degree <= 22 exactly; G7 degree <= 13, so |K - G| vanishes up to 13.
  for (int deg : {0, 1, 5, 13, 22}) {
    double k[1];
    const double err = gk15::apply<1>([&](double t, double (&o)[1]) { o[0] = std::pow(t, deg); }, 0.5, 2.0, k);
    const double exact = (std::pow(2.0, deg + 1) - std::pow(0.5, deg + 1)) / (deg + 1);
    EXPECT_NEAR(k[0], exact, 1e-13 * exact) << deg;
    if (deg <= 13) {
      EXPECT_LT(err, 1e-12 * exact) << deg;
    }
  }
}

TEST(GaussKronrod, ErrorEstimateBoundsTheTrueError) {
  double k[2];
  const double err = gk15::apply<2>(
      [](double t, double (&o)[2]) {
        o[0] = std::exp(-3 * t);
        o[1] = 1 / (1 + 25 * t * t);  // Runge's function: hard for G7
      },
      -1, 1, k);
  const double e0 = (std::exp(3.0) - std::exp(-3.0)) / 3, e1 = 2 * std::atan(5.0) / 5;
  EXPECT_NEAR(k[0], e0, 1e-12);
  EXPECT_GE(err, std::abs(k[1] - e1));  // the estimate is conservative
  EXPECT_GT(err, 1e-4);                 // and flags the hard component
}

}  // namespace
}  // namespace vri
