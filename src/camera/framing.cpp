#include "vri/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "vri/error.hpp"

namespace vri {

namespace {

constexpr double kDegree = std::numbers::pi / 180;

// v turned by `angle` radians about the unit axis k (Rodrigues' formula).
Vec3 rotate(Vec3 v, Vec3 k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

}  // namespace

CameraSpec frame_box(Vec3 lo, Vec3 hi, CameraSpec spec) {
  const Vec3 centre = (lo + hi) * 0.5;
  const double radius = std::max(length(hi - lo) * 0.5, 1e-9);
  const Vec3 up = length(spec.up) > 0 ? normalize(spec.up) : Vec3{0, 1, 0};
  const Vec3 from = std::abs(up.z) > std::cos(25 * kDegree) ? Vec3{0, -1, 0} : Vec3{0, 0, 1};
  double distance = 0;
  if (spec.projection == Projection::Perspective) {
    // The narrower half-angle: fov_y vertically, or the horizontal one on a tall image.
    const double half_y = spec.fov_y * kDegree / 2;
    const double half_x = std::atan(std::tan(half_y) * spec.width / spec.height);
    distance = radius / std::sin(std::min(half_y, half_x));
  } else {
    spec.ortho_height = 2 * radius * std::max(1.0, double(spec.height) / spec.width);
    distance = 2 * radius;  // outside the sphere: every ray starts before the box
  }
  spec.target = centre;
  spec.eye = centre + from * distance;
  return spec;
}

CameraSpec move_camera(CameraSpec spec, double azimuth, double elevation, double roll, double zoom) {
  if (!std::isfinite(azimuth) || !std::isfinite(elevation) || !std::isfinite(roll))
    throw Error("camera azimuth, elevation and roll must be finite");
  if (!(zoom > 0) || !std::isfinite(zoom)) throw Error("camera zoom must be a positive number");
  Vec3 offset = spec.eye - spec.target;
  if (length(offset) == 0 || length(spec.up) == 0) throw Error("camera eye and target are the same point");
  Vec3 up = spec.up;
  offset = rotate(offset, normalize(up), azimuth * kDegree);
  const Vec3 side = cross(offset, up);
  if (elevation != 0) {
    if (length(side) == 0) throw Error("camera up vector is parallel to the viewing direction");
    const Vec3 k = normalize(side);
    offset = rotate(offset, k, elevation * kDegree);
    up = rotate(up, k, elevation * kDegree);
  }
  up = rotate(up, normalize(offset), -roll * kDegree);
  spec.eye = spec.target + offset;
  spec.up = up;
  // The zoom is what the user gave: a view it makes impossible is said of it,
  // not of the fov_y or height it computed (issue 47).
  if (spec.projection == Projection::Perspective) {
    spec.fov_y = 2 * std::atan(std::tan(spec.fov_y * kDegree / 2) / zoom) / kDegree;
    if (!(spec.fov_y > 0 && spec.fov_y < 180))
      throw Error("camera zoom " + format_g(zoom) + " makes fov_y " + format_g(spec.fov_y) +
                  " degrees; it must stay in (0, 180)");
  } else {
    spec.ortho_height /= zoom;
    if (!(spec.ortho_height > 0) || !std::isfinite(spec.ortho_height))
      throw Error("camera zoom " + format_g(zoom) + " makes ortho_height " + format_g(spec.ortho_height) +
                  "; it must stay a positive number");
  }
  return spec;
}

}  // namespace vri
