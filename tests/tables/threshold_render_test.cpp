// Issue 46, class 1: a transfer function that steps at its first control
// point ("transparent below 50": two points at s = 50), or whose points all
// share one scalar. SPEC §3 holds the first point below the step and the
// last one at it. The tables' axis spanned only the control points, so every
// scalar below was clamped onto the value above: preint1, preint2 and preint2-dual gave
// RMS 0.52 against `exact`, every pixel wrong; the mesh tables likewise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "test_support.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "tables/discrete_tf.hpp"

namespace vri {
namespace {

// RMS over every channel of every pixel.
double rms(const Image& a, const Image& b) {
  double sum2 = 0;
  for (std::size_t k = 0; k < a.data().size(); ++k) sum2 += std::pow(double(a.data()[k]) - b.data()[k], 2);
  return std::sqrt(sum2 / a.data().size());
}

Image render_with(Scene scene, MethodSpec method) {
  scene.method = std::move(method);
  return SceneRenderer(scene).render();
}

TEST(TableAxis, RenderingTablesCoverTheDataAndTheControlPoints) {
  const TransferFunction tf({{50, 0, 0, 0, 0}, {50, 1, 1, 1, 2}, {200, 0.5, 0.5, 0.5, 3}});
  const ScalarAxis spec = table_axis(tf, 256);  // SPEC §10, `vri table`: the control points
  EXPECT_EQ(spec.s_lo, 50);
  EXPECT_EQ(spec.s_hi, 200);
  const ScalarAxis wide = table_axis(tf, 256, DataRange{0, 255});
  EXPECT_EQ(wide.s_lo, 0);
  EXPECT_EQ(wide.s_hi, 255);
  const ScalarAxis inside = table_axis(tf, 256, DataRange{60, 70});
  EXPECT_EQ(inside.s_lo, 50);
  EXPECT_EQ(inside.s_hi, 200);
  // Below the step the first point holds, at it the last one sharing s (SPEC §3).
  const DiscreteTf d(tf, 256, DataRange{0, 255});
  EXPECT_EQ(d[0].tau, 0);
  EXPECT_EQ(d[49].tau, 0);
  EXPECT_EQ(d[50].tau, 2);
  const TransferFunction one({{80, 0, 0, 1, 0}, {80, 1, 1, 0, 0.05}});  // all points at one scalar
  const DiscreteTf all(one, 256, DataRange{0, 255});
  EXPECT_EQ(all[79].tau, 0);
  EXPECT_EQ(all[80].tau, 0.05);
}

// The same function with one more point below the step, holding the first
// point's values: a transfer function the tables always handled.
TransferFunction with_point_below(const TransferFunction& tf, double below) {
  std::vector<ControlPoint> points = tf.points();
  ControlPoint first = points.front();
  first.s = below;
  points.insert(points.begin(), first);
  return TransferFunction(points);
}

// The same function written with a point at the data's minimum renders the
// same bytes with every table method (both tables span the data), and both
// stay near `exact`: before, the step at the first point gave RMS 0.52.
void expect_as_with_a_point_below(Scene scene, const std::vector<TransferFunction>& tfs, double below,
                                  std::initializer_list<const char*> methods, MethodSpec base, double bound) {
  for (const TransferFunction& tf : tfs) {
    const std::string name = std::to_string(tf.points().size()) + " points from " + std::to_string(tf.s_lo());
    scene.transfer_function = tf;
    const Image reference = render_with(scene, {.name = "exact", .tolerance = 1e-7});
    for (const char* method : methods) {
      base.name = method;
      scene.transfer_function = tf;
      const Image image = render_with(scene, base);
      scene.transfer_function = with_point_below(tf, below);
      EXPECT_EQ(test::pixels(image), test::pixels(render_with(scene, base))) << name << ", " << method;
      const double e = rms(image, reference);
      std::printf("%s, %s: RMS %.2e against exact\n", name.c_str(), method, e);
      EXPECT_LT(e, bound) << name << ", " << method;
    }
  }
}

// Grid methods on neghip (uint8, 0..255).
TEST(ThresholdRender, GridTablesHoldTheValueBelowAStepAtTheFirstPoint) {
  Scene scene = load_scene(test::source_path("scenes/neghip.json"));
  scene.camera.width = scene.camera.height = 48;
  const std::vector<TransferFunction> tfs = {
      TransferFunction({{50, 1, 0.5, 0.2, 0}, {50, 1, 0.5, 0.2, 0.3}, {255, 0.2, 0.5, 1, 0.6}}),  // "transparent below 50"
      TransferFunction({{80, 0, 0, 1, 0}, {80, 1, 1, 0, 0.05}}),                                // all points at 80
      TransferFunction({{30, 1, 0, 0, 0.02}, {30, 0, 1, 0, 0.02}, {200, 0, 0, 1, 0.1}}),        // colour steps only
  };
  // Measured up to 3.4e-3 (preint2-dual's 64 entries on the colour step).
  expect_as_with_a_point_below(scene, tfs, scene.grid().min_value(), {"preint1", "preint2", "preint2-dual"},
                               {.step = 0.5}, 5e-3);
}

// The mesh tables (tet-raycast, pt, pt-cylindrical) on the bundled blunt fin.
TEST(ThresholdRender, MeshTablesHoldTheValueBelowAStepAtTheFirstPoint) {
  Scene scene = load_scene(test::source_path("scenes/blunt_fin.json"));
  scene.camera.width = scene.camera.height = 40;
  const std::vector<TransferFunction> tfs = {
      TransferFunction({{0.8, 0.1, 0.4, 1, 0}, {0.8, 0.1, 0.4, 1, 0.3}, {2.0, 1, 0.6, 0.2, 1}})};
  const auto& scalars = scene.mesh().scalars();
  expect_as_with_a_point_below(scene, tfs, *std::min_element(scalars.begin(), scalars.end()),
                               {"tet-raycast", "pt", "pt-cylindrical"}, {}, 5e-3);
}

}  // namespace
}  // namespace vri
