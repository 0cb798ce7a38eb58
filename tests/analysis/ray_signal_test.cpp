#include "vri/analysis.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"
#include "vri/error.hpp"

namespace vri {
namespace {

TEST(RaySignal, LinearSignal) {
  // s = 2x along x over [0, 8], uniform step 0.5: orders 1 and 2 are exact,
  // and order 0 (each sample held for h/2 either side) has xi = b h L / 4.
  const auto vol = test::volume_from({9, 3, 3}, [](double x, double, double) { return 2 * x; });
  const RaySignal sig(vol, {{-1, 1, 1}, {1, 0, 0}}, 0.5);
  EXPECT_EQ(sig.sample_t().size(), 17u);
  EXPECT_NEAR(sig.xi(0), 2 * 0.5 * 8 / 4, 1e-9);
  EXPECT_NEAR(sig.xi(1), 0, 1e-9);
  EXPECT_NEAR(sig.xi(2), 0, 1e-9);
}

TEST(RaySignal, StepsLongerThanTheRayOrNotFinite) {
  // issue 17: an infinite step left one sample and read past the end; a
  // step longer than the ray gives one interval, the linear signal exactly.
  const auto vol = test::volume_from({9, 3, 3}, [](double x, double, double) { return 2 * x; });
  const Ray ray{{-1, 1, 1}, {1, 0, 0}};
  EXPECT_THROW(RaySignal(vol, ray, INFINITY), Error);
  EXPECT_THROW(RaySignal(vol, ray, NAN), Error);
  EXPECT_THROW(RaySignal(vol, ray, 1e-300), Error);  // too many samples, refused before the cast
  const RaySignal sig(vol, ray, 1e300);
  EXPECT_EQ(sig.sample_t().size(), 2u);
  EXPECT_NEAR(sig.approximation(2, 4.0), 6.0, 1e-9);  // x = 3
  EXPECT_NEAR(sig.xi(1), 0, 1e-9);
}

TEST(RaySignal, QuadraticSignalIsExactAtSecondOrder) {
  // f = x y is reproduced exactly by trilinear interpolation; along the
  // diagonal x = y = u the signal is u^2 = t^2 / 2 (t = sqrt 2 u).
  const auto vol = test::volume_from({9, 9, 3}, [](double x, double y, double) { return x * y; });
  const double h = std::sqrt(2.0) / 2;  // half a cell diagonal
  const RaySignal sig(vol, {{0, 0, 1}, normalize({1, 1, 0})}, h);
  const double L = 8 * std::sqrt(2.0);
  // linear interpolation of t^2/2 over an interval of length h errs by h^3/12 in area
  EXPECT_NEAR(sig.xi(1), (L / h) * h * h * h / 12, 1e-5);  // xi is a 256-point midpoint sum
  EXPECT_NEAR(sig.xi(2), 0, 1e-9);
  EXPECT_NEAR(sig.approximation(2, 3.3), 3.3 * 3.3 / 2, 1e-9);
}

TEST(RaySignal, CellFaceSamplingPutsEachParabolaInsideOneCell) {
  const auto vol = test::volume_from({5, 5, 5}, [](double x, double y, double z) { return x * y * z; });
  const RaySignal sig(vol, {{-1, 0.3, 0.7}, normalize({1, 0.35, 0.2})}, std::nullopt);
  const auto& t = sig.sample_t();
  ASSERT_EQ(t.size() % 2, 1u);  // faces and midpoints: an even number of intervals
  for (std::size_t k = 0; k + 2 < t.size(); k += 2) EXPECT_NEAR(t[k + 1] - t[k], t[k + 2] - t[k + 1], 1e-12);
  // inside a cell xyz along a ray is a cubic: the parabola is close but not exact
  EXPECT_GT(sig.xi(2), 0);
  EXPECT_LT(sig.xi(2), 0.2 * sig.xi(1));
  EXPECT_LT(sig.xi(1), sig.xi(0));
}

TEST(RaySignal, PlotAndErrors) {
  const auto vol = test::volume_from({4, 4, 4}, [](double x, double, double) { return x; });
  const RaySignal sig(vol, {{-1, 1, 1}, {1, 0, 0}}, 1.0);
  const std::string svg = ray_signal_svg(sig);
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_EQ(std::count(svg.begin(), svg.end(), '\n') > 10, true);
  EXPECT_THROW(RaySignal(vol, {{-1, 9, 1}, {1, 0, 0}}, 1.0), Error);  // misses
  EXPECT_THROW(RaySignal(vol, {{-1, 1, 1}, {1, 0, 0}}, 0.0), Error);
}

}  // namespace
}  // namespace vri
