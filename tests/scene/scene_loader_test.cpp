#include "vri/scene.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"

namespace vri {
namespace {

const std::string kCamera = R"("camera": {"eye": [20, 20, 60], "target": [20, 20, 20], "width": 8, "height": 6})";

TEST(SceneLoader, ReadsEveryKeyWithDefaults) {
  const Scene s = parse_scene(R"({
    "volume": {"builtin": "marschner_lobb", "dims": [9, 9, 9], "spacing": [0.5, 0.5, 1], "origin": [1, 2, 3]},
    "transfer_function": {"opacity_points": [[0, 1, 0, 0, 0.5], [1, 0, 0, 1, 0.5]], "unit_distance": 2},
    "camera": {"eye": [0, 0, 10], "target": [0, 0, 0], "fov_y": 45, "width": 30, "height": 20},
    "background": [0.1, 0.2, 0.3],
    "method": {"name": "riemann", "step": 0.25, "tolerance": 1e-3, "table_size": 128}})",
                              ".");
  EXPECT_EQ(s.grid().dims(), (std::array<int, 3>{9, 9, 9}));
  EXPECT_DOUBLE_EQ(s.grid().spacing().x, 0.5);
  EXPECT_DOUBLE_EQ(s.grid().origin().z, 3);
  EXPECT_NEAR(s.transfer_function(0.5).tau, std::log(2.0) / 2, 1e-15);
  EXPECT_DOUBLE_EQ(s.camera.fov_y, 45);
  EXPECT_DOUBLE_EQ(s.camera.up.y, 1);  // default up
  EXPECT_EQ(s.camera.width, 30);
  EXPECT_DOUBLE_EQ(s.background.z, 0.3);
  EXPECT_EQ(s.method.name, "riemann");
  EXPECT_DOUBLE_EQ(s.method.step, 0.25);
  EXPECT_EQ(s.method.table_size, 128);
  EXPECT_TRUE(s.method.table_size_given);
  EXPECT_EQ(s.method.iterations, 8);  // default
}

TEST(SceneLoader, PathsAreRelativeToTheSceneFile) {
  const Scene s = load_scene(test::source_path("scenes/bucky.json"));
  EXPECT_EQ(s.grid().dims(), (std::array<int, 3>{32, 32, 32}));
  EXPECT_EQ(s.transfer_function.points().size(), 5u);
}

TEST(SceneLoader, EveryBundledSceneLoads) {
  for (const char* name : {"neghip", "fuel", "bucky", "silicium", "hydrogen_atom", "marschner_lobb", "tooth", "engine",
                           "bonsai", "boston_teapot"}) {
    const Scene s = load_scene(test::source_path(std::string("scenes/") + name + ".json"));
    EXPECT_GT(s.grid().max_value(), s.grid().min_value()) << name;
    EXPECT_NO_THROW(make_integrator(s.method, s.grid(), s.transfer_function)) << name;
  }
}

void expect_refused(const std::string& json, const std::string& fragment) {
  try {
    parse_scene(json, test::source_path("scenes"), "scene");
    ADD_FAILURE() << "accepted: " << json;
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
  }
}

TEST(SceneLoader, RefusesBadScenesWithOneClearLine) {
  const std::string tf = R"("transfer_function": {"points": [[0, 1, 1, 1, 0.1]]})";
  const std::string vol = R"("volume": {"builtin": "sphere", "dims": [8, 8, 8]})";
  expect_refused("{ not json", "malformed JSON");
  // issue 17: a typo is no longer ignored; the nearest key is suggested
  expect_refused("{" + vol + ", " + kCamera + R"(, "trasnfer_function": {}})",
                 "scene: trasnfer_function: unknown key (did you mean 'transfer_function'?)");
  expect_refused("{" + vol + ", " + tf + ", " + kCamera + R"(, "extra_key_for_the_future": 1})", "unknown key (known: ");
  expect_refused("[1, 2]", "scene: expected a JSON object, found [1,2]");
  expect_refused("{" + tf + ", " + kCamera + "}", "missing 'volume'");
  expect_refused("{" + vol + ", " + kCamera + R"(, "transfer_function": {"points": [[5, 1, 1, 1, 0.1], [1, 1, 1, 1, 0.1]]}})", "sorted");
  expect_refused("{" + vol + ", " + kCamera + R"(, "transfer_function": {"points": [[5, 1, 1, 1, -0.1]]}})", "tau");
  expect_refused("{" + vol + ", " + kCamera + R"(, "transfer_function": {"points": [[5, 1, 1]]}})", "transfer_function.points[0]: expected an array of 5 finite numbers, found [5,1,1]");
  expect_refused("{" + vol + ", " + kCamera +
                     R"(, "transfer_function": {"opacity_points": [[5, 1, 1, 1, 1.0]], "unit_distance": 1}})",
                 "opacity");
  expect_refused("{" + vol + ", " + tf + R"(, "camera": {"eye": [1, 1, 1], "target": [1, 1, 1]}})", "same point");
  expect_refused("{" + vol + ", " + tf + R"(, "camera": {"eye": [0, 5, 0], "target": [0, 0, 0]}})", "parallel");
  expect_refused("{" + vol + ", " + tf + R"(, "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "width": 0}})", "positive");
  expect_refused("{" + vol + ", " + tf + R"(, "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "width": "wide"}})", "width");
  expect_refused("{" + vol + ", " + tf + R"(, "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "projection": "orthographic"}})",
                 "ortho_height");
  expect_refused("{" + tf + ", " + kCamera + R"(, "volume": {"builtin": "sphere", "dims": [8, 0, 8]}})", "at least 2");
  expect_refused("{" + tf + ", " + kCamera + R"(, "volume": {"builtin": "sphere", "dims": [100000, 100000, 100000]}})", "exceeds the limit");
  expect_refused("{" + tf + ", " + kCamera + R"(, "volume": {"builtin": "teapot"}})", "volume.builtin: expected marschner_lobb, sphere, random or tetrahedralized, found \"teapot\"");
  // A file's keys on a builtin volume (found by fuzz_scene: it tetrahedralized a 64^3 sphere, ignoring "file").
  expect_refused("{" + tf + ", " + kCamera + R"(, "volume": {"builtin": "sphere", "file": [1, 4, 4]}})",
                 "volume.file: applies to volume files, not to builtin volumes");
  expect_refused("{" + tf + ", " + kCamera + R"(, "volume": {"builtin": "sphere", "grid": [91, 8, 4]}})",
                 "volume.grid: applies to tetrahedralized volumes only");
  expect_refused("{" + tf + ", " + kCamera + R"(, "volume": {"file": "../data/bucky_32x32x32_uint8.raw", "dims": [32, 32, 31]}})",
                 "bytes");
  expect_refused("{" + tf + ", " + kCamera + R"(, "volume": {"file": "../data/bucky_32x32x32_uint8.raw", "dims": [32, 32, 32], "type": "complex"}})",
                 "unknown sample type");
  expect_refused("{" + tf + ", " + kCamera + R"(, "volume": {"file": "nowhere.raw", "dims": [2, 2, 2]}})", "cannot open");
  expect_refused("{" + tf + ", " + kCamera + R"(, "volume": {"file": "mesh.vtk"}})", "cannot open");
  expect_refused("{" + vol + ", " + kCamera + R"(, "transfer_function": {"file": "missing_tf.json"}})", "cannot open");
}

// "clip" (SPEC §12): planes and a box in world units, on the volume.
TEST(SceneLoader, ReadsAndChecksClip) {
  const std::string head = R"({"volume": {"builtin": "sphere", "dims": [8, 8, 8]},
    "transfer_function": {"points": [[0, 1, 1, 1, 0.1]]}, )" + kCamera;
  const Scene s = parse_scene(head + R"(, "clip": {"planes": [[0, 0, 2, -3], [1, 1, 0, 0.5]],
    "box": [[-1, 0, 1], [2, 3, 4.5]]}})", ".");
  const ClipRegion& c = s.clip();
  ASSERT_EQ(c.planes.size(), 2u);
  EXPECT_DOUBLE_EQ(c.planes[0].normal.z, 2);
  EXPECT_DOUBLE_EQ(c.planes[0].d, -3);
  EXPECT_DOUBLE_EQ(c.planes[1].d, 0.5);
  ASSERT_TRUE(c.box);
  EXPECT_DOUBLE_EQ(c.box->lo.x, -1);
  EXPECT_DOUBLE_EQ(c.box->hi.z, 4.5);
  EXPECT_EQ(&s.clip(), &s.grid().clip_region());  // the volume holds it
  EXPECT_FALSE(parse_scene(head + "}", ".").clip().active());
  EXPECT_FALSE(parse_scene(head + R"(, "clip": {}})", ".").clip().active());
  EXPECT_TRUE(parse_scene(head + R"(, "clip": {"box": [[0, 0, 0], [0, 1, 1]]}})", ".").clip().active());  // flat
  expect_refused(head + R"(, "clip": [1, 2]})", "scene: clip: expected a JSON object, found [1,2]");
  expect_refused(head + R"(, "clip": {"plane": []}})", "scene: clip.plane: unknown key (did you mean 'planes'?)");
  expect_refused(head + R"(, "clip": {"planes": [0, 0, 1, 0]}})", "scene: clip.planes[0]: expected an array of 4 finite numbers");
  expect_refused(head + R"(, "clip": {"planes": {"n": 1}}})", "scene: clip.planes: expected an array of planes");
  expect_refused(head + R"(, "clip": {"planes": [[0, 0, 0, 1]]}})", "scene: clip.planes[0]: expected a plane [nx, ny, nz, d] whose normal is not 0");
  expect_refused(head + R"(, "clip": {"planes": [[1e300, 1e300, 0, 1]]}})", "whose normal is not 0");
  expect_refused(head + R"(, "clip": {"planes": [[0, 0, 1, "a"]]}})", "clip.planes[0]: expected an array of 4 finite numbers");
  expect_refused(head + R"(, "clip": {"box": [[2, 0, 0], [1, 1, 1]]}})",
                 "scene: clip.box: expected two corners [[x0, y0, z0], [x1, y1, z1]] with x0 <= x1");
  expect_refused(head + R"(, "clip": {"box": [[0, 0, 0]]}})", "scene: clip.box: expected two corners");
  expect_refused(head + R"(, "clip": {"box": [[0, 0], [1, 1, 1]]}})", "scene: clip.box: expected an array of 3 finite numbers");
  EXPECT_DOUBLE_EQ(parse_clip(R"({"planes": [[1, 0, 0, 2]]})").planes[0].d, 2);
}

TEST(SceneLoader, ReadsAndChecksIterations) {
  const std::string head = R"({"volume": {"builtin": "sphere", "dims": [8, 8, 8]},
    "transfer_function": {"points": [[0, 1, 1, 1, 0.1]]}, )" + kCamera;
  const Scene s = parse_scene(head + R"(, "method": {"name": "preint2", "iterations": 16}})", ".");
  EXPECT_EQ(s.method.iterations, 16);
  EXPECT_FALSE(s.method.table_size_given);
  expect_refused(head + R"(, "method": {"iterations": 0}})", "method.iterations (--iterations): expected an integer in [1, 4096], found 0");
  expect_refused(head + R"(, "method": {"iterations": 4097}})", "found 4097");
  expect_refused(head + R"(, "method": {"iterations": 2.5}})", "method.iterations (--iterations): expected an integer in [1, 4096], found 2.5");
  expect_refused(head + R"(, "method": {"iterations": "many"}})", "iterations");
}

TEST(MakeIntegrator, RefusesUnknownAndUnimplementedMethods) {
  const Scene s = parse_scene(R"({"volume": {"builtin": "sphere", "dims": [8, 8, 8]},
    "transfer_function": {"points": [[0, 1, 1, 1, 0.1]]}, )" + kCamera + "}", ".");
  MethodSpec m;
  m.name = "magic";
  EXPECT_THROW(make_integrator(m, s.grid(), s.transfer_function), Error);
  m.name = "riemann";
  m.step = 0;
  EXPECT_THROW(make_integrator(m, s.grid(), s.transfer_function), Error);
  m.name = "exact";
  EXPECT_EQ(make_integrator(m, s.grid(), s.transfer_function)->name(), "exact");
}

}  // namespace
}  // namespace vri
