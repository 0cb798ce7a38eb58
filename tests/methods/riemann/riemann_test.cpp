#include "methods/riemann/riemann.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "test_support.hpp"
#include "vri/error.hpp"
#include "methods/exact/exact.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "volume/builtin_volumes.hpp"

namespace vri {
namespace {

// The closed forms hold to 1e-12 on the double path, the reference (the
// float path: FastPath tests and float_riemann_test.cpp).
const FastPath kDouble{.float_math = false};

TEST(Riemann, HomogeneousMediumIsExactAtAnyStep) {
  const TransferFunction tf({{0, 0.3, 0.6, 0.1, 0.25}});
  const auto vol = random_field({9, 9, 9}, 1);
  const Ray ray{{-3, 4, 4}, {1, 0, 0}};  // chord of length 8
  for (double step : {0.3, 1.0, 3.0, 7.9}) {
    const Rgba c = RiemannIntegrator(vol, tf, step, {}, kDouble).integrate(ray);
    EXPECT_NEAR(c[3], 1 - std::exp(-2.0), 1e-12) << step;
    EXPECT_NEAR(c[1], 0.6 * (1 - std::exp(-2.0)), 1e-12) << step;
  }
}

TEST(Riemann, StepsAreInVoxelUnits) {
  // Spacing 0.5: a step of 1 voxel unit is 0.5 world units; a linear tau ramp
  // makes the left sum's error proportional to the world step.
  const auto vol = test::volume_from({9, 2, 2}, [](double x, double, double) { return x; }, {0.5, 0.5, 0.5});
  const TransferFunction tf({{0, 1, 1, 1, 0}, {4, 1, 1, 1, 1}});
  const Ray ray{{-1, 0.25, 0.25}, {1, 0, 0}};
  // tau(x) = x/4 on x in [0, 4]: left sums with world step 0.5 give depth 0.5 * sum_{k<8} k/8 = 1.75.
  EXPECT_NEAR(RiemannIntegrator(vol, tf, 1.0, {}, kDouble).integrate(ray)[3], 1 - std::exp(-1.75), 1e-12);
  EXPECT_NEAR(RiemannIntegrator(vol, tf, 1.0).integrate(ray)[3], 1 - std::exp(-1.75), 1e-6);  // float path
}

// A constant field: the sum is exact whatever the step, 1 - exp(-tau L)
// in alpha and c (1 - exp(-tau L)) in colour, to float rounding.
TEST(Riemann, FloatPathHomogeneousSlabIsClosedForm) {
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

// Summed absolute error against exact for h = 0.2, 0.1, 0.05, 0.025 on neghip (24 x 24).
std::vector<double> neghip_errors(const Lighting& lighting) {
  Scene scene = load_scene(test::source_path("scenes/neghip.json"));
  scene.camera.width = scene.camera.height = 24;
  const Camera cam(scene.camera);
  const Image ref = render(cam, ExactIntegrator(scene.grid(), scene.transfer_function, 1e-8, lighting));
  std::vector<double> err;
  for (double h : {0.2, 0.1, 0.05, 0.025}) {
    const Image img = render(cam, RiemannIntegrator(scene.grid(), scene.transfer_function, h, lighting));
    double sum = 0;
    for (std::size_t i = 0; i < img.data().size(); ++i) sum += std::abs(img.data()[i] - ref.data()[i]);
    err.push_back(sum);
  }
  return err;
}

TEST(Riemann, ConvergesToExactAtFirstOrder) {
  const auto err = neghip_errors({});
  for (std::size_t i = 1; i < err.size(); ++i) {
    const double order = std::log2(err[i - 1] / err[i]);
    std::printf("riemann h = %g: summed error %.6g, order %.3f\n", 0.2 / (1 << i), err[i], order);
    EXPECT_GT(order, 0.9) << "h halving step " << i;
    EXPECT_LT(order, 1.2) << "h halving step " << i;
  }
  // measured: 1.113, 1.087, 1.039 - approaching 1 as h shrinks
  EXPECT_NEAR(std::log2(err[2] / err[3]), 1.0, 0.08);
}

TEST(Riemann, LitConvergesToLitExactAtFirstOrder) {
  const auto err = neghip_errors(Lighting{true, 0.3, 0.7, 0.4, 32, "sampled"});
  for (std::size_t i = 1; i < err.size(); ++i) {
    const double order = std::log2(err[i - 1] / err[i]);
    std::printf("lit riemann h = %g: summed error %.6g, order %.3f\n", 0.2 / (1 << i), err[i], order);
    EXPECT_GT(order, 0.85) << i;
    EXPECT_LT(order, 1.3) << i;
  }
}

TEST(Riemann, RejectsBadSteps) {
  const auto vol = random_field({3, 3, 3});
  const TransferFunction tf({{0, 0, 0, 0, 1}});
  EXPECT_THROW(RiemannIntegrator(vol, tf, 0), Error);
  EXPECT_THROW(RiemannIntegrator(vol, tf, -1), Error);
  EXPECT_THROW(RiemannIntegrator(vol, tf, 1e-6), Error);
  EXPECT_THROW(RiemannIntegrator(vol, tf, NAN), Error);
}

}  // namespace
}  // namespace vri
