#pragma once
// vri/render.hpp: rendering an image: renderers, backends, cancellation, the checks made before a render, SceneRenderer, and comparing images.

#include <array>
#include <span>
#include <vector>
#include <atomic>
#include <functional>
#include <tbb/task_group.h>
#include <mutex>
#include <memory>
#include <string>
#include <cstddef>
#include <optional>

#include "vri/camera.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"
#include "vri/image.hpp"
#include "vri/transfer_function.hpp"
#include "vri/scene.hpp"

// ---- image_compare ---------------------------------------------------------
// Per-channel differences between two images (SPEC §10 `vri compare`).

namespace vri {

struct ChannelDifference {
  double share_over = 0;  // share of pixels with |a - b| > tolerance, in [0, 1]
  double rms = 0;
  double max = 0;         // NaN when any difference is NaN (it stays: issue 46)
  std::size_t nan = 0;    // pixels whose difference is NaN (either image NaN there)
};

// a and b hold `channels` interleaved values per pixel; sizes must match.
std::vector<ChannelDifference> compare_images(std::span<const float> a, std::span<const float> b,
                                              int channels, double tolerance);

}  // namespace vri

// ---- renderer --------------------------------------------------------------
// The renderer: one ray per pixel through the camera, integrated by any
// Integrator, in square tiles spread over threads. Each pixel depends only on
// its own ray, so the image is the same bytes for any thread count.

namespace vri {

struct RenderOptions {
  int threads = 0;     // 0: every core
  int tile_size = 16;  // pixels a side
  // Set by another thread to stop the render between tiles (the viewer drops
  // a frame the user will no longer see); render() then throws RenderCancelled.
  const std::atomic<bool>* cancel = nullptr;
  // Called with the share of tiles done (0 .. 1), from whichever render thread
  // finished a tile, at most once per whole percent: keep it cheap and thread-safe.
  std::function<void(double)> progress = {};
};

// A render whose RenderOptions::cancel was set throws RenderCancelled (vri/error.hpp): no image.

// Throws RenderCancelled if options.cancel is set (for renderers of their own, between tiles).
void throw_if_cancelled(const RenderOptions& options);

Image render(const Camera& camera, const Integrator& integrator, const RenderOptions& options = {});

}  // namespace vri

// ---- cancellation ----------------------------------------------------------
// Cancellation: work another thread may stop - a render between its tiles
// (flag(), for RenderOptions::cancel) and a table build between its rows
// (the TBB group run() puts it in: its parallel loops stop taking work, and
// the builders check tbb::is_current_task_group_canceling() per row). The
// viewer cancels a page's work when a newer request or its close comes;
// Python cancels a render on Ctrl-C.

namespace vri {

class Cancellation {
 public:
  // From any thread: what runs stops soon, and what starts after does not run.
  void cancel() {
    std::lock_guard lock(mutex_);
    flag_ = true;
    if (group_) group_->cancel_group_execution();
  }
  // Before the next work, on the thread that runs it (ordered with cancel()
  // by the caller: the viewer takes its next request and resets under one lock).
  void reset() { flag_ = false; }
  bool cancelled() const { return flag_; }
  const std::atomic<bool>* flag() const { return &flag_; }

  // Runs f() in a TBB group that cancel() stops; throws RenderCancelled when it
  // was cancelled (what f left half built is the caller's to throw away, as
  // the exception unwinds it), else returns as f did.
  template <class F>
  void run(F&& f) {
    tbb::task_group_context context;
    {
      std::lock_guard lock(mutex_);
      if (flag_) throw RenderCancelled();
      group_ = &context;
    }
    tbb::task_group group(context);
    tbb::task_group_status status;
    try {
      status = group.run_and_wait([&] {
        // Off before the group resets its context: no cancel() reaches it after.
        struct Leave {
          Cancellation& c;
          ~Leave() {
            std::lock_guard lock(c.mutex_);
            c.group_ = nullptr;
          }
        } leave{*this};
        f();
      });
    } catch (...) {
      if (flag_) throw RenderCancelled();  // a failure of the cancelled work's leftovers
      throw;
    }
    if (status == tbb::task_group_status::canceled || flag_) throw RenderCancelled();
  }

 private:
  std::mutex mutex_;
  std::atomic<bool> flag_{false};
  tbb::task_group_context* group_ = nullptr;
};

}  // namespace vri

// ---- backend ---------------------------------------------------------------
// Backends (SPEC §11: `--backend cpu|vulkan`): where a scene is rendered. The
// CPU backend is the library itself; the Vulkan backend (vulkan/: GLSL
// compute shaders, the loader opened at run time) renders the same
// integrals on any Vulkan device, Mesa's CPU implementation lavapipe
// included: riemann and the preint methods within 1e-4 per channel of the
// CPU float path, adaptive within its tolerance of `exact` on a stated share of
// pixels (docs/GPU.md).

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

// One scene made ready for a method that projects whole cells (pt,
// pt-cylindrical; MethodInfo::make_projected): its tables built.
class ProjectedSceneRenderer {
 public:
  virtual ~ProjectedSceneRenderer() = default;
  virtual Image render(const Camera& camera, const RenderOptions& options) const = 0;
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

// ---- table_request ---------------------------------------------------------
// TableRequest: one pre-integration table as `vri table` (SPEC §10) and the
// Python vri.table ask for it, built by one function so both give the same
// bytes and the same refusals.
//   order 1, one length:   shape (N, N, 4)     indexed [s_f, s_b]
//   order 1, M lengths:    shape (M, N, N, 4)  indexed [l, s_f, s_b], l = LMAX m / (M - 1)
//   order 2:               shape (N, N, N, 4)  indexed [s_f, s_m, s_b] (El Hajjar et al. 2008)

namespace vri {

struct TableRequest {
  int size = 256, order = 1;
  double length = 1;                  // slab length, world units
  std::optional<int> lengths;         // order 1: M lengths (with max_length)
  std::optional<double> max_length;
  std::optional<std::string> builder; // order 1: brute, incremental (default), sliced, engel, exact; order 2: plain, fast (default), exact
  std::optional<int> iterations;      // order 2: chords per slab (default kDefaultSecondOrderIterations)
  int steps = 0;                      // sliced: integration steps (0: 2N)
  std::string accumulation = "fp32";  // sliced: 8bit, 12bit, fp16, fp32
  // cpu or vulkan (order 1: sliced, the default there, fp32 only; order 2:
  // fast): where the table is built (vri/render.hpp).
  std::string backend = "cpu";
};

struct BuiltTable {
  std::vector<std::size_t> shape;
  std::span<const float> data;  // float32 premultiplied RGBA, C order
  std::shared_ptr<const void> owner;  // the table the data lives in (no copy)
  std::string builder;      // the builder's own name, with " (vulkan)" when built there
  double seconds = 0;       // build time (the table alone)
};

// Throws vri::Error for a bad order, size, builder or a flag of the other order.
BuiltTable build_table(const TransferFunction& tf, const TableRequest& request);

}  // namespace vri

// ---- render_checks ---------------------------------------------------------
// Checks every render makes around the render itself (issue 17; the CLI and
// the Python module alike): parameters that would crash or hang it, work caps
// estimated before it, images that must not be returned (NaN/Inf) and images
// worth a warning (all transparent). Messages name the CLI flag and the scene key.

namespace vri {

// The bound on what early termination dropped in an image rendered with
// threshold `termination` > 0: a ray stops only once T < termination, and its
// pixel keeps alpha = 1 - T, so every pixel that may have stopped has
// 1 - alpha < termination and lost at most its 1 - alpha (times the largest colour).
struct TerminationBound {
  long long pixels = 0;   // pixels with 1 - alpha < termination: those that may have stopped early
  double max_remaining = 0;  // the largest 1 - alpha among them
};
TerminationBound termination_bound(const Image& image, double termination);

// Most worker threads accepted (TBB crashes on absurd counts).
inline constexpr int kMaxThreads = 1024;

// --threads in [0, kMaxThreads]; vri::Error beyond.
int checked_threads(int threads);

// Samples per ray and in all, estimated from the step and the volume's
// diagonal; vri::Error saying how to raise the cap when over it.
void check_work(const Scene& scene, const Camera& camera);

// vri::Error if the image holds a NaN or an infinity (no file is written).
void refuse_non_finite(const Image& image, const std::string& what);

// When every pixel is transparent, the likely cause in one line ("the camera
// looks away from the volume ..."), for a warning; nullopt otherwise.
std::optional<std::string> transparency_cause(const Image& image, const Scene& scene, const Camera& camera);

}  // namespace vri

// ---- scene_renderer --------------------------------------------------------
// SceneRenderer: one scene made ready to render - its parameters checked, its
// work estimated against the caps, its integrator (or, for `pt` and
// `pt-cylindrical`, its projected-tetrahedra tables) built - then rendered.
// `vri render`, the Python module and library users all render through it,
// so each gets the same checks and the same bytes for the same scene. With
// Backend::Vulkan the scene is made ready on a GPU instead (backend.hpp).

namespace vri {

class SceneRenderer {
 public:
  // Throws vri::Error for bad parameters, work over the caps or a method the
  // volume does not support. Refers to `scene`: keep it alive and unchanged.
  // The tables are built on `threads` threads (0: every core, and a
  // Cancellation around the constructor can stop the build; with threads > 0
  // it cannot: the build runs in its own TBB arena).
  explicit SceneRenderer(const Scene& scene, Backend backend = Backend::Cpu, int threads = 0);
  ~SceneRenderer();
  SceneRenderer(const SceneRenderer&) = delete;
  SceneRenderer& operator=(const SceneRenderer&) = delete;

  const Camera& camera() const { return camera_; }
  // The integrator's own name (with its variant), or the projected method's.
  std::string method_name() const;
  Backend backend() const { return gpu_ ? Backend::Vulkan : Backend::Cpu; }
  // "cpu", or the GPU's name ("vulkan: llvmpipe (LLVM 15.0.6, 256 bits)").
  std::string device_name() const;

  // The image; vri::Error if it holds NaN or infinity (refuse_non_finite),
  // so no caller writes one.
  Image render(const RenderOptions& options = {}) const;
  // The same scene seen through another camera (its size and work checked as
  // the scene's own): the viewer orbits and previews with the tables built once.
  Image render(const Camera& camera, const RenderOptions& options = {}) const;

  // The method as an error-estimating integrator (adaptive), or vri::Error
  // saying that `what` (a flag or function name) needs adaptive.
  const ErrorEstimatingIntegrator& error_estimating(const std::string& what) const;
  // The per-pixel error estimate of adaptive (render_error_estimate), checked as render().
  Image render_error_estimate(const RenderOptions& options = {}) const;

 private:
  void prepare(Backend backend);  // the integrator, projected tables or GPU renderer
  const Scene& scene_;
  Camera camera_;
  std::unique_ptr<Integrator> integrator_;
  std::unique_ptr<ProjectedSceneRenderer> projected_;  // pt, pt-cylindrical
  std::unique_ptr<GpuSceneRenderer> gpu_;
};

}  // namespace vri
