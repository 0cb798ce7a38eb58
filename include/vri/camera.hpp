#pragma once
// vri/camera.hpp: the camera of SPEC §4 and the framing that fits it to a volume.

#include <optional>

#include "vri/geometry.hpp"

// ---- camera ----------------------------------------------------------------
// Camera (SPEC §6): pinhole perspective or orthographic; pixel (0,0) is the
// top-left, rays go through pixel centres.

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
  // What ray() builds on: the unit frame (u right, v up, w toward the eye),
  // tan(fov_y/2) or ortho_height/2, width / height. The GPU makes its rays
  // from these (src/methods/march/ray_setup.hpp).
  struct Frame {
    Vec3 u, v, w;
    double half_h, aspect;
  };
  Frame frame() const { return {u_, v_, w_, half_h_, aspect_}; }
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

// ---- framing ---------------------------------------------------------------
// Cameras made from the volume instead of written by hand (issue 20, item 3):
// a camera that frames a box, as ParaView's and VTK's "reset camera" do, and
// VTK's camera motions (Azimuth, Elevation, Roll, Zoom) relative to it.

namespace vri {

// `spec` (its size, fov_y, projection and up kept) looking at the centre of the
// box [lo, hi] from the side that up allows - from +z (looking down -z), or,
// when up is within 25 degrees of the z axis, from -y (looking along +y) - at the
// distance where the box's bounding sphere touches the narrower side of the
// view; orthographic: ortho_height the sphere's diameter.
CameraSpec frame_box(Vec3 lo, Vec3 hi, CameraSpec spec = {});

// VTK's camera motions, in this order, about the target (degrees): azimuth
// turns the eye about `up` (to the right for positive angles), elevation
// raises it towards `up` (up turns with it, so 90 degrees looks straight down
// without a degenerate camera: VTK would need OrthogonalizeViewUp), roll turns
// `up` about the view direction; zoom magnifies by `zoom` as VTK's Zoom does:
// the field of view narrows (tan(fov_y/2) / zoom), or ortho_height / zoom.
CameraSpec move_camera(CameraSpec spec, double azimuth, double elevation, double roll, double zoom);

}  // namespace vri
