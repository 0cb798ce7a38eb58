#include "vri/render.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <vector>

#include "camera/screen_footprint.hpp"
#include "vri/error.hpp"

namespace vri {

Image render(const Camera& camera, const Integrator& integrator, const RenderOptions& options) {
  if (options.threads < 0) throw Error("thread count must be >= 0");
  if (options.tile_size <= 0) throw Error("tile size must be positive");
  const int W = camera.width(), H = camera.height(), ts = options.tile_size;
  const int tiles_x = (W + ts - 1) / ts, tiles_y = (H + ts - 1) / ts;
  Image image(W, H);
  const int tiles = tiles_x * tiles_y;
  // Only the pixels whose rays may meet the method's footprint are cast; the
  // others keep the image's zeros, what their rays would give.
  const Footprint* footprint = integrator.footprint();
  const ScreenFootprint seen = footprint ? ScreenFootprint(camera, *footprint) : ScreenFootprint(camera);
  std::atomic<int> done{0};
  auto render_tiles = [&](const tbb::blocked_range<int>& range) {
    for (int t = range.begin(); t != range.end(); ++t) {
      if (options.cancel && options.cancel->load(std::memory_order_relaxed)) return;
      const int x0 = (t % tiles_x) * ts, y0 = (t / tiles_x) * ts;
      const int x1 = std::min(W, x0 + ts);
      const int y1 = std::min(H, y0 + ts);
      // Two pixel rows at a time, handed over in blocks of 4 x 2 pixels: a
      // packet's 8 rays (methods/march/float_packet.hpp) then lie closer
      // together in the volume than 8 of one row, so they cross the same
      // voxels and macro cells more often.
      std::vector<Ray> rays(2 * (x1 - x0));
      std::vector<Rgba> out(rays.size());
      std::vector<std::array<int, 2>> pixel(rays.size());
      for (int y = y0; y < y1; y += 2) {
        const int ye = std::min(y1, y + 2);
        // The blocks that reach into the footprint's pixels, on the tile's grid of blocks.
        const ScreenFootprint::Span span = seen.rows(y, ye);
        const int bx1 = std::min(x1, span.x1);
        int n = 0;
        for (int bx = x0 + std::max(0, (span.x0 - x0) / 4 * 4); bx < bx1; bx += 4) {
          if (!seen.sees(bx, std::min(x1, bx + 4), y, ye)) continue;
          for (int py = y; py < ye; ++py)
            for (int px = bx; px < std::min(x1, bx + 4); ++px) {
              pixel[n] = {px, py};
              rays[n++] = camera.ray(px, py);
            }
        }
        if (n == 0) continue;
        integrator.integrate_row(rays.data(), n, out.data());
        for (int i = 0; i < n; ++i) image.set(pixel[i][0], pixel[i][1], out[i]);
      }
      if (options.progress) {
        const int n = done.fetch_add(1) + 1;
        if (n * 100 / tiles != (n - 1) * 100 / tiles) options.progress(double(n) / tiles);
      }
    }
  };
  tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
  arena.execute([&] { tbb::parallel_for(tbb::blocked_range<int>(0, tiles, 1), render_tiles); });
  throw_if_cancelled(options);
  return image;
}

void throw_if_cancelled(const RenderOptions& options) {
  if (options.cancel && options.cancel->load()) throw RenderCancelled();
}

}  // namespace vri
