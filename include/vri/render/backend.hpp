#pragma once
// Backends (SPEC §11: `--backend cpu|vulkan`): where a scene is rendered. The
// CPU backend is the library itself; the Vulkan backend (vulkan/: GLSL
// compute shaders, the loader opened at run time) renders the same
// integrals on any Vulkan device, Mesa's CPU implementation lavapipe
// included: riemann and the preint methods within 1e-4 per channel of the
// CPU float path, adaptive within its tolerance of `exact` on a stated share of
// pixels (docs/GPU.md).
#include <memory>
#include <string>
#include <vector>

#include "vri/camera/camera.hpp"
#include "vri/image.hpp"
#include "vri/render/renderer.hpp"

namespace vri {

struct Scene;
class TableBuilder;        // tables/table_builder.hpp
class SecondOrderBuilder;  // tables/second_order_table.hpp

enum class Backend { Cpu, Vulkan };

// "cpu" or "vulkan"; vri::Error naming both otherwise.
Backend parse_backend(const std::string& name);
std::string backend_name(Backend backend);

// Whether this build has the Vulkan backend (VRI_VULKAN, on when glslc and
// the Vulkan headers were found).
bool vulkan_backend_built();

// One scene made ready on a GPU: its volume, transfer function and tables on
// the device. SceneRenderer holds one for Backend::Vulkan.
class GpuSceneRenderer {
 public:
  virtual ~GpuSceneRenderer() = default;
  virtual Image render(const Camera& camera, const RenderOptions& options) const = 0;
  // "vulkan: llvmpipe (LLVM 15.0.6, 256 bits)"
  virtual std::string device_name() const = 0;
};

// vri::Error with one line when this build has no Vulkan backend, no device
// is usable, or the scene's method or options are not on the GPU yet.
std::unique_ptr<GpuSceneRenderer> make_vulkan_scene_renderer(const Scene& scene);

// Pre-integration tables built on the Vulkan device (issue 22, item 3;
// docs/GPU.md, "Tables"): order 1 by `sliced` (Roettger & Ertl 2002,
// SlicedBuilder's with float32 accumulation; steps 0: 2N) or `incremental`
// (Lum, Wilson & Ma 2004), order 2 by `fast` (El Hajjar et al. 2008,
// FastSecondOrderBuilder's). vri::Error with one
// line for another builder, or as make_vulkan_scene_renderer.
std::unique_ptr<TableBuilder> make_vulkan_table_builder(const std::string& builder, int steps);
std::unique_ptr<SecondOrderBuilder> make_vulkan_second_order_builder(const std::string& builder);

// `vri devices`: each Vulkan device, one line ("0: llvmpipe (LLVM 15.0.6,
// 256 bits), CPU, Vulkan 1.3.230"); an empty list when there are none.
// vri::Error when the build or the machine has no Vulkan loader.
std::vector<std::string> list_vulkan_devices();

}  // namespace vri
