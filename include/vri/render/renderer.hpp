#pragma once
// The renderer: one ray per pixel through the camera, integrated by any
// Integrator, in square tiles spread over threads. Each pixel depends only on
// its own ray, so the image is the same bytes for any thread count.
#include "vri/camera/camera.hpp"
#include "vri/integrators/integrator.hpp"
#include "vri/render/image.hpp"

namespace vri {

struct RenderOptions {
  int threads = 0;     // 0: every core
  int tile_size = 16;  // pixels a side
};

Image render(const Camera& camera, const Integrator& integrator, const RenderOptions& options = {});

}  // namespace vri
