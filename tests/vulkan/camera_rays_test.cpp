// The GPU makes each pixel's ray from the camera (vulkan/shaders/camera_rays.glsl,
// src/methods/march/ray_setup.hpp; issue 47, item 16): a frame uploads the
// camera block - 512 bytes a chunk of pixels, plus riemann's jitter
// fractions - not ~100 bytes a pixel; and the rays it makes in double-float
// sample where the CPU's double rays do, far from the world's origin (the
// block's frame), from inside the volume, orthographic, through a mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "camera_block.h"  // VRI_CAMERA_FLOATS
#include "gpu_against_cpu.hpp"
#include "gpu_buffer.hpp"
#include "mesh/mesh_test_support.hpp"
#include "test_support.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "vulkan_device.hpp"

namespace vri {
namespace {

using test::gpu_against_cpu;

// A Marschner-Lobb grid of 24^3 at origin `origin`, anisotropic spacing, a
// transfer function with a steep ramp; the camera 40 units off its centre.
Scene far_scene(const std::string& origin, const char* method) {
  Scene scene = parse_scene(R"({"volume": {"builtin": "marschner_lobb", "dims": [24, 24, 24],
      "origin": )" + origin + R"(, "spacing": [0.5, 0.25, 1]},
    "transfer_function": {"points": [[0, 0, 0, 0, 0], [0.4, 0.2, 0.5, 1, 0.1], [0.55, 1, 0.8, 0.2, 0.8],
                                     [0.56, 1, 0.2, 0.1, 3], [1, 1, 1, 1, 0.4]]},
    "camera": {"eye": [0, 0, 1], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y": 35, "width": 40, "height": 32},
    "method": {"name": "riemann", "step": 0.3}})",
                            test::source_path("scenes"));
  const Vec3 centre = (scene.grid().box_lo() + scene.grid().box_hi()) * 0.5;
  scene.camera.target = centre;
  scene.camera.eye = centre + Vec3{28, -17, 23};
  scene.camera.up = {0, 0, 1};
  scene.method.name = method;
  return scene;
}

bool lavapipe() { return vulkan::VulkanDevice::shared()->info().name.rfind("llvmpipe", 0) == 0; }

// What rendering `scene` on the GPU uploads, once its renderer is made.
std::uint64_t frame_upload(const Scene& scene) {
  const SceneRenderer renderer(scene, Backend::Vulkan);
  const std::uint64_t before = vulkan::GpuBuffer::uploaded_bytes();
  (void)renderer.render({.threads = 2});
  return vulkan::GpuBuffer::uploaded_bytes() - before;
}

// The camera block's bytes (camera_block.h): 128 floats, the clip planes' room included.
constexpr std::uint64_t kBlockBytes = 4 * VRI_CAMERA_FLOATS;
static_assert(kBlockBytes == 512);

TEST(CameraRays, AFrameUploadsTheCameraBlockNotItsRays) {
  Scene scene = far_scene("[0, 0, 0]", "riemann");
  scene.camera.width = 520;
  scene.camera.height = 510;  // 265,200 pixels: two chunks of at most 2^18
  scene.method.step = 0.8;
  scene.method.tolerance = 1e-3;  // adaptive's
  for (const char* method : {"riemann", "preint1", "preint2", "preint2-dual", "adaptive"}) {
    scene.method.name = method;
    EXPECT_EQ(frame_upload(scene), 2u * kBlockBytes) << method;
  }
  scene.method.name = "riemann";
  scene.method.jitter = 7;  // a fraction (hi, lo) a pixel: a hash of the CPU's double ray
  EXPECT_EQ(frame_upload(scene), 2u * kBlockBytes + 8u * 265200u);
  EXPECT_EQ(vulkan::VulkanDevice::validation_messages(), 0u);
}

TEST(CameraRays, FarFromTheOriginTheGpuSamplesWhereTheCpuDoes) {
  for (const std::string origin : {"[0, 0, 0]", "[1e6, -2e6, 3.3e5]", "[-7.25e7, 1e-3, 5e4]"}) {
    for (const char* method : {"riemann", "preint1", "preint2", "preint2-dual"}) {
      Scene scene = far_scene(origin, method);
      scene.method.table_size = 64;
      scene.method.table_size_given = true;
      const test::Difference d = gpu_against_cpu(scene);
      EXPECT_LE(d.max, 1e-4) << origin << " " << method;
      // On lavapipe (IEEE float, no contraction) riemann and preint agree to
      // the byte near the origin: the rays made in double-float sample where
      // the double ones do, and preint's partial slab goes on from the
      // kernel's double-float sums. Far from it the CPU's world positions
      // round at 1e-10 and the GPU's frame elsewhere: a sample's last bit.
      const bool same_bytes = lavapipe() && origin == "[0, 0, 0]" && std::string(method) != "preint2-dual";
      if (same_bytes) EXPECT_EQ(d.differing, 0u) << method;
      else EXPECT_LE(d.max, 1e-6) << origin << " " << method;
    }
    Scene jittered = far_scene(origin, "riemann");
    jittered.method.jitter = 99;
    EXPECT_LE(gpu_against_cpu(jittered).max, 1e-4) << origin << " jitter";
  }
  EXPECT_EQ(vulkan::VulkanDevice::validation_messages(), 0u);
}

// An orthographic camera whose eye is inside the volume (rays start at t = 0),
// looking down a diagonal; and a perspective one inside it.
TEST(CameraRays, FromInsideTheVolumeAndOrthographic) {
  for (const bool ortho : {true, false}) {
    for (const char* method : {"riemann", "preint1", "preint2", "preint2-dual"}) {
      Scene scene = far_scene("[1e5, 1e5, 1e5]", method);
      const Vec3 centre = scene.camera.target;
      scene.camera.eye = centre + Vec3{1.5, 0.5, 2};
      scene.camera.target = centre + Vec3{-3, -1, -4};
      if (ortho) {
        scene.camera.projection = Projection::Orthographic;
        scene.camera.ortho_height = 6;
      }
      scene.method.table_size = 64;
      scene.method.table_size_given = true;
      EXPECT_LE(gpu_against_cpu(scene).max, 1e-4) << ortho << " " << method;
    }
  }
  EXPECT_EQ(vulkan::VulkanDevice::validation_messages(), 0u);
}

// A mesh 1e6 from the origin: its rays from the camera block, less its centre.
TEST(CameraRays, AMeshFarFromTheOrigin) {
  const auto wave = [](double x, double y, double z) { return 0.5 + 0.4 * std::sin(0.9 * x + 0.5 * y) * std::cos(0.7 * z); };
  const TetMesh near = test::carved_mesh(5, wave, [](double, double, double) { return true; });
  const Vec3 offset{1e6, -3e5, 2e6};
  std::vector<Vec3> points = near.points();
  for (Vec3& p : points) p = p + offset;
  Scene scene{TetMesh(std::move(points), near.tets(), near.scalars()), TransferFunction({{0, 0, 0, 1, 0}, {0.3, 0, 1, 0, 0.2}, {0.6, 1, 1, 0, 1.2}, {1, 1, 0, 0, 0.4}}),
              {}, {}, {0, 0, 0}, {}};
  scene.method.name = "tet-raycast";
  scene.method.table_size = 64;
  scene.method.length_samples = 16;
  scene.camera.width = 40;
  scene.camera.height = 32;
  scene.camera.eye = offset + Vec3{13, -8, 10};
  scene.camera.target = offset + Vec3{2.5, 2.5, 2.5};
  EXPECT_LE(gpu_against_cpu(scene).max, 1e-4);
  EXPECT_EQ(frame_upload(scene), kBlockBytes);
  EXPECT_EQ(vulkan::VulkanDevice::validation_messages(), 0u);
}

}  // namespace
}  // namespace vri
