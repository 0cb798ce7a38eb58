#include "vulkan_preint.hpp"
#include "preint_push_constants.h"
#include "preint1.hpp"  // make_vulkan_preint

#include <bit>
#include <cstdint>

#include "methods/march/float_shading.hpp"
#include "methods/march/ray_steps.hpp"  // world_step
#include "pixel_kernel.hpp"
#include "methods/march/ray_setup.hpp"
#include "vri/error.hpp"
#include "methods/fast_path.hpp"
#include "preint2.hpp"  // second_order_builder_name
#include "tables/zero_opacity.hpp"
#include "tables/table_builder.hpp"

namespace vri::vulkan {

namespace {

const std::uint32_t kPreint1Spirv[] = {
#include "preint1.spv.inc"
};
const std::uint32_t kPreint2Spirv[] = {
#include "preint2.spv.inc"
};

// preint.comp's push constants.
struct Params {
  VRI_PREINT_PUSH_CONSTANTS
};
static_assert(sizeof(Params) <= 128, "lavapipe's push constants");

// The bindings of preint.comp: the volume, three tables, the gradients (four
// each), the camera block, the empty macro cells, the image, the rays' ends.
constexpr int kBindings = 5 * GpuArray::kParts + 4;

std::span<const std::byte> bytes_of(const float* data, std::size_t floats) {
  return std::as_bytes(std::span<const float>(data, floats));
}

}  // namespace

VulkanPreint::VulkanPreint(std::shared_ptr<const VulkanDevice> device, const Scene& scene)
    : VulkanGridRenderer(std::move(device), scene),
      steps_(scene.method.name == "preint2" ? 2 : 1),
      h_(detail::world_step(scene.grid(), scene.method.step, scene.method.name.c_str())),
      tf_(scene.transfer_function, scene.method.table_size,
          DataRange{scene.grid().min_value(), scene.grid().max_value()}),
      sampler_(scene.grid()) {
  const Lighting& lighting = scene.lighting;
  if (lighting.enabled && lighting.mode != "sampled" && lighting.mode != "interpolated")
    throw Error(scene.method.name + ": lighting mode must be sampled or interpolated, got '" + lighting.mode + "'");
  const bool interpolated = lighting.enabled && lighting.mode == "interpolated";
  // The tables as the CPU integrators build them (preint1.cpp, preint2.cpp).
  std::size_t floats = 0;
  if (steps_ == 1) {
    if (interpolated) {
      weighted1_.emplace(build_weighted_tables(tf_, h_));
      tables_ = {weighted1_->front.data().data(), weighted1_->back.data().data(), nullptr};
      floats = weighted1_->front.data().size();
      axis_.emplace(weighted1_->front.axis());
    } else {
      table1_.emplace(make_table_builder(scene.method.builder)->build(tf_, h_));
      tables_ = {table1_->data().data(), nullptr, nullptr};
      floats = table1_->data().size();
      axis_.emplace(table1_->axis());
    }
  } else {
    const auto make = make_second_order_builder(second_order_builder_name(scene.method.builder));
    if (interpolated) {
      weighted2_.emplace(make->build_weighted(tf_, 2 * h_, scene.method.iterations));
      tables_ = {weighted2_->full.data(), weighted2_->middle.data(), weighted2_->back.data()};
      floats = weighted2_->full.bytes() / sizeof(float);
      axis_.emplace(weighted2_->full.axis());
    } else {
      table2_.emplace(make->build(tf_, 2 * h_, scene.method.iterations));
      tables_ = {table2_->data(), nullptr, nullptr};
      floats = table2_->bytes() / sizeof(float);
      axis_.emplace(table2_->axis());
    }
  }
  const char* names[] = {"the pre-integration table", "a weighted table (lighting)", "a weighted table (lighting)"};
  for (int k = 0; k < 3; ++k)
    if (tables_[k]) on_device_[k].emplace(device_, bytes_of(tables_[k], floats), names[k]);
  lighting_.weighted = interpolated ? tables_ : std::array<const float*, 3>{};
  if (lighting.enabled) {
    float_shading_ = std::make_unique<detail::FloatShading>(lighting, *shader_, sampler_);
    lighting_.shading = float_shading_.get();
  }
  // The CPU's classification (preint1.cpp, preint2.cpp): what it would leap over.
  const Skipping skipping(scene.grid(), ZeroOpacity(tf_, steps_ == 2 ? TableOrder::Second : TableOrder::First),
                                  scene.method.fast, scene.method.name);
  empty_.emplace(device_, scene.grid(), skipping.space());
  kernel_.emplace(device_, steps_ == 1 ? std::span<const std::uint32_t>(kPreint1Spirv) : kPreint2Spirv, kBindings,
                  sizeof(Params), inputs().split_arrays());
}

Bindings VulkanPreint::inputs() const { return table_march_inputs(volume_, on_device_, shading_, *empty_); }

VulkanPreint::~VulkanPreint() = default;

Image VulkanPreint::render(const Camera& camera, const RenderOptions& options) const {
  throw_if_cancelled(options);
  const GridVolume& volume = scene_.grid();
  const RaySetup rays = [&](PixelSpan span) { return camera_block(camera, grid_box(volume, h_), span); };
  const HostFinish finish{9, [&](PixelSpan span, std::span<float> rgba, std::span<const float> tails) {
                            add_partial_slabs(camera, span, rgba, tails, options.threads);
                          }};
  Params p{grid_params(*device_, volume, volume_.type, scene_.method.fast.termination),
           {axis_->size(), axis_->lo(), axis_->scale()},
           shading_params(shading_, lighting_.interpolated() ? 2 : 1),
           empty_->params};
  return run_pixels(device_, *kernel_, camera.width(), camera.height(), inputs().list(), rays, p.grid, &p,
                    &finish);
}

void VulkanPreint::add_partial_slabs(const Camera& camera, PixelSpan span, std::span<float> rgba,
                                     std::span<const float> tails, int threads) const {
  const GridVolume& volume = scene_.grid();
  volume.visit([&](auto values) {
    for_each_pixel(camera, span, threads, [&](std::size_t i, int x, int y) {
      const std::span<const float> tail = tails.subspan(9 * i, 9);
      const auto full = std::bit_cast<std::int32_t>(tail[0]);
      if (full < 0) return;  // a miss, or T fell below the termination threshold
      const Ray ray = camera.ray(x, y);
      const auto iv = volume.clip(ray);
      if (!iv) return;  // a graze the kernel's double-float took for a hit
      const Vec3 u0 = sampler_.grid(ray.at(iv->t0)), du = sampler_.grid_step(ray.dir * h_);
      const detail::FloatSample front =
          detail::sample_at(sampler_, values.data(), lighting_, detail::direction(ray),
                            u0 + static_cast<double>(static_cast<long long>(full) * steps_) * du);
      // The kernel's double-float sums, as the CPU's double ones.
      const auto sum = [&](int k) { return double(tail[1 + 2 * k]) + double(tail[2 + 2 * k]); };
      detail::FrontToBack acc;
      acc.T = sum(0);
      for (int c = 0; c < 3; ++c) acc.C[c] = sum(1 + c);
      const auto add = [&](const auto& slabs) {
        for (const SlabRgba& v : slabs) acc.add(v.r, v.g, v.b, v.a);
      };
      if (steps_ == 1)
        add(detail::last_slabs<1>(sampler_, values.data(), tf_, lighting_, ray, *iv, full, h_, front));
      else
        add(detail::last_slabs<2>(sampler_, values.data(), tf_, lighting_, ray, *iv, full, h_, front));
      const Rgba out = acc.result();
      for (int c = 0; c < 4; ++c) rgba[4 * i + c] = static_cast<float>(out[c]);
    });
  });
}

}  // namespace vri::vulkan

namespace vri {

std::unique_ptr<GpuSceneRenderer> make_vulkan_preint(const Scene& scene) {
  return std::make_unique<vulkan::VulkanPreint>(vulkan::VulkanDevice::shared(), scene);
}

}  // namespace vri
