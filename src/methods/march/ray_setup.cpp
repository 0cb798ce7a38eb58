#include "ray_setup.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <string>

#include "vri/error.hpp"

#include "methods/riemann/float_riemann.hpp"  // jitter_fraction

namespace vri::vulkan {

namespace {

// The block's slots and words (camera_block.h, shared with camera_rays.glsl).
enum Slot {
  kEye = VRI_CAM_EYE, kU = VRI_CAM_U, kV = VRI_CAM_V, kW = VRI_CAM_W, kAspect = VRI_CAM_ASPECT,
  kHalfH = VRI_CAM_HALF_H, kBoxLo = VRI_CAM_BOX_LO, kBoxHi = VRI_CAM_BOX_HI, kOrigin = VRI_CAM_ORIGIN,
  kInverse = VRI_CAM_INVERSE, kStep = VRI_CAM_STEP, kScale = VRI_CAM_SCALE, kPlane0 = VRI_CAM_PLANE0
};
enum Word { kWidth = VRI_CAM_WIDTH, kHeight = VRI_CAM_HEIGHT, kFirst = VRI_CAM_FIRST, kOrtho = VRI_CAM_ORTHO,
            kExtras = VRI_CAM_EXTRAS, kPlanes = VRI_CAM_PLANES, kKernelCuts = VRI_CAM_KERNEL_CUTS };
constexpr std::size_t kMaxClipPlanes = VRI_CAM_MAX_PLANES;

// x as the double-float hi + lo at out[0], out[1].
void put(float* out, double x) {
  const float hi = static_cast<float>(x);
  out[0] = hi;
  out[1] = static_cast<float>(x - static_cast<double>(hi));
}
void put(std::vector<float>& block, int slot, double x) { put(block.data() + 2 * slot, x); }
void put(std::vector<float>& block, int slot, Vec3 v) {
  for (int a = 0; a < 3; ++a) put(block, slot + a, v[a]);
}
void put_word(std::vector<float>& block, int at, std::uint32_t w) { block[at] = std::bit_cast<float>(w); }

}  // namespace

RayBox grid_box(const GridVolume& volume, double step) {
  const Vec3 s = volume.spacing();
  RayBox box{volume.box_lo(), volume.box_hi(), volume.origin(), {1 / s.x, 1 / s.y, 1 / s.z}, step, {}, false, false};
  const ClipRegion& clip = volume.clip_region();
  box.planes = clip.planes;
  // The boxes' intersection: clip_to_box on it is the max and min of the
  // two boxes' crossings (GridVolume::clip), the same values.
  if (clip.box)
    for (int a = 0; a < 3; ++a) {
      box.lo[a] = std::max(box.lo[a], clip.box->lo[a]);
      box.hi[a] = std::min(box.hi[a], clip.box->hi[a]);
      box.none = box.none || box.lo[a] > box.hi[a];
    }
  if (box.none) box.lo = box.hi = volume.box_lo();  // a frame of the volume's, nothing kept
  return box;
}

RayBox mesh_box(const TetMesh& mesh, Vec3 centre) {
  const Vec3 pad = (mesh.box_hi() - mesh.box_lo()) * 1e-3;
  RayBox box{mesh.box_lo() - pad, mesh.box_hi() + pad, centre, {1, 1, 1}, 0, mesh.clip_region().planes, false, true};
  if (const auto& crop = mesh.clip_region().box)
    for (int a = 0; a < 3; ++a) {
      Vec3 n{0, 0, 0};
      n[a] = 1;
      box.planes.push_back({n, -crop->lo[a]});       // p >= lo
      box.planes.push_back({-1 * n, crop->hi[a]});   // p <= hi
    }
  return box;
}

std::vector<float> camera_block(const Camera& camera, const RayBox& box, PixelSpan span, int extras) {
  std::vector<float> block(kCameraFloats + span.count * static_cast<std::size_t>(extras), 0.0f);
  // The frame: the box's centre at 0, its largest side scaled by a power of
  // two (exact: ratios and grid coordinates stay the CPU's) to [1, 2).
  const Vec3 centre = (box.lo + box.hi) * 0.5, size = box.hi - box.lo;
  const double largest = std::max({size.x, size.y, size.z});
  const double scale = largest > 0 && std::isfinite(largest) ? std::ldexp(1.0, -std::ilogb(largest)) : 1.0;
  const auto frame = [&](Vec3 p) { return (p - centre) * scale; };
  const CameraSpec& spec = camera.spec();
  const Camera::Frame f = camera.frame();
  const bool ortho = spec.projection == Projection::Orthographic;
  put(block, kEye, frame(spec.eye));
  put(block, kU, f.u);
  put(block, kV, f.v);
  put(block, kW, f.w);
  put(block, kAspect, f.aspect);
  put(block, kHalfH, ortho ? f.half_h * scale : f.half_h);  // world units when orthographic
  put(block, kBoxLo, frame(box.lo));
  put(block, kBoxHi, frame(box.hi));
  put(block, kOrigin, frame(box.origin));
  put(block, kInverse, box.inverse * (1 / scale));
  put(block, kStep, box.step * scale);
  put(block, kScale, scale);
  put_word(block, kWidth, static_cast<std::uint32_t>(camera.width()));
  put_word(block, kHeight, static_cast<std::uint32_t>(camera.height()));
  put_word(block, kFirst, static_cast<std::uint32_t>(span.first));
  put_word(block, kOrtho, ortho ? 1 : 0);
  put_word(block, kExtras, static_cast<std::uint32_t>(extras));
  // The clip planes in the frame: n . p + d >= 0 with p = q / scale + centre
  // for q in the frame is n . q + scale (n . centre + d) >= 0, n made unit.
  if (box.planes.size() > kMaxClipPlanes)
    throw Error("--backend vulkan: at most " + std::to_string(kMaxClipPlanes) + " clip planes on the GPU, not " +
                std::to_string(box.planes.size()));
  put_word(block, kPlanes, box.none ? 0xffffffffu : static_cast<std::uint32_t>(box.planes.size()));
  put_word(block, kKernelCuts, box.kernel_cuts ? 1 : 0);
  for (std::size_t i = 0; i < box.planes.size(); ++i) {
    const ClipPlane& p = box.planes[i];
    const double n = length(p.normal);
    const int at = kPlane0 + 4 * static_cast<int>(i);
    put(block, at, p.normal * (1 / n));
    put(block, at + 3, scale * (dot(p.normal, centre) + p.d) / n);
  }
  return block;
}

void for_each_pixel(const Camera& camera, PixelSpan span, int threads,
                    const std::function<void(std::size_t, int, int)>& f) {
  const auto width = static_cast<std::size_t>(camera.width());
  tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);  // as render() does
  arena.execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, span.count, 256), [&](const tbb::blocked_range<std::size_t>& r) {
      for (std::size_t i = r.begin(); i < r.end(); ++i) {
        const std::size_t p = span.first + i;
        f(i, static_cast<int>(p % width), static_cast<int>(p / width));
      }
    });
  });
}

std::vector<float> riemann_block(const Camera& camera, const GridVolume& volume, double h,
                                 std::optional<std::uint64_t> jitter, PixelSpan span, int threads) {
  std::vector<float> block = camera_block(camera, grid_box(volume, h), span, jitter ? 2 : 0);
  if (!jitter) return block;
  for_each_pixel(camera, span, threads, [&](std::size_t i, int x, int y) {
    put(block.data() + kCameraFloats + 2 * i, detail::jitter_fraction(camera.ray(x, y), *jitter));
  });
  return block;
}

}  // namespace vri::vulkan
