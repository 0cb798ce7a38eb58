// The per-pixel error estimate of the adaptive methods.
#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"
#include "methods/adaptive/adaptive_guaranteed.hpp"
#include "methods/adaptive/adaptive_simpson.hpp"
#include "methods/exact/exact.hpp"
#include "render/error_estimate.hpp"
#include "vri/render.hpp"
#include "volume/builtin_volumes.hpp"

namespace vri {
namespace {

const GridVolume& volume() {
  static const GridVolume vol = marschner_lobb({25, 25, 25});
  return vol;
}
const TransferFunction& tf() {
  static const TransferFunction t({{0.2, 0.1, 0.4, 0.9, 0}, {0.5, 0.9, 0.6, 0.1, 0.6}, {0.5, 1, 0.2, 0.2, 0.3},
                                   {0.8, 1, 1, 1, 0.1}});
  return t;
}
// 16 x 12 pixels; the volume [0,24]^3 covers the middle, the corners miss it.
Camera camera() { return Camera({.eye = {60, 45, 80}, .target = {12, 12, 12}, .fov_y = 40, .width = 16, .height = 12}); }

double sum(const Image& img) {
  double s = 0;
  for (float v : img.data()) s += v;
  return s;
}

TEST(ErrorEstimate, ZeroWhereRaysMissAndNonNegative) {
  const AdaptiveSimpsonIntegrator integ(volume(), tf(), {.tolerance = 1e-3});
  const Image est = render_error_estimate(camera(), integ);
  for (int c = 0; c < 4; ++c) EXPECT_EQ(est.pixel(0, 0)[c], 0.f);
  for (float v : est.data()) EXPECT_GE(v, 0.f);
  EXPECT_GT(est.pixel(8, 6)[3], 0.f);
}

TEST(ErrorEstimate, ShrinksWithTheTolerance) {
  for (AdaptiveStrategy st : {AdaptiveStrategy::Coupled, AdaptiveStrategy::Decoupled}) {
    const double loose = sum(render_error_estimate(camera(), AdaptiveSimpsonIntegrator(volume(), tf(), {.tolerance = 1e-2, .strategy = st})));
    const double tight = sum(render_error_estimate(camera(), AdaptiveSimpsonIntegrator(volume(), tf(), {.tolerance = 1e-5, .hmin = 0.001, .strategy = st})));
    EXPECT_LT(tight, 0.1 * loose) << int(st);
  }
}

TEST(ErrorEstimate, GuaranteedModeBoundsTheActualError) {
  // On smooth pieces the estimate |D - S|/15 bounds the error of the
  // Richardson-corrected sum; the early stop adds at most 0.1 tol.
  const double tol = 1e-3;
  const GuaranteedAdaptiveIntegrator integ(volume(), tf(), {.tolerance = tol});
  const Camera cam = camera();
  const Image img = render(cam, integ), est = render_error_estimate(cam, integ);
  const Image ref = render(cam, ExactIntegrator(volume(), tf(), 1e-10));
  for (std::size_t i = 0; i < img.data().size(); ++i) {
    EXPECT_LE(std::abs(img.data()[i] - ref.data()[i]), est.data()[i] + 0.1 * tol + 1e-6) << i;
    EXPECT_LE(est.data()[i], tol) << i;
  }
}

TEST(ErrorEstimate, SameBytesForAnyThreadCount) {
  const AdaptiveSimpsonIntegrator integ(volume(), tf(), {.tolerance = 1e-3, .strategy = AdaptiveStrategy::Decoupled});
  EXPECT_EQ(test::pixels(render_error_estimate(camera(), integ, {.threads = 1})),
            test::pixels(render_error_estimate(camera(), integ, {.threads = 2, .tile_size = 3})));
}

}  // namespace
}  // namespace vri
