#include "vri/scene.hpp"

#include <gtest/gtest.h>

#include "vri/error.hpp"

namespace vri {
namespace {

Scene scene_with(const std::string& method) {
  return parse_scene(R"({"volume": {"builtin": "sphere", "dims": [8, 8, 8]},
    "transfer_function": {"points": [[0, 1, 1, 1, 0], [1, 1, 1, 1, 1]]},
    "camera": {"eye": [3.5, 3.5, 30], "target": [3.5, 3.5, 3.5], "width": 8, "height": 6},
    "method": )" + method + "}",
                     ".");
}

TEST(SceneOverrides, AnotherMethodDropsTheScenesTableSize) {
  Scene s = scene_with(R"({"name": "preint1", "table_size": 1024})");
  ASSERT_TRUE(s.method.table_size_given);
  SceneOverrides o;
  o.method = "preint2-dual";
  apply_overrides(s, o);
  EXPECT_EQ(s.method.name, "preint2-dual");
  EXPECT_FALSE(s.method.table_size_given);  // preint2-dual keeps its own default
}

TEST(SceneOverrides, TheSameMethodOrAGivenSizeKeepsIt) {
  Scene same = scene_with(R"({"name": "preint1", "table_size": 1024})");
  SceneOverrides o;
  o.method = "preint1";
  apply_overrides(same, o);
  EXPECT_TRUE(same.method.table_size_given);
  Scene given = scene_with(R"({"name": "preint1"})");
  o.method = "preint2-dual";
  o.table_size = 32;
  apply_overrides(given, o);
  EXPECT_TRUE(given.method.table_size_given);
  EXPECT_EQ(given.method.table_size, 32);
}

TEST(SceneOverrides, SetsEveryGivenFieldAndNoOther) {
  Scene s = scene_with(R"({"name": "riemann", "step": 0.5})");
  SceneOverrides o;
  o.strategy = "guaranteed";
  o.step = 2;
  o.hmin = 0.01;
  o.width = 17;
  o.skip_empty = false;
  o.float_math = false;
  apply_overrides(s, o);
  EXPECT_EQ(s.method.strategy, "guaranteed");
  EXPECT_DOUBLE_EQ(s.method.step, 2);
  EXPECT_DOUBLE_EQ(s.method.hmin, 0.01);
  EXPECT_DOUBLE_EQ(s.method.tolerance, 1e-6);  // untouched
  EXPECT_EQ(s.camera.width, 17);
  EXPECT_EQ(s.camera.height, 6);
  EXPECT_FALSE(s.method.fast.skip_empty);
  EXPECT_FALSE(s.method.fast.float_math);
}

TEST(SceneOverrides, AGivenVolumeReplacesTheVolumeKey) {
  const GridVolume grid({2, 2, 2}, std::vector<float>{0, 1, 2, 3, 4, 5, 6, 7});
  const std::string rest = R"({"transfer_function": {"points": [[0, 1, 1, 1, 0], [7, 1, 1, 1, 1]]},
    "camera": {"eye": [0.5, 0.5, 9], "target": [0.5, 0.5, 0.5], "width": 4, "height": 4}})";
  const Scene s = parse_scene(rest, grid, ".");
  EXPECT_EQ(s.grid().max_value(), 7.f);
  EXPECT_THROW(parse_scene(R"({"volume": {"builtin": "sphere"}, )" + rest.substr(1), grid, "."), Error);
}

}  // namespace
}  // namespace vri
