// Clipping on the Vulkan backend (SPEC §12 "clip"; camera_rays.glsl cuts
// each pixel's ray at the planes, the crop box is in the camera block's):
// every GPU grid method against the CPU's float path on a clipped bundled
// scene, and a crop box that misses the volume drawing nothing; tet-raycast
// trimming its pieces in the kernel.
#include <gtest/gtest.h>

#include <string>

#include "gpu_against_cpu.hpp"
#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "vulkan_device.hpp"

namespace vri {
namespace {

// neghip (box [0, 63]^3) at 48 x 40, lit, cut by two oblique planes and a
// crop box, none on a grid plane or a step's end.
Scene clipped_neghip(const std::string& method) {
  Scene scene = load_scene(test::source_path("scenes/neghip_lit.json"));
  SceneOverrides o;
  o.method = method;
  o.width = 48;
  o.height = 40;
  o.step = 0.7;
  o.tolerance = 1e-4;  // adaptive's (at least 1e-5 on the GPU)
  o.clip = ClipRegion{{{{1, 0.3, -0.2}, -30.7}, {{0.1, -1, 0.05}, 50.3}}, Box{{4.3, -10, 7.9}, {59.1, 61.7, 52.2}}};
  apply_overrides(scene, o);
  return scene;
}

class VulkanClip : public ::testing::TestWithParam<std::string> {};

// As the unclipped scenes (vulkan_render_test.cpp): within 1e-4 of the CPU's
// float path; adaptive's float step decisions may flip on 0.5% of pixels.
TEST_P(VulkanClip, MatchesTheCpuFloatPath) {
  Scene scene = clipped_neghip(GetParam());
  const Image cpu = SceneRenderer(scene).render({.threads = 2});
  const Image gpu = SceneRenderer(scene, Backend::Vulkan).render({.threads = 2});
  EXPECT_GT(test::max_alpha(cpu), 0.05);
  if (GetParam() == "adaptive")
    EXPECT_LE(test::share_over(gpu, cpu, 1e-4), 0.005);
  else
    EXPECT_LE(test::compare(gpu, cpu).max, 1e-4);
  // The clip shows: the unclipped image differs.
  set_clip(scene.volume, ClipRegion{});
  EXPECT_GT(test::share_over(SceneRenderer(scene, Backend::Vulkan).render({.threads = 2}), gpu, 1e-2), 0.05);
  EXPECT_EQ(vulkan::VulkanDevice::validation_messages(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Methods, VulkanClip,
                         ::testing::Values("riemann", "preint1", "preint2", "preint2-dual", "adaptive"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (c == '-') c = '_';
                           return name;
                         });

TEST(VulkanClip, ACropBoxBesideTheVolumeDrawsNothing) {
  Scene scene = clipped_neghip("riemann");
  set_clip(scene.volume, ClipRegion{{}, Box{{70, 0, 0}, {80, 63, 63}}});
  const Image gpu = SceneRenderer(scene, Backend::Vulkan).render({.threads = 2});
  EXPECT_EQ(test::max_alpha(gpu), 0);
}

TEST(VulkanClip, TooManyPlanesAreRefusedInOneLine) {
  Scene scene = clipped_neghip("riemann");
  ClipRegion many;
  for (int i = 0; i < 9; ++i) many.planes.push_back({{1, 0, 0}, double(i)});
  set_clip(scene.volume, many);
  try {
    SceneRenderer(scene, Backend::Vulkan).render({.threads = 2});
    FAIL() << "nine planes on the GPU";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("at most 8 clip planes on the GPU, not 9"), std::string::npos) << e.what();
  }
}

// tet-raycast's walk starts at the mesh's box, so the kernel trims each
// piece to the planes itself (the crop box's faces among them), as TetWalk
// does: within 1e-4 of the CPU, lit and not.
TEST(VulkanClip, TetRaycastTrimsItsPiecesAsTheCpuDoes) {
  Scene scene = load_scene(test::source_path("scenes/blunt_fin_lit.json"));
  SceneOverrides o;
  o.method = "tet-raycast";
  o.width = 48;
  o.height = 30;
  o.table_size = 64;
  const auto [lo, hi] = bounds(scene.volume);
  // The plane through the box's middle, the crop box's top below its top.
  const Vec3 mid = 0.5 * (lo + hi);
  o.clip = ClipRegion{{{{1, 0.2, 0.1}, -dot(Vec3{1, 0.2, 0.1}, mid)}}, Box{lo - Vec3{1, 1, 1}, {hi.x + 1, hi.y + 1, mid.z}}};
  apply_overrides(scene, o);
  for (const char* mode : {"sampled", "interpolated"}) {
    scene.lighting.mode = mode;
    const Image cpu = SceneRenderer(scene).render({.threads = 2});
    const Image gpu = SceneRenderer(scene, Backend::Vulkan).render({.threads = 2});
    EXPECT_GT(test::max_alpha(cpu), 0.05) << mode;
    EXPECT_LE(test::compare(gpu, cpu).max, 1e-4) << mode;
    Scene whole = scene;
    set_clip(whole.volume, ClipRegion{});
    EXPECT_GT(test::share_over(SceneRenderer(whole, Backend::Vulkan).render({.threads = 2}), gpu, 1e-2), 0.05) << mode;
  }
  EXPECT_EQ(vulkan::VulkanDevice::validation_messages(), 0u);
}

}  // namespace
}  // namespace vri
