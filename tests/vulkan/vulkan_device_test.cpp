// The Vulkan device and the command line around it (issue 22, items 1 and 5):
// `vri devices`, `--backend vulkan` giving the CPU's PNG, VRI_VULKAN_DEVICE,
// `vri table --backend vulkan`, and a machine without a driver getting one
// clear line and no file.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include "cli/cli_support.hpp"
#include "vri/error.hpp"
#include "vulkan_device.hpp"

namespace vri::test {
namespace {

TEST(VulkanDevice, ListsAUsableDeviceAndSharesIt) {
  const auto devices = vulkan::VulkanDevice::list();
  ASSERT_FALSE(devices.empty()) << "the tests need a Vulkan device (mesa-vulkan-drivers gives lavapipe)";
  bool usable = false;
  for (const auto& d : devices) usable = usable || d.usable;
  EXPECT_TRUE(usable);
  const auto a = vulkan::VulkanDevice::shared(), b = vulkan::VulkanDevice::shared();
  EXPECT_EQ(a.get(), b.get());
  EXPECT_FALSE(a->info().name.empty());
  EXPECT_TRUE(a->validating()) << "the tests run with the validation layer (validation_on.cpp)";
  EXPECT_EQ(vulkan::VulkanDevice::validation_messages(), 0u);
}

// A discrete GPU without resizable BAR: 8 GiB of VRAM the host cannot map,
// a 256 MiB window it can, and host memory. Device-local buffers go to the
// 8 GiB heap (written through staging), not to the window.
TEST(VulkanDevice, DeviceLocalBuffersTakeTheLargestHeap) {
  VkPhysicalDeviceMemoryProperties m{};
  m.memoryHeapCount = 3;
  m.memoryHeaps[0] = {std::uint64_t{8} << 30, VK_MEMORY_HEAP_DEVICE_LOCAL_BIT};
  m.memoryHeaps[1] = {std::uint64_t{256} << 20, VK_MEMORY_HEAP_DEVICE_LOCAL_BIT};
  m.memoryHeaps[2] = {std::uint64_t{32} << 30, 0};
  const VkMemoryPropertyFlags local = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT,
                              host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  m.memoryTypeCount = 3;
  m.memoryTypes[0] = {host, 2};
  m.memoryTypes[1] = {local | host, 1};
  m.memoryTypes[2] = {local, 0};
  EXPECT_EQ(vulkan::choose_memory_type(m, 0b111, local, host), 2u);
  EXPECT_EQ(vulkan::choose_memory_type(m, 0b011, local, host), 1u);  // only the window allowed
  EXPECT_EQ(vulkan::choose_memory_type(m, 0b111, host, 0), 0u);      // staging
  // Unified memory (lavapipe, integrated GPUs): the one heap, mappable.
  m.memoryHeapCount = 1;
  m.memoryTypeCount = 1;
  m.memoryTypes[0] = {local | host, 0};
  EXPECT_EQ(vulkan::choose_memory_type(m, 0b1, local, host), 0u);
  EXPECT_THROW(vulkan::choose_memory_type(m, 0b10, local, host), Error);
}

// Issue 47: under GPU-assisted validation the shared device was destroyed
// from a static destructor after the layer had torn itself down: exit 139
// once the image was written. Now released by an atexit handler first.
TEST(VulkanCli, ExitsCleanlyUnderGpuAssistedValidation) {
  TempDir dir;
  const ProcessResult r = run("render " + source_path("scenes/neghip.json") + " --backend vulkan --method preint1 --width 24 "
                                  "--height 24 -q -o " + (dir / "v.png").string(),
                              dir,
                              "VRI_VULKAN_VALIDATION=1 "
                              "VK_LAYER_ENABLES=VK_VALIDATION_FEATURE_ENABLE_GPU_ASSISTED_EXT ");
  if (r.err.find("validation layer is missing") != std::string::npos) GTEST_SKIP() << r.err;
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "v.png"));
}

// Issue 47: the host set up every ray of the image before the first chunk ran
// (~88 bytes a pixel for riemann: 88 MiB at 1024^2, 1.87 GB at 4096^2), outside
// --max-memory. Now the GPU makes the rays from a camera block
// (camera_rays_test.cpp): a 1024^2 frame costs the image (twice: the render
// and the file), about 64 MiB over an 8^2 one on lavapipe, where it cost over 200.
TEST(VulkanCli, RaysAreSetUpAChunkAtATime) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "resident memory is the sanitizer's here";
#endif
  TempDir dir;
  const std::string render = "render " + source_path("scenes/neghip.json") + " --backend vulkan --method riemann -q";
  auto peak_kib = [] {
    rusage u{};
    getrusage(RUSAGE_CHILDREN, &u);
    return u.ru_maxrss;  // the largest child so far, KiB
  };
  ASSERT_EQ(run(render + " --width 8 --height 8 -o " + (dir / "small.npy").string(), dir).code, 0);
  const long small = peak_kib();
  const ProcessResult big =
      run(render + " --width 1024 --height 1024 --max-memory 96M -o " + (dir / "big.npy").string(), dir);
  ASSERT_EQ(big.code, 0) << big.err;
  EXPECT_LT(peak_kib() - small, 120 * 1024) << "KiB over an 8x8 frame";
}

TEST(VulkanCli, DevicesAndBackendFlag) {
  TempDir dir;
  const ProcessResult list = run("devices", dir);
  ASSERT_EQ(list.code, 0) << list.err;
  EXPECT_EQ(list.out.rfind("0: ", 0), 0u) << list.out;

  const std::string scene = source_path("scenes/engine.json");
  const std::string flags = " --method riemann --step 1.5 --width 40 --height 32 -q";
  const ProcessResult gpu =
      run("render " + scene + flags + " --backend vulkan -o " + (dir / "gpu.png").string(), dir,
          "VRI_VULKAN_VALIDATION=1 ");
  ASSERT_EQ(gpu.code, 0) << gpu.err;
  EXPECT_EQ(gpu.err.find("validation"), std::string::npos) << gpu.err;
  ASSERT_EQ(run("render " + scene + flags + " -o " + (dir / "cpu.png").string(), dir).code, 0);
  EXPECT_EQ(slurp(dir / "gpu.png"), slurp(dir / "cpu.png"));  // lavapipe: the same bytes

  const ProcessResult bad = run("render " + scene + flags + " --backend metal -o " + (dir / "x.png").string(), dir);
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.err.find("backend must be cpu or vulkan"), std::string::npos) << bad.err;
  const ProcessResult index =
      run("render " + scene + flags + " --backend vulkan -o " + (dir / "x.png").string(), dir, "VRI_VULKAN_DEVICE=7 ");
  EXPECT_EQ(index.code, 1);
  EXPECT_NE(index.err.find("VRI_VULKAN_DEVICE=7 names no device"), std::string::npos) << index.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
}

// `vri table --backend vulkan` (issue 22, item 3): the GPU's table, the
// builders it has, and one line and no file for the others.
TEST(VulkanCli, TableBackend) {
  TempDir dir;
  const std::string tf = " --tf " + source_path("presets/bonsai.json") + " --size 64";
  const ProcessResult gpu = run("table" + tf + " --backend vulkan -o " + (dir / "g.npy").string(), dir);
  ASSERT_EQ(gpu.code, 0) << gpu.err;
  EXPECT_NE(gpu.err.find("with 'incremental (vulkan)'"), std::string::npos) << gpu.err;  // the CPU's default too
  EXPECT_TRUE(std::filesystem::exists(dir / "g.npy"));
  const ProcessResult second = run("table" + tf + " --order 2 --backend vulkan -o " + (dir / "g2.npy").string(), dir);
  ASSERT_EQ(second.code, 0) << second.err;
  EXPECT_NE(second.err.find("64x64x64 table with 'fast (vulkan)'"), std::string::npos) << second.err;
  for (const char* bad : {" --builder brute --backend vulkan", " --accumulation 12bit --backend vulkan",
                          " --order 2 --builder plain --backend vulkan", " --backend metal"}) {
    const ProcessResult r = run("table" + tf + bad + " -o " + (dir / "x.npy").string(), dir);
    EXPECT_EQ(r.code, 1) << bad;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.npy")) << bad;
  }
}

TEST(VulkanCli, NoDriverIsOneLineAndNoFile) {
  TempDir dir;
  // (Validation off: with it the loader itself reports the missing file.)
  const std::string no_driver = "VRI_VULKAN_VALIDATION=0 VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json ";
  const ProcessResult list = run("devices", dir, no_driver);
  EXPECT_EQ(list.code, 1);
  EXPECT_NE(list.err.find("no Vulkan device found"), std::string::npos) << list.err;
  const ProcessResult r = run("render " + source_path("scenes/engine.json") +
                                  " --method riemann --width 8 --height 8 --backend vulkan -o " +
                                  (dir / "x.png").string(),
                              dir, no_driver);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("vri: error: vulkan: no Vulkan"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));
  // The CPU backend does not need Vulkan at all.
  EXPECT_EQ(run("render " + source_path("scenes/engine.json") + " --method riemann --width 8 --height 8 -q -o " +
                    (dir / "y.png").string(),
                dir, no_driver)
                .code,
            0);
}

}  // namespace
}  // namespace vri::test
