// Arrays larger than one storage buffer (vulkan/host/gpu_array.hpp,
// shaders/split_array.glsl): this program pretends the device's largest
// storage buffer is 256 KiB (VRI_VULKAN_MAX_BUFFER_BYTES, set before the
// device is made), so small scenes split their volume, tables and gradient
// field into up to four parts, and the rays into chunks, as a 256^3 scene
// does on lavapipe (128 MiB), and the tables built on the GPU are written
// into parts. The images must still match the CPU float path (on lavapipe:
// to the byte; adaptive guaranteed: within its tolerance of `exact`) and the
// tables the CPU's, with the validation layer on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "gpu_against_cpu.hpp"
#include "gpu_array.hpp"
#include "gpu_scene_data.hpp"
#include "mesh/mesh_test_support.hpp"
#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "tables/second_order_table.hpp"
#include "tables/sliced_builder.hpp"
#include "vulkan_device.hpp"

namespace vri {
namespace {

constexpr std::size_t kPart = 256 * 1024;
const bool kSmallBuffers = setenv("VRI_VULKAN_MAX_BUFFER_BYTES", std::to_string(kPart).c_str(), 1) == 0;

TEST(GpuArray, SplitsIntoPartsAndReadsBack) {
  ASSERT_TRUE(kSmallBuffers);
  const auto device = vulkan::VulkanDevice::shared();
  ASSERT_EQ(device->max_storage_buffer_bytes(), kPart);
  ASSERT_EQ(std::size_t{1} << device->part_shift(), kPart);
  std::vector<std::byte> data(3 * kPart + 1000);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = std::byte((i * 2654435761u) >> 13);
  const vulkan::GpuArray array(device, data, "the test array");
  const auto parts = array.bindings();
  for (int k = 0; k < 4; ++k) ASSERT_NE(parts[k], nullptr);
  EXPECT_NE(parts[2], parts[3]) << "four parts";
  EXPECT_EQ(parts[3]->size(), 1000u) << "the last part holds the rest";
  std::vector<std::byte> back(data.size());
  array.download(back);
  EXPECT_EQ(back, data);

  const vulkan::GpuArray small(device, std::vector<std::byte>(100, std::byte{7}), "a small array");
  for (const vulkan::GpuBuffer* b : small.bindings()) EXPECT_EQ(b, small.bindings()[0]) << "one part, repeated";

  try {
    vulkan::GpuArray too_big(device, 4 * kPart + 16, "the huge table");
    ADD_FAILURE() << "five parts accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the huge table"), std::string::npos) << e.what();
  }
}

// Issue 47: four 2 GiB buffers hold 2^33 uint8 voxels, which the shaders'
// 32-bit offsets would wrap; such a volume is refused before any upload.
TEST(GpuArray, VolumesBeyondTheShadersOffsetsAreRefused) {
  EXPECT_NO_THROW(vulkan::check_shader_addressable(GridVolume::kMaxSamples));
  EXPECT_NO_THROW(vulkan::check_shader_addressable(0xffffffffULL / 3));
  try {
    vulkan::check_shader_addressable(std::uint64_t{1} << 32);
    ADD_FAILURE() << "2^32 voxels accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("32-bit offsets"), std::string::npos) << e.what();
  }
}

Scene with(Scene scene, const char* method, int table_size, int width, int height) {
  scene.method.name = method;
  scene.method.step = 0.7;
  scene.method.table_size = table_size;
  scene.method.table_size_given = true;
  scene.camera.width = width;
  scene.camera.height = height;
  return scene;
}

// adaptive guaranteed at 1e-3 on the GPU (float step decisions of its own):
// within its tolerance of `exact`.
void expect_guaranteed_within_tolerance(Scene scene) {
  scene.method.strategy = "guaranteed";
  scene.method.tolerance = 1e-3;
  Scene exact = scene;
  exact.method.name = "exact";
  exact.method.tolerance = 1e-7;
  const Image gpu = SceneRenderer(scene, Backend::Vulkan).render({.threads = 2});
  EXPECT_LE(test::compare(gpu, SceneRenderer(exact).render({.threads = 2})).max, 1e-3);
  EXPECT_GT(test::max_alpha(gpu), 0.05);
}

// A float volume of 41^3 (three parts), preint1's 256^2 table (four parts),
// preint2's 40^3 (four), and 96 x 80 rays of up to 128 bytes (four chunks).
TEST(SplitArrays, UnlitScenesMatchTheCpu) {
  const Scene scene = parse_scene(R"({"volume": {"builtin": "marschner_lobb", "dims": [41, 41, 41]},
    "transfer_function": {"points": [[0, 0, 0, 0, 0], [0.3, 0.2, 0.5, 1, 0.05], [0.6, 1, 0.8, 0.2, 0.2],
                                     [0.61, 1, 0.2, 0.1, 3], [0.62, 1, 0.8, 0.2, 0.2], [1, 1, 1, 1, 0.4]]},
    "camera": {"eye": [95, 82, 116], "target": [20, 20, 20], "up": [0, 0, 1], "fov_y": 30}})",
                                  test::source_path("scenes"));
  EXPECT_LE(test::gpu_against_cpu(with(scene, "riemann", 256, 96, 80)).max, 1e-4);
  EXPECT_LE(test::gpu_against_cpu(with(scene, "preint1", 256, 96, 80)).max, 1e-4);
  EXPECT_LE(test::gpu_against_cpu(with(scene, "preint2", 40, 96, 80)).max, 1e-4);
  expect_guaranteed_within_tolerance(with(scene, "adaptive", 256, 96, 80));  // table_size unread
  EXPECT_EQ(vulkan::VulkanDevice::validation_messages(), 0u);
}

// The lit Marschner-Lobb scene: its gradient field (41^3 x 12 bytes) in four
// parts, preint2's three weighted 40^3 tables in four each, preint2-dual's
// 32 x 12^3 likewise.
TEST(SplitArrays, LitScenesMatchTheCpu) {
  Scene scene = load_scene(test::source_path("scenes/marschner_lobb_lit.json"));
  for (const char* mode : {"sampled", "interpolated"}) {
    scene.lighting.mode = mode;
    EXPECT_LE(test::gpu_against_cpu(with(scene, "riemann", 256, 48, 40)).max, 1e-4) << mode;
    EXPECT_LE(test::gpu_against_cpu(with(scene, "preint1", 128, 48, 40)).max, 1e-4) << mode;
    EXPECT_LE(test::gpu_against_cpu(with(scene, "preint2", 40, 48, 40)).max, 1e-4) << mode;
    // 32 lengths of 12^3: four parts each.
    EXPECT_LE(test::gpu_against_cpu(with(scene, "preint2-dual", 12, 48, 40)).max, 1e-4) << mode;
  }
  expect_guaranteed_within_tolerance(with(scene, "adaptive", 256, 48, 40));  // table_size unread
  EXPECT_EQ(vulkan::VulkanDevice::validation_messages(), 0u);
}

// tet-raycast's (l, s_f, s_b) table of 64 lengths of 32^2 (1 MiB: four
// parts) on a small mesh (its tetrahedra in one buffer: 96 bytes each).
TEST(SplitArrays, MeshTablesMatchTheCpu) {
  Scene scene{test::carved_mesh(7, [](double x, double y, double z) { return 0.1 * x + 0.08 * y - 0.05 * z + 0.4; },
                                [](double x, double y, double) { return !(x > 2 && x < 4 && y > 2 && y < 4); }),
              TransferFunction({{0, 0, 0, 1, 0}, {0.3, 0, 1, 0, 0.2}, {0.6, 1, 1, 0, 1.2}, {1, 1, 0, 0, 0.4}}),
              {}, {}, {0, 0, 0}, {}};
  scene.camera.eye = {14, -9, 11};
  scene.camera.target = {3, 3, 3};
  scene = with(scene, "tet-raycast", 32, 48, 40);
  scene.method.length_samples = 64;
  EXPECT_LE(test::gpu_against_cpu(scene).max, 1e-4);
  EXPECT_EQ(vulkan::VulkanDevice::validation_messages(), 0u);
}

// Tables written into split arrays: a 200^2 first-order table (three
// parts) and a 40^3 second-order one (four), as the CPU builds them.
TEST(SplitArrays, TablesBuiltOnTheGpuMatchTheCpu) {
  const DiscreteTf tf(load_transfer_function(test::source_path("presets/neghip_spike.json")), 200);
  const PreintegrationTable gpu = make_vulkan_table_builder("sliced", 0)->build(tf, 3.0);
  const PreintegrationTable cpu = SlicedBuilder().build(tf, 3.0);
  double max = 0;
  for (std::size_t i = 0; i < cpu.data().size(); ++i) max = std::max(max, std::abs(double(gpu.data()[i]) - cpu.data()[i]));
  EXPECT_LE(max, 1e-5);
  const DiscreteTf tf2(load_transfer_function(test::source_path("presets/bonsai.json")), 40);
  const SecondOrderTable g2 = make_vulkan_second_order_builder("fast")->build(tf2, 3.0, 8);
  const SecondOrderTable c2 = make_second_order_builder("fast")->build(tf2, 3.0, 8);
  max = 0;
  for (std::size_t i = 0; i < c2.bytes() / sizeof(float); ++i) max = std::max(max, std::abs(double(g2.data()[i]) - c2.data()[i]));
  EXPECT_LE(max, 1e-6);
  EXPECT_EQ(vulkan::VulkanDevice::validation_messages(), 0u);
}

}  // namespace
}  // namespace vri
