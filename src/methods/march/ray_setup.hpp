#pragma once
// The rays of a GPU march, set up on the host in double exactly as the CPU
// float paths set them up (clip to the box, sample count, the partial last
// step, the jitter's fraction), so the GPU and the CPU take their samples at
// the same places and differ only by float roundings per sample. Positions
// travel as double-float pairs (vulkan/shaders/double_float.glsl). Each call
// sets up one span of pixels (run_pixels' chunk): the whole image's rays,
// ~100 bytes a pixel, were 1.87 GB at 4096^2 and outside --max-memory (issue 47).
#include <cstdint>
#include <optional>
#include <vector>

#include "pixel_kernel.hpp"  // PixelSpan
#include "vri/camera.hpp"
#include "methods/preint/float_march.hpp"  // FloatLighting, last_slabs
#include "vri/volume.hpp"
#include "tables/discrete_tf.hpp"

namespace vri::vulkan {

// riemann's ray, 21 floats (src/methods/riemann/riemann.comp): u0 hi x3, lo x3;
// du hi x3, lo x3; o hi, lo; o of the last step hi, lo; h_k of the last
// step; the number of samples (int bits); the direction in float.
inline constexpr int kRiemannRayFloats = 21;

// The riemann rays of `pixels`, for step h (world units); threads as
// RenderOptions (0: every core).
std::vector<float> riemann_rays(const Camera& camera, const GridVolume& volume, double h,
                                std::optional<std::uint64_t> jitter, PixelSpan pixels, int threads);

// A ray by its entry into the box, 17 floats (adaptive.comp,
// preint2_dual.comp): u0 hi x3, lo x3 (the entry, grid units); du hi x3, lo
// x3 (grid units per world unit along the ray); the length inside the box,
// hi and lo (-1: the ray misses it); the direction in float.
inline constexpr int kEntryRayFloats = 17;

std::vector<float> entry_rays(const Camera& camera, const GridVolume& volume, PixelSpan pixels, int threads);

// The ray of preint1 (steps 1) or preint2 (steps 2), slab_ray_floats(steps)
// floats (src/methods/preint/preint.comp): u0 hi x3, lo x3; du hi x3, lo x3; the
// number of whole slabs (int bits; -1: the ray misses the volume); the
// partial last slab's `steps` sub-slabs, each (r, g, b, alpha), integrated
// exactly and lit as on the CPU (last_slabs, src/methods/preint/float_march.hpp),
// hi x 4 steps, then lo x 4 steps (the CPU composites them in double); the
// direction in float.
constexpr int slab_ray_floats(int steps) { return 16 + 8 * steps; }

std::vector<float> slab_rays(int steps, const Camera& camera, const GridVolume& volume, const DiscreteTf& tf,
                             const detail::FloatLighting& lighting, double h, PixelSpan pixels, int threads);

// A ray through a tetrahedral mesh, 7 floats (tet_raycast.comp): the
// origin less `centre` (where the ray enters the mesh's box, widened by
// 1e-3 of its diagonal, or the eye when inside it), the unit direction, and
// 1 (-1: the ray misses the box). Distances along it are the CPU's from
// that origin on.
inline constexpr int kMeshRayFloats = 7;

std::vector<float> mesh_rays(const Camera& camera, const TetMesh& mesh, Vec3 centre, PixelSpan pixels, int threads);

}  // namespace vri::vulkan
