#include "vulkan_preint2_dual.hpp"

#include "preint2_dual_push_constants.h"
#include <cstdint>
#include <span>

#include "pixel_kernel.hpp"
#include "methods/march/ray_setup.hpp"
#include "vri/error.hpp"
#include "methods/fast_path.hpp"
#include "methods/preint/preint2.hpp"  // second_order_builder_name
#include "preint2_dual.hpp"
#include "tables/second_order_weighted.hpp"
#include "tables/zero_opacity.hpp"

namespace vri::vulkan {

namespace {

const std::uint32_t kSpirv[] = {
#include "preint2_dual.spv.inc"
};

// preint2_dual.comp's push constants.
struct Params {
  VRI_PREINT2_DUAL_PUSH_CONSTANTS
};
static_assert(sizeof(Params) <= 128, "lavapipe's push constants");

// The bindings: the volume, three tables, the gradients (four each), the rays, the empty macro cells, the image.
constexpr int kBindings = 5 * GpuArray::kParts + 3;

// A length table on the device, its slices one after another.
GpuArray on_device(const std::shared_ptr<const VulkanDevice>& device, const SecondOrderLengthTable& t,
                   const char* what) {
  GpuArray array(device, t.bytes(), what);
  std::size_t offset = 0;
  for (const SecondOrderTable& slice : t.slices()) {
    array.upload(std::as_bytes(std::span<const float>(slice.data(), slice.bytes() / sizeof(float))), offset);
    offset += slice.bytes();
  }
  return array;
}

}  // namespace

VulkanPreint2Dual::VulkanPreint2Dual(std::shared_ptr<const VulkanDevice> device, const Scene& scene)
    : VulkanGridRenderer(std::move(device), scene),
      tf_(scene.transfer_function,
          scene.method.table_size_given ? scene.method.table_size : Preint2DualIntegrator::kDefaultTableSize,
          DataRange{scene.grid().min_value(), scene.grid().max_value()}),
      axis_(tf_.axis()),
      max_length_(Preint2DualIntegrator::max_slab_length(scene.grid())),
      lengths_(Preint2DualIntegrator::kLengths) {
  const Lighting& lighting = scene.lighting;
  if (lighting.enabled && lighting.mode != "sampled" && lighting.mode != "interpolated")
    throw Error("preint2-dual: lighting mode must be sampled or interpolated, got '" + lighting.mode + "'");
  mode_ = !lighting.enabled ? 0 : lighting.mode == "sampled" ? 1 : 2;
  // The tables as Preint2DualIntegrator builds them.
  const auto make = make_second_order_builder(second_order_builder_name(scene.method.builder));
  if (mode_ == 2) {
    const SecondOrderWeightedLengthTables w =
        build_second_order_weighted_length_tables(*make, tf_, lengths_, max_length_, scene.method.iterations);
    tables_[0].emplace(on_device(device_, w.full, "the pre-integration table"));
    tables_[1].emplace(on_device(device_, w.middle, "a weighted table (lighting)"));
    tables_[2].emplace(on_device(device_, w.back, "a weighted table (lighting)"));
  } else {
    tables_[0].emplace(on_device(
        device_, build_second_order_length_table(*make, tf_, lengths_, max_length_, scene.method.iterations),
        "the pre-integration table"));
  }
  const Skipping skipping(scene.grid(), ZeroOpacity(tf_, TableOrder::Second), scene.method.fast,
                                  "preint2-dual");
  empty_.emplace(device_, scene.grid(), skipping.space());
  kernel_.emplace(device_, kSpirv, kBindings, sizeof(Params), inputs().split_arrays());
}

Bindings VulkanPreint2Dual::inputs() const { return table_march_inputs(volume_, tables_, shading_, *empty_); }

Image VulkanPreint2Dual::render(const Camera& camera, const RenderOptions& options) const {
  throw_if_cancelled(options);
  const GridVolume& volume = scene_.grid();
  const RaySetup rays = [&](PixelSpan span) { return camera_block(camera, grid_box(volume, 0), span); };
  const FloatAxis axis(axis_);
  Params p{grid_params(*device_, volume, volume_.type, scene_.method.fast.termination),
           {axis.size(), axis.lo(), axis.scale()},
           shading_params(shading_, mode_),
           static_cast<float>(max_length_),
           lengths_,
           empty_->params};
  return run_pixels(device_, *kernel_, camera.width(), camera.height(), inputs().list(), rays,
                    p.grid, &p);
}

}  // namespace vri::vulkan

namespace vri {

std::unique_ptr<GpuSceneRenderer> make_vulkan_preint2_dual(const Scene& scene) {
  return std::make_unique<vulkan::VulkanPreint2Dual>(vulkan::VulkanDevice::shared(), scene);
}

}  // namespace vri
