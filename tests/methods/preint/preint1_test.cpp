#include "methods/preint/preint1.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "methods/bucky_support.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri {
namespace {

// A constant field: every slab is homogeneous, so any step, including one
// that leaves a partial last slab, must give alpha = 1 - exp(-tau L) exactly.
TEST(Preint1, ConstantFieldMatchesClosedFormForAnyStep) {
  const GridVolume volume({4, 4, 4}, std::vector<float>(64, 100.0f), {2, 2, 2});
  const TransferFunction tf({{0, 0, 0, 0, 0}, {100, 0.5, 0.25, 1, 0.3}, {200, 1, 1, 1, 2}});
  const Ray ray{{1.3, 2.2, -5}, {0, 0, 1}};  // crosses the box over z in [0, 6]
  const double a = 1 - std::exp(-0.3 * 6);
  for (double step : {1.0, 0.7, 2.5, 4.0}) {  // world step 2 * step; 6 / (2 * step) not always whole
    const Preint1Integrator p(volume, tf, step, 65, "incremental");  // s = 100 is entry 32
    const Rgba v = p.integrate(ray);
    EXPECT_NEAR(v[3], a, 2e-6) << step;
    EXPECT_NEAR(v[0], 0.5 * a, 2e-6) << step;
    EXPECT_NEAR(v[1], 0.25 * a, 2e-6) << step;
  }
}

// The bundled bucky ball through a transfer function of two narrow spikes
// (one scalar unit wide) on a gentle ramp; control points sit on the 256
// table scalars, so the table's discretisation is exact.
Scene spiky_bucky() {
  return test::bucky_scene(R"([[0,0,0,0,0], [59,0.2,0.2,1,0], [60,0.2,0.4,1,0.6], [61,0.2,0.2,1,0],
      [139,1,0.3,0.1,0], [140,1,0.6,0.1,1.5], [141,1,0.3,0.1,0], [200,0.9,0.9,0.9,0.02], [255,1,1,1,0.05]])",
                           40);
}

using test::rms_alpha;

TEST(Preint1, ConvergesToExactAndBeatsRiemannOnNarrowSpikes) {
  const Scene scene = spiky_bucky();
  const auto exact = make_integrator({.name = "exact", .tolerance = 1e-6}, scene.grid(), scene.transfer_function);
  const Image reference = render(Camera(scene.camera), *exact);
  double previous = 1;
  for (double step : {1.0, 0.5, 0.25, 0.125, 0.0625}) {
    const double pre = rms_alpha(scene, reference, {.name = "preint1", .step = step});
    const double rie = rms_alpha(scene, reference, {.name = "riemann", .step = step});
    EXPECT_LT(pre, previous) << step;
    EXPECT_LT(pre, rie / 2.5) << step;  // measured: 3.7x at step 1, 7x at 0.25
    previous = pre;
  }
  EXPECT_LT(previous, 2e-3);  // measured 1.4e-3 at step 1/16
}

TEST(Preint1, BadParametersAreErrors) {
  const Scene scene = spiky_bucky();
  EXPECT_THROW(Preint1Integrator(scene.grid(), scene.transfer_function, 0.0, 256, "incremental"), Error);
  EXPECT_THROW(Preint1Integrator(scene.grid(), scene.transfer_function, 1.0, 1, "incremental"), Error);
  EXPECT_THROW(Preint1Integrator(scene.grid(), scene.transfer_function, 1.0, 256, "fastest"), Error);
  EXPECT_THROW(make_integrator({.name = "preint1"}, scene.grid(), scene.transfer_function, {.enabled = true, .mode = "phong"}),
               Error);
}

}  // namespace
}  // namespace vri
