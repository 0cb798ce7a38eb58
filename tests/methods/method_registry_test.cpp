// The method registry (vri/methods.hpp) says the truth: every method renders
// the volumes, and takes the options, it claims, and refuses the others in
// one line naming it (issue 48: every list of methods reads the registry).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>
#include <vector>
#include <string>

#include "methods/method_registry_support.hpp"
#include "vri/methods.hpp"
#include "vri/render.hpp"  // vulkan_backend_built; check_work
#include "vri/camera.hpp"

namespace vri {
namespace {

TEST(MethodRegistry, NamesAreSpecNinesInItsOrderAndOnce) {
  std::string names;
  std::set<std::string_view> seen;
  for (const MethodInfo& m : methods()) {
    names += std::string(m.name) + " ";
    EXPECT_TRUE(seen.insert(m.name).second) << m.name;
    EXPECT_TRUE(m.grid || m.mesh) << m.name;
    EXPECT_FALSE(m.paper.empty()) << m.name;
    EXPECT_EQ(find_method(m.name), &m);
  }
  EXPECT_EQ(names, "riemann preint1 preint2 preint2-dual adaptive exact pt pt-cylindrical tet-raycast ");
  EXPECT_EQ(find_method("preint3"), nullptr);
}

// SPEC §9's parameter column, read independently of the registry: each
// method lists at least those (the table builder where it builds tables).
TEST(MethodRegistry, ParametersHoldSpecNinesColumn) {
  const std::pair<const char*, std::vector<std::string_view>> spec[] = {
      {"riemann", {"step"}},
      {"preint1", {"step", "table_size"}},
      {"preint2", {"step", "table_size", "iterations"}},
      {"preint2-dual", {"table_size", "iterations"}},
      {"adaptive", {"tolerance", "h0", "hmin", "hmax", "strategy"}},
      {"exact", {"tolerance"}},
      {"pt", {"table_size", "length_samples"}},
      {"pt-cylindrical", {"table_size", "planes"}},
      {"tet-raycast", {"table_size"}}};
  for (const auto& [name, keys] : spec) {
    const auto& listed = known_method(name).parameters;
    for (const std::string_view key : keys)
      EXPECT_NE(std::find(listed.begin(), listed.end(), key), listed.end()) << name << " " << key;
  }
}

TEST(MethodRegistry, ListsReadAsSentences) {
  EXPECT_EQ(method_names([](const MethodInfo& m) { return m.mesh && m.per_ray; }, "or"), "exact or tet-raycast");
  EXPECT_EQ(method_names([](const MethodInfo& m) { return m.jitter; }), "riemann");
  EXPECT_EQ(method_names([](const MethodInfo& m) { return m.termination; }), "riemann, preint1, preint2 and preint2-dual");
  try {
    known_method("preint3");
    FAIL() << "an unknown method was taken";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "unknown method 'preint3' (known: riemann, preint1, preint2, preint2-dual, adaptive, exact, "
                           "pt, pt-cylindrical, tet-raycast)");
  }
}

class EveryMethod : public ::testing::TestWithParam<std::string> {
 protected:
  const MethodInfo& method() const { return known_method(GetParam()); }
};

// A method's constructors are where its flags say it renders: one
// registration holds both, and make_integrator, SceneRenderer (pt,
// pt-cylindrical) and the Vulkan backend call nothing else.
TEST(MethodRegistry, ConstructorsAreWhereTheFlagsSay) {
  for (const vri::MethodInfo& m : vri::methods()) {
    SCOPED_TRACE(std::string(m.name));
    EXPECT_EQ(m.make_grid != nullptr, m.grid && m.per_ray);
    EXPECT_EQ(m.make_mesh != nullptr, m.mesh && m.per_ray);
    EXPECT_EQ(m.make_projected != nullptr, !m.per_ray);
    EXPECT_EQ(m.make_gpu != nullptr, vri::vulkan_backend_built() && (m.gpu_grid || m.gpu_mesh));
  }
}

TEST_P(EveryMethod, RendersTheVolumesItClaimsAndRefusesTheOthers) {
  for (const bool grid : {true, false}) {
    const std::string why = test::refusal(test::small_scene(grid, method()));
    const bool claimed = grid ? method().grid : method().mesh;
    if (claimed)
      EXPECT_EQ(why, "") << (grid ? "grid" : "mesh");
    else
      EXPECT_NE(why.find(GetParam()), std::string::npos) << (grid ? "grid: " : "mesh: ") << why;
  }
}

TEST_P(EveryMethod, TakesTerminationAndJitterWhereItClaims) {
  const bool grid = method().grid;
  Scene scene = test::small_scene(grid, method());
  scene.method.fast.termination = 0.01;
  const std::string termination = test::refusal(scene);
  EXPECT_EQ(termination.empty(), method().termination && grid) << termination;
  if (!termination.empty()) {
    EXPECT_NE(termination.find("termination"), std::string::npos) << termination;
  }
  scene = test::small_scene(grid, method());
  scene.method.jitter = 7;
  const std::string jitter = test::refusal(scene);
  EXPECT_EQ(jitter.empty(), method().jitter) << jitter;
  if (!jitter.empty()) {
    EXPECT_NE(jitter.find("jitter applies to riemann only"), std::string::npos) << jitter;
  }
}

// The work cap counts samples by the parameter the registry names: a tiny
// step over the cap is refused naming it; a cell walker is counted a
// sample per voxel unit, whatever its step says.
TEST_P(EveryMethod, WorkCapReadsTheStepParameterItNames) {
  Scene scene = test::small_scene(method().grid, method());
  scene.method.step = scene.method.hmin = 1e-3;
  scene.method.h0 = scene.method.hmax = 1e-3;
  scene.method.max_samples = 10;
  std::string why;
  try {
    check_work(scene, Camera(scene.camera));
  } catch (const Error& e) {
    why = e.what();
  }
  ASSERT_NE(why, "");
  const std::string named = "with method." + std::string(method().step_parameter) + " 0.001";
  if (method().step_parameter.empty())
    EXPECT_EQ(why.find("with method."), std::string::npos) << why;
  else
    EXPECT_NE(why.find(named), std::string::npos) << why;
}

// The registry's parameters are the method-block keys that shape the image:
// each one it lists changes some bytes, every other key changes none (a
// listed key a method ignored, or an unlisted one it read, fails here).
TEST_P(EveryMethod, ReadsTheParametersItListsAndNoOther) {
  const bool grid = method().grid;
  Scene base = test::small_scene(grid, method());
  base.method.tolerance = 1e-3;  // adaptive's steps then reach hmax
  base.lighting.enabled = true;   // exact's tolerance then decides its quadrature
  const auto render = [](const Scene& s) {
    const Image image = SceneRenderer(s).render(RenderOptions{.threads = 1});
    return std::vector<float>(image.data().begin(), image.data().end());
  };
  const std::vector<float> before = render(base);
  const bool second_order = GetParam().rfind("preint2", 0) == 0;
  const std::pair<const char*, void (*)(MethodSpec&)> changes[] = {
      {"step", [](MethodSpec& m) { m.step *= 0.7; }},
      {"tolerance", [](MethodSpec& m) { m.tolerance = 0.05; }},  // exact takes at most 0.1
      {"table_size", [](MethodSpec& m) { m.table_size *= 2; }},
      {"iterations", [](MethodSpec& m) { m.iterations /= 2; }},
      {"length_samples", [](MethodSpec& m) { m.length_samples += 4; }},
      {"planes", [](MethodSpec& m) { m.planes = 40; }},
      {"h0", [](MethodSpec& m) { m.h0 *= 0.6; }},
      {"hmin", [](MethodSpec& m) { m.hmin = m.h0; }},  // no step shorter than the first
      {"hmax", [](MethodSpec& m) { m.hmax *= 0.5; }},
      {"strategy", [](MethodSpec& m) { m.strategy = "decoupled"; }},
  };
  const auto& listed = method().parameters;
  for (const auto& [key, change] : changes) {
    Scene changed = base;
    change(changed.method);
    const bool reads = std::find(listed.begin(), listed.end(), key) != listed.end();
    // Read, but not seen in these 30 float pixels: exact's lit quadrature
    // meets 1e-3 and 0.05 alike to a float; adaptive's steps at 1e-3 never
    // shrink below h0, so hmin = h0 changes none of them.
    const std::string pair = GetParam() + " " + key;
    if (reads && (pair == "exact tolerance" || pair == "adaptive hmin")) continue;
    EXPECT_EQ(render(changed) != before, reads) << key << (reads ? " is listed but changed nothing" : " is not listed but changed the image");
  }
  Scene other_builder = base;
  other_builder.method.builder = second_order ? "plain" : "engel";  // brute and incremental agree to a float
  const bool reads = std::find(listed.begin(), listed.end(), "builder") != listed.end();
  EXPECT_EQ(render(other_builder) != before, reads) << "builder";
  for (const std::string_view key : listed)  // a key of the method block: a numeric one has its rule
    EXPECT_TRUE(key == "builder" || key == "strategy" ||
                std::any_of(method_parameters().begin(), method_parameters().end(),
                            [&](const MethodParameter& p) { return p.key == key; }))
        << key;
}

std::vector<std::string> all_names() {
  std::vector<std::string> names;
  for (const MethodInfo& m : methods()) names.emplace_back(m.name);
  return names;
}

INSTANTIATE_TEST_SUITE_P(Registry, EveryMethod, ::testing::ValuesIn(all_names()),
                         [](const auto& info) { return test::scene_test_name(info.param + ".json"); });

}  // namespace
}  // namespace vri
