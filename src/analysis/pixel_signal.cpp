#include "vri/analysis.hpp"

#include <cmath>
#include <string>

#include "vri/camera.hpp"
#include "vri/error.hpp"

namespace vri {

RaySignal pixel_signal(const Scene& scene, int px, int py, std::optional<double> step) {
  const Camera camera(scene.camera);
  if (px < 0 || py < 0 || px >= camera.width() || py >= camera.height())
    throw Error("pixel (" + std::to_string(px) + ", " + std::to_string(py) + ") is outside the " +
                std::to_string(camera.width()) + "x" + std::to_string(camera.height()) + " image");
  if (step && !(*step >= 1e-4 && std::isfinite(*step)))
    throw Error("--step: expected a finite number >= 1e-4 (voxel units), found " + format_g(*step));
  const GridVolume& grid = scene.grid();
  return RaySignal(grid, camera.ray(px, py), step ? std::optional<double>(*step * grid.voxel_unit()) : std::nullopt);
}

std::vector<RaySignalRow> signal_rows(const RaySignal& sig, int rows_per_interval) {
  std::vector<RaySignalRow> rows;
  const auto& ts = sig.sample_t();
  for (std::size_t k = 0; k < ts.size(); ++k) {
    const int n = k + 1 < ts.size() ? rows_per_interval : 1;
    for (int i = 0; i < n; ++i) {
      const double t = i == 0 ? ts[k] : ts[k] + (ts[k + 1] - ts[k]) * i / n;
      rows.push_back({t, sig.signal(t), {sig.approximation(0, t), sig.approximation(1, t), sig.approximation(2, t)},
                      i == 0});
    }
  }
  return rows;
}

}  // namespace vri
