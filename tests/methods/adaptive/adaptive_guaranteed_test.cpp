// Issue 16 item 2: `adaptive --strategy guaranteed` meets its tolerance, and
// its error estimate (plus the early stop's 0.1 tol) bounds its actual error,
// on transfer functions that are opaque and steep, against `exact` at a
// tolerance 1000 times tighter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "test_support.hpp"
#include "vri/camera.hpp"
#include "methods/adaptive/adaptive_guaranteed.hpp"
#include "methods/exact/exact.hpp"
#include "vri/scene.hpp"
#include "volume/builtin_volumes.hpp"

namespace vri {
namespace {

struct Worst {
  double err = 0, over_estimate = 0;  // max |error|; max (|error| - estimate - 0.1 tol)
  int over_tolerance = 0;
};

// Compares guaranteed with exact on every ray, channel by channel.
template <class Rays>
Worst compare(const GridVolume& vol, const TransferFunction& tf, double tol, const Rays& rays,
              const Lighting& lighting = {}) {
  const GuaranteedAdaptiveIntegrator g(vol, tf, {.tolerance = tol}, lighting);
  const ExactIntegrator ex(vol, tf, tol * 1e-3, lighting);
  Worst w;
  for (const Ray& r : rays) {
    RayStats stats;
    const Rgba a = g.integrate(r, stats), e = ex.integrate(r);
    bool over = false;
    for (int c = 0; c < 4; ++c) {
      const double d = std::abs(a[c] - e[c]);
      w.err = std::max(w.err, d);
      w.over_estimate = std::max(w.over_estimate, d - stats.error_estimate[c] - 0.1 * tol);
      over = over || d > tol;
    }
    w.over_tolerance += over;
  }
  return w;
}

std::vector<Ray> image_rays(const Camera& cam) {
  std::vector<Ray> rays;
  for (int y = 0; y < cam.height(); ++y)
    for (int x = 0; x < cam.width(); ++x) rays.push_back(cam.ray(x, y));
  return rays;
}

std::vector<Ray> view_rays(const GridVolume& vol, int n) {
  const Vec3 c = 0.5 * (vol.box_lo() + vol.box_hi());
  const Vec3 ext = vol.box_hi() - vol.box_lo();
  return image_rays(Camera({.eye = c + Vec3{1.1, 0.7, 1.9} * ext.x, .target = c, .fov_y = 40, .width = n, .height = n}));
}

TEST(Guaranteed, SteepOpaqueRamp) {
  // tau 0 -> 500 over three scalar units (0.3 voxel): exact alpha is 1 on every ray that
  // crosses it; before the step cap guaranteed gave alpha 7e-6 here.
  const auto vol = test::volume_from({17, 3, 3}, [](double x, double, double) { return 10 * x; });
  const TransferFunction tf({{0, 0, 0, 0, 0}, {70, 0.2, 0.9, 0.1, 0}, {73, 1, 0.3, 0.6, 500}});
  std::vector<Ray> rays{{{-1, 1, 1}, {1, 0, 0}}};
  for (double a = 0.05; a < 1.5; a += 0.1) rays.push_back({{-1, 1, 1 - std::sin(a)}, normalize({std::cos(a), 0.01, std::sin(a)})});
  for (double tol : {1e-2, 1e-3, 1e-5}) {
    const Worst w = compare(vol, tf, tol, rays);
    EXPECT_EQ(w.over_tolerance, 0) << tol << ": max error " << w.err;
    EXPECT_LE(w.over_estimate, 1e-12) << tol;
  }
}

TEST(Guaranteed, ExtremeTransferFunctionsEndWithTheRightAnswer) {
  // Control points near -+1e308 (the segment width overflows), and tau
  // 1e300 (a step cap far below the floor): the first is a constant medium
  // to within 1e-307, the second opaque at once with the colour at entry.
  const auto vol = test::volume_from({11, 3, 3}, [](double x, double, double) { return x - 5; });
  const Ray ray{{-5, 1, 1}, {1, 0, 0}};
  const Rgba wide = GuaranteedAdaptiveIntegrator(vol, TransferFunction({{-1e308, 0, 0.2, 1, 0}, {1e308, 1, 0.2, 0, 0.8}}),
                                                 {.tolerance = 1e-6})
                        .integrate(ray);
  const double alpha = 1 - std::exp(-0.4 * 10);
  EXPECT_NEAR(wide[3], alpha, 1e-6);
  EXPECT_NEAR(wide[0], 0.5 * alpha, 1e-6);
  const Rgba dense =
      GuaranteedAdaptiveIntegrator(vol, TransferFunction({{-5, 0.3, 0.6, 0.9, 1e300}}), {.tolerance = 1e-6}).integrate(ray);
  EXPECT_EQ(dense[3], 1.0);
  EXPECT_NEAR(dense[0], 0.3, 1e-6);
  EXPECT_NEAR(dense[2], 0.9, 1e-6);
}

// Issue 46, class 5: where the step cap (half an optical depth a step)
// falls under the floor of 1e-4 voxel the floor won and every step was
// accepted: neghip's preset with its extinctions times 1e6 had 1.25 % of
// pixels over 1e-3, times 1e8 30 %, times 1e10 errors of 0.14 (the campaign:
// 0.9). Such pieces are now integrated as `exact` integrates them.
TEST(Guaranteed, DenseMediaKeepTheTolerance) {
  const Scene scene = load_scene(test::source_path("scenes/neghip.json"));
  for (double scale : {1e6, 1e8, 1e10, 1e14}) {
    std::vector<ControlPoint> points = scene.transfer_function.points();
    for (auto& p : points) p.tau *= scale;
    const Worst w = compare(scene.grid(), TransferFunction(points), 1e-3, view_rays(scene.grid(), 24));
    EXPECT_EQ(w.over_tolerance, 0) << scale << ": max error " << w.err;
  }
}

TEST(Guaranteed, RandomTransferFunctionsWithTwoToFortyPoints) {
  std::mt19937 rng(16);
  std::uniform_real_distribution<double> u(0, 1);
  const auto vol = marschner_lobb({17, 17, 17});
  const auto rays = view_rays(vol, 16);
  for (int trial = 0; trial < 40; ++trial) {
    const int n = 2 + trial % 12 * 38 / 11;  // 2 .. 40
    // Opaque: tau up to 1000 per unit (the field changes by ~0.1 per voxel),
    // some steps, some transparent runs. Without the step cap 7 of these 40
    // went over the tolerance, by up to 0.12.
    std::vector<ControlPoint> pts;
    for (int i = 0; i < n; ++i) {
      const double s = (i + u(rng)) / n;
      const double tau = u(rng) < 0.3 ? 0.0 : std::pow(10.0, 3 * u(rng)) * (u(rng) < 0.5 ? 1 : 0.05);
      pts.push_back({s, u(rng), u(rng), u(rng), tau});
      if (u(rng) < 0.2) pts.push_back({s, u(rng), u(rng), u(rng), 1000 * u(rng)});
    }
    const TransferFunction tf(pts);
    const Worst w = compare(vol, tf, 1e-3, rays);
    EXPECT_EQ(w.over_tolerance, 0) << "trial " << trial << " (" << n << " points): max error " << w.err;
    EXPECT_LE(w.over_estimate, 1e-12) << "trial " << trial;
  }
}

TEST(Guaranteed, BonsaiWithAnOpaqueTransferFunction) {
  Scene scene = load_scene(test::source_path("scenes/bonsai.json"));
  scene.camera.width = scene.camera.height = 32;
  // Opaque from 40 up, reaching tau = 500 per voxel over three scalar units.
  const TransferFunction tf({{0, 0, 0, 0, 0}, {40, 0.9, 0.6, 0.2, 0}, {43, 0.3, 0.8, 0.1, 500}, {255, 1, 1, 1, 500}});
  const Worst w = compare(scene.grid(), tf, 1e-3, image_rays(Camera(scene.camera)));
  EXPECT_EQ(w.over_tolerance, 0) << "max error " << w.err;
  EXPECT_LE(w.over_estimate, 1e-12);
}

// Lit, near a vanishing gradient the specular spike lies where the field
// along the ray turns: a cell taken as one piece there (as unlit cells in
// one segment are) put 0.01 % of this scene's pixels over 1e-4 at 128².
TEST(Guaranteed, LitMarschnerLobbAtTightTolerance) {
  Scene scene = load_scene(test::source_path("scenes/marschner_lobb_lit.json"));
  scene.camera.width = scene.camera.height = 128;
  const Worst w = compare(scene.grid(), scene.transfer_function, 1e-4, image_rays(Camera(scene.camera)), scene.lighting);
  EXPECT_EQ(w.over_tolerance, 0) << "max error " << w.err;
}

}  // namespace
}  // namespace vri
