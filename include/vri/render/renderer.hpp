#pragma once
// The renderer: one ray per pixel through the camera, integrated by any
// Integrator, in square tiles spread over threads. Each pixel depends only on
// its own ray, so the image is the same bytes for any thread count.
#include <atomic>
#include <functional>

#include "vri/camera/camera.hpp"
#include "vri/core/cancelled.hpp"
#include "vri/core/error.hpp"
#include "vri/integrators/integrator.hpp"
#include "vri/image.hpp"

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

// A render whose RenderOptions::cancel was set throws RenderCancelled (vri/core/cancelled.hpp): no image.

// Throws RenderCancelled if options.cancel is set (for renderers of their own, between tiles).
void throw_if_cancelled(const RenderOptions& options);

Image render(const Camera& camera, const Integrator& integrator, const RenderOptions& options = {});

}  // namespace vri
