#include "vri/camera.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "vri/error.hpp"

namespace vri {

namespace {

bool finite(Vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

Camera::Camera(const CameraSpec& spec) : spec_(spec) {
  if (spec.width <= 0 || spec.height <= 0)
    throw Error("image size must be positive, got " + std::to_string(spec.width) + "x" +
                std::to_string(spec.height));
  if (spec.width > kMaxSide || spec.height > kMaxSide ||
      static_cast<long long>(spec.width) * spec.height > kMaxPixels)
    throw Error("image size " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                " is too large (at most " + std::to_string(kMaxSide) + " a side, " +
                std::to_string(kMaxPixels) + " pixels)");
  if (!finite(spec.eye) || !finite(spec.target) || !finite(spec.up))
    throw Error("camera eye, target and up must be finite");
  const Vec3 view = spec.eye - spec.target;
  if (length(view) == 0) throw Error("camera eye and target are the same point");
  w_ = normalize(view);
  if (length(spec.up) == 0) throw Error("camera up vector is zero");
  const Vec3 side = cross(spec.up, w_);
  if (length(side) <= 1e-9 * length(spec.up))
    throw Error("camera up vector is parallel to the viewing direction");
  u_ = normalize(side);
  v_ = cross(w_, u_);
  aspect_ = double(spec.width) / spec.height;
  if (spec.projection == Projection::Perspective) {
    if (!(spec.fov_y > 0 && spec.fov_y < 180))
      throw Error("camera fov_y must be in (0, 180) degrees, got " + format_g(spec.fov_y));
    half_h_ = std::tan(spec.fov_y * std::numbers::pi / 360.0);
  } else {
    if (!(spec.ortho_height > 0) || !std::isfinite(spec.ortho_height))
      throw Error("orthographic camera needs a positive ortho_height");
    half_h_ = spec.ortho_height / 2;
  }
}

Ray Camera::ray(int px, int py) const {
  const double x = (2.0 * (px + 0.5) / spec_.width - 1.0) * half_h_ * aspect_;
  const double y = (1.0 - 2.0 * (py + 0.5) / spec_.height) * half_h_;
  if (spec_.projection == Projection::Perspective)
    return {spec_.eye, normalize(x * u_ + y * v_ - w_)};
  return {spec_.eye + x * u_ + y * v_, -w_};
}

std::optional<std::pair<double, double>> Camera::project(Vec3 p) const {
  const Vec3 r = p - spec_.eye;
  double x = dot(r, u_), y = dot(r, v_);
  const double depth = -dot(r, w_);
  if (spec_.projection == Projection::Perspective) {
    if (depth <= 0) return std::nullopt;
    x /= depth;
    y /= depth;
  }
  // Invert x = (2(px+0.5)/W - 1) * half_h * aspect; return the continuous
  // coordinate whose pixel centre is px + 0.5.
  const double px = (x / (half_h_ * aspect_) + 1.0) * spec_.width / 2.0;
  const double py = (1.0 - y / half_h_) * spec_.height / 2.0;
  return std::make_pair(px, py);
}

}  // namespace vri
