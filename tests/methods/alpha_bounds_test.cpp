// Issue 16 item 3: every method returns a pixel (C, alpha) with alpha = 1 - T
// in [0, 1] and each colour channel within what the transfer function can
// emit, on every bundled scene.
//
// The bound. C = integral of c(s) tau T dt and alpha = integral of tau T dt =
// 1 - T_end (SPEC §4), so C <= alpha * max c. Unlit, max c is the largest
// r, g or b of the control points (c is linear between them). Lit (SPEC §5),
// c_lit = c (ka + kd |N.L|) + ks |N.H|^p with |N.L|, |N.H| <= 1 and c_lit not
// clamped, so max c_lit = maxc (ka + kd) + ks.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "test_support.hpp"
#include "vri/camera.hpp"
#include "vri/methods.hpp"
#include "methods/mesh_tables.hpp"
#include "methods/projected/projected_tetrahedra.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "tables/cylindrical_table.hpp"

namespace vri {
namespace {

double brightest(const Scene& scene) {
  double maxc = 0;
  for (const auto& p : scene.transfer_function.points()) maxc = std::max({maxc, p.r, p.g, p.b});
  const Lighting& l = scene.lighting;
  return l.enabled ? maxc * (l.ambient + l.diffuse) + l.specular : maxc;
}

std::vector<MethodSpec> grid_methods() {
  std::vector<MethodSpec> m;
  m.push_back({.name = "riemann", .step = 0.5});
  m.push_back({.name = "exact", .tolerance = 1e-3});
  for (const char* st : {"coupled", "decoupled", "guaranteed"})
    m.push_back({.name = "adaptive", .tolerance = 1e-2, .strategy = st});
  for (const char* name : {"preint1", "preint2", "preint2-dual"})
    m.push_back({.name = name, .step = 1.0, .table_size = 32, .table_size_given = true, .iterations = 8});
  return m;
}

std::vector<MethodSpec> mesh_methods() {
  std::vector<MethodSpec> m;
  m.push_back({.name = "exact", .tolerance = 1e-3});
  for (const char* name : {"tet-raycast", "pt", "pt-cylindrical"})
    m.push_back({.name = name, .table_size = 32, .table_size_given = true, .length_samples = 8});
  return m;
}

Image render_with(const Scene& scene, const MethodSpec& spec, const Camera& cam) {
  if (spec.name == "pt" || spec.name == "pt-cylindrical") {
    const auto table = make_slab_table(spec, scene.mesh(), scene.transfer_function);
    const auto weighted = make_weighted_length_tables(spec, scene.mesh(), scene.transfer_function, scene.lighting);
    if (spec.name == "pt") return render_projected(cam, scene.mesh(), *table, {}, scene.lighting, weighted.get());
    const CylindricalTable cyl(*table, spec.table_size, spec.table_size);
    if (!weighted) return render_projected(cam, scene.mesh(), cyl, {}, scene.lighting);
    const WeightedCylindricalTables wc{
        CylindricalTable(weighted->front, spec.table_size, spec.table_size),
        CylindricalTable(weighted->back, spec.table_size, spec.table_size)};
    return render_projected(cam, scene.mesh(), cyl, {}, scene.lighting, &wc);
  }
  const auto integ = std::visit(
      [&](const auto& v) { return make_integrator(spec, v, scene.transfer_function, scene.lighting); }, scene.volume);
  return render(cam, *integ);
}

class AlphaBounds : public ::testing::TestWithParam<std::string> {};

TEST_P(AlphaBounds, AlphaInUnitIntervalAndColourWithinAlphaTimesBrightest) {
  Scene scene = load_scene(test::source_path("scenes/" + GetParam()));
  scene.camera.width = scene.camera.height = 24;
  const Camera cam(scene.camera);
  const double maxc = brightest(scene);
  const bool mesh = std::holds_alternative<TetMesh>(scene.volume);
  for (const MethodSpec& spec : mesh ? mesh_methods() : grid_methods()) {
    const Image img = render_with(scene, spec, cam);
    const std::string what = GetParam() + " " + spec.name + " " + spec.strategy;
    int bad = 0;
    for (int y = 0; y < img.height(); ++y)
      for (int x = 0; x < img.width(); ++x) {
        const float* p = img.pixel(x, y);
        const double a = p[3];
        // float storage: a few ulps of slack.
        const bool ok = a >= 0 && a <= 1 && p[0] >= 0 && p[1] >= 0 && p[2] >= 0 &&
                        std::max({p[0], p[1], p[2]}) <= a * maxc * (1 + 1e-5) + 1e-6;
        if (!ok && bad++ < 3)
          ADD_FAILURE() << what << " pixel " << x << "," << y << ": " << p[0] << " " << p[1] << " " << p[2]
                        << " alpha " << a << " (brightest " << maxc << ")";
      }
    EXPECT_EQ(bad, 0) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(AllBundledScenes, AlphaBounds, ::testing::ValuesIn(test::bundled_scenes()),
                         [](const auto& info) { return test::scene_test_name(info.param); });

}  // namespace
}  // namespace vri
