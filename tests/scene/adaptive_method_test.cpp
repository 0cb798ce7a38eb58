// The adaptive keys of a scene's method block (SPEC §8, §9).
#include <gtest/gtest.h>

#include "vri/error.hpp"
#include "vri/scene.hpp"

namespace vri {
namespace {

std::string scene_with(const std::string& method) {
  return R"({"volume": {"builtin": "sphere", "dims": [8, 8, 8]},
             "transfer_function": {"points": [[0, 1, 1, 1, 0.1]]},
             "camera": {"eye": [20, 20, 20], "target": [4, 4, 4]},
             "method": )" + method + "}";
}

TEST(AdaptiveMethodBlock, ReadsEveryKey) {
  const Scene s = parse_scene(scene_with(R"({"name": "adaptive", "tolerance": 0.002, "h0": 0.25,
                                             "hmin": 0.05, "hmax": 1.5, "strategy": "decoupled"})"), ".");
  EXPECT_EQ(s.method.name, "adaptive");
  EXPECT_DOUBLE_EQ(s.method.tolerance, 0.002);
  EXPECT_DOUBLE_EQ(s.method.h0, 0.25);
  EXPECT_DOUBLE_EQ(s.method.hmin, 0.05);
  EXPECT_DOUBLE_EQ(s.method.hmax, 1.5);
  EXPECT_EQ(s.method.strategy, "decoupled");
}

TEST(AdaptiveMethodBlock, DefaultsAreThePapers) {
  const Scene s = parse_scene(scene_with(R"({"name": "adaptive"})"), ".");
  EXPECT_DOUBLE_EQ(s.method.h0, 0.5);
  EXPECT_DOUBLE_EQ(s.method.hmin, 0.1);
  EXPECT_DOUBLE_EQ(s.method.hmax, 2.0);
  EXPECT_EQ(s.method.strategy, "coupled");
}

TEST(AdaptiveMethodBlock, RejectsBadTypes) {
  EXPECT_THROW(parse_scene(scene_with(R"({"name": "adaptive", "strategy": 3})"), "."), Error);
  EXPECT_THROW(parse_scene(scene_with(R"({"name": "adaptive", "hmax": "big"})"), "."), Error);
}

}  // namespace
}  // namespace vri
