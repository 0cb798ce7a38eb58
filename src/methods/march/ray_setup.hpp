#pragma once
// What a GPU march's rays are made from: the camera block that
// vulkan/shaders/camera_rays.glsl reads to make each pixel's ray on the GPU
// as the CPU float paths make it (Camera::ray, clip_to_box, the grid entry,
// in double-float), so a frame uploads a few hundred bytes, not a ray per
// pixel (~100 B a pixel, 1.87 GB at 4096^2 when the host set every ray up,
// issue 47). Riemann's jitter fractions are the one per-pixel input (a hash
// of the ray in double, jitter_fraction): two floats a pixel, with --jitter only.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "camera_block.h"  // vulkan/shaders/: its layout, shared with the kernels
#include "pixel_kernel.hpp"  // PixelSpan
#include "vri/camera.hpp"
#include "vri/volume.hpp"

namespace vri::vulkan {

// The block's floats (vulkan/shaders/camera_block.h); a pixel's extras follow it.
inline constexpr int kCameraFloats = VRI_CAMERA_FLOATS;

// The box the rays are clipped to, and the grid they are marched through.
struct RayBox {
  Vec3 lo, hi;
  Vec3 origin;   // the grid's origin (a mesh: the centre its positions are taken from)
  Vec3 inverse;  // grid units per world unit (a mesh: unused)
  double step = 0;  // the march's step, world units (0: none)
  // The volume's clip (SPEC §12): a grid's crop box is in lo, hi, a mesh's
  // among its planes; `none` where the crop box misses the grid's box;
  // `kernel_cuts`: the kernel cuts at the planes itself (clip_window), as a
  // mesh walk that starts at the box must.
  std::vector<ClipPlane> planes;
  bool none = false, kernel_cuts = false;
};

// The grid's box cut by its clip region's box, with the region's planes.
RayBox grid_box(const GridVolume& volume, double step);
// The mesh's box widened by 1e-3 of its diagonal on each side, as the CPU's
// mesh walk, and its clip as planes (the crop box's six faces after them).
RayBox mesh_box(const TetMesh& mesh, Vec3 centre);

// The camera block for the pixels of `span`, `extras` floats a pixel
// reserved after it (zeros).
std::vector<float> camera_block(const Camera& camera, const RayBox& box, PixelSpan span, int extras = 0);

// f(i, x, y) for each pixel i of `span` (pixel (x, y) of the image) on
// `threads` threads (0: every core), as render() runs its pixels.
void for_each_pixel(const Camera& camera, PixelSpan span, int threads,
                    const std::function<void(std::size_t, int, int)>& f);

// riemann's block: with a jitter seed, each pixel's fraction (hi, lo) after
// it; threads as RenderOptions (0: every core).
std::vector<float> riemann_block(const Camera& camera, const GridVolume& volume, double h,
                                 std::optional<std::uint64_t> jitter, PixelSpan span, int threads);

}  // namespace vri::vulkan
