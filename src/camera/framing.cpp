#include "vri/camera/framing.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace vri {

CameraSpec frame_box(Vec3 lo, Vec3 hi, int width, int height, double fov_y) {
  const Vec3 centre = (lo + hi) * 0.5;
  const double radius = std::max(length(hi - lo) * 0.5, 1e-9);
  // The narrower half-angle: fov_y vertically, or the horizontal one on a tall image.
  const double half_y = fov_y * std::numbers::pi / 360.0;
  const double half_x = std::atan(std::tan(half_y) * width / height);
  const double half = std::min(half_y, half_x);
  CameraSpec spec;
  spec.target = centre;
  spec.eye = centre + Vec3{0, 0, radius / std::sin(half)};
  spec.up = {0, 1, 0};
  spec.fov_y = fov_y;
  spec.width = width;
  spec.height = height;
  return spec;
}

}  // namespace vri
