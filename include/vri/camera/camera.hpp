#pragma once
// Camera (SPEC §6): pinhole perspective or orthographic; pixel (0,0) is the
// top-left, rays go through pixel centres.
#include <optional>

#include "vri/core/ray.hpp"
#include "vri/core/vec3.hpp"

namespace vri {

enum class Projection { Perspective, Orthographic };

struct CameraSpec {
  Vec3 eye{0, 0, 1};
  Vec3 target{0, 0, 0};
  Vec3 up{0, 1, 0};
  double fov_y = 30;  // degrees, perspective only
  int width = 512, height = 512;
  Projection projection = Projection::Perspective;
  double ortho_height = 0;  // world units, orthographic only
};

class Camera {
 public:
  // Largest accepted image: 16384 pixels a side and 2^26 pixels in all.
  static constexpr int kMaxSide = 16384;
  static constexpr long long kMaxPixels = 1LL << 26;

  // Throws vri::Error for eye == target, up parallel to the view, a bad fov,
  // non-positive or absurd sizes, or orthographic without a positive ortho_height.
  explicit Camera(const CameraSpec& spec);

  const CameraSpec& spec() const { return spec_; }
  int width() const { return spec_.width; }
  int height() const { return spec_.height; }

  Ray ray(int px, int py) const;
  // Continuous pixel coordinates (px, py) at which the world point p is seen
  // (pixel centres at integer + 0.5 ... i.e. the inverse of ray()); nullopt if behind the eye.
  std::optional<std::pair<double, double>> project(Vec3 p) const;

 private:
  CameraSpec spec_;
  Vec3 u_, v_, w_;
  double half_h_;  // tan(fov_y/2) or ortho_height/2
  double aspect_;
};

}  // namespace vri
