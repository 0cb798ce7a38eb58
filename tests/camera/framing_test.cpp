// Cameras made from the volume: frame_box holds the whole box in view (any
// aspect, either projection, z-up data seen from the side), move_camera
// follows VTK's Azimuth, Elevation, Roll and Zoom, and scenes and overrides
// use them ("fit", the default without an eye).
#include "vri/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/scene.hpp"

namespace vri {
namespace {

// Every corner of [lo, hi] projects inside the image; returns how close the
// nearest one comes to the border, in pixels.
double inside_margin(const CameraSpec& spec, Vec3 lo, Vec3 hi) {
  const Camera camera(spec);
  double margin = 1e300;
  for (int c = 0; c < 8; ++c) {
    const Vec3 p{c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z};
    const auto px = camera.project(p);
    if (!px) return -1;
    margin = std::min({margin, px->first, spec.width - px->first, px->second, spec.height - px->second});
  }
  return margin;
}

TEST(Framing, BoxFitsAnyAspectAndProjection) {
  const Vec3 lo{-3, 10, 2}, hi{40, 17, 9};
  for (auto projection : {Projection::Perspective, Projection::Orthographic})
    for (auto [w, h] : {std::pair{512, 512}, std::pair{800, 300}, std::pair{200, 700}})
      for (double fov : {15.0, 30.0, 60.0}) {
        CameraSpec s;
        s.width = w;
        s.height = h;
        s.fov_y = fov;
        s.projection = projection;
        const CameraSpec f = frame_box(lo, hi, s);
        EXPECT_GT(inside_margin(f, lo, hi), 0) << w << "x" << h << " fov " << fov;
        EXPECT_EQ(f.target.x, (lo.x + hi.x) / 2);
        EXPECT_GT(f.eye.z, hi.z);  // looking down -z
        EXPECT_EQ(f.width, w);
      }
}

TEST(Framing, SphereTouchesTheNarrowerSide) {
  CameraSpec s;  // 512 x 512, fov 30
  const CameraSpec f = frame_box({0, 0, 0}, {2, 2, 2}, s);
  const double radius = std::sqrt(3.0);
  EXPECT_NEAR(length(f.eye - f.target), radius / std::sin(15 * std::acos(-1.0) / 180), 1e-12);
}

TEST(Framing, ZUpDataIsSeenFromTheSide) {
  CameraSpec s;
  s.up = {0, 0, 1};
  const CameraSpec f = frame_box({0, 0, 0}, {1, 1, 1}, s);
  EXPECT_LT(f.eye.y, 0);  // from -y, looking along +y, z up
  EXPECT_EQ(f.eye.x, 0.5);
  EXPECT_EQ(f.eye.z, 0.5);
  EXPECT_NO_THROW(Camera{f});
}

TEST(Framing, AzimuthElevationRollFollowVtk) {
  CameraSpec s;
  s.eye = {0, 0, 10};
  s.target = {0, 0, 0};
  s.up = {0, 1, 0};
  // Azimuth 90: about up (right-handed), the eye from +z to +x.
  CameraSpec a = move_camera(s, 90, 0, 0, 1);
  EXPECT_NEAR(a.eye.x, 10, 1e-12);
  EXPECT_NEAR(a.eye.z, 0, 1e-12);
  // Elevation 90: the eye raised to +y, up turned with it to -z: no degenerate camera.
  CameraSpec e = move_camera(s, 0, 90, 0, 1);
  EXPECT_NEAR(e.eye.y, 10, 1e-12);
  EXPECT_NEAR(e.up.z, -1, 1e-12);
  EXPECT_NO_THROW(Camera{e});
  // Roll 90: up turned about the direction of projection (-z) right-handed, as
  // VTK's RotateWXYZ(angle, DirectionOfProjection): from +y to +x; 360 is no roll.
  CameraSpec r = move_camera(s, 0, 0, 90, 1);
  EXPECT_NEAR(r.up.x, 1, 1e-12);
  CameraSpec full = move_camera(s, 360, 0, 360, 1);
  EXPECT_NEAR(full.eye.z, 10, 1e-12);
  EXPECT_NEAR(full.up.y, 1, 1e-12);
  EXPECT_THROW(move_camera(s, 0, 0, 0, 0), Error);
  EXPECT_THROW(move_camera(s, NAN, 0, 0, 1), Error);
}

TEST(Framing, ZoomMagnifiesAroundTheCentre) {
  for (auto projection : {Projection::Perspective, Projection::Orthographic}) {
    CameraSpec s;
    s.eye = {0, 0, 10};
    s.projection = projection;
    s.ortho_height = 8;
    const Vec3 p{1.5, -0.75, 0};
    const auto before = Camera(s).project(p), after = Camera(move_camera(s, 0, 0, 0, 2)).project(p);
    ASSERT_TRUE(before && after);
    EXPECT_NEAR(after->first - 256, 2 * (before->first - 256), 1e-9);
    EXPECT_NEAR(after->second - 256, 2 * (before->second - 256), 1e-9);
  }
}

TEST(Framing, ScenesFitByDefaultAndRefuseFitWithAnEye) {
  const std::string tf = R"("transfer_function": {"points": [[0, 1, 1, 1, 0.1]]})";
  const std::string vol = R"("volume": {"builtin": "sphere", "dims": [20, 30, 40], "spacing": [1, 0.5, 2]})";
  const Scene fitted = parse_scene("{" + vol + ", " + tf + R"(, "camera": {"width": 300, "height": 200}})", ".");
  const auto [lo, hi] = bounds(fitted.volume);
  EXPECT_GT(inside_margin(fitted.camera, lo, hi), 0);
  const Scene turned =
      parse_scene("{" + vol + ", " + tf + R"(, "camera": {"fit": true, "azimuth": 30, "elevation": 20, "zoom": 1.5}})",
                  ".");
  const CameraSpec expected = move_camera(frame_box(lo, hi, CameraSpec{}), 30, 20, 0, 1.5);
  EXPECT_EQ(turned.camera.eye.x, expected.eye.x);
  EXPECT_EQ(turned.camera.fov_y, expected.fov_y);
  EXPECT_THROW(parse_scene("{" + vol + ", " + tf + R"(, "camera": {"fit": true, "eye": [0, 0, 5]}})", "."), Error);
  EXPECT_THROW(parse_scene("{" + vol + ", " + tf + R"(, "camera": {"eye": [0, 0, 5], "zoom": 0}})", "."), Error);
  EXPECT_THROW(parse_camera(R"({"fit": true})"), Error);
  // The command line's --fit --azimuth: the same camera through the overrides.
  Scene s = parse_scene("{" + vol + ", " + tf + R"(, "camera": {"eye": [0, 0, 500], "target": [1, 2, 3]}})", ".");
  SceneOverrides o;
  o.fit = true;
  o.azimuth = 30;
  o.elevation = 20;
  o.zoom = 1.5;
  apply_overrides(s, o);
  EXPECT_EQ(s.camera.eye.x, expected.eye.x);
  EXPECT_EQ(s.camera.eye.y, expected.eye.y);
}

}  // namespace
}  // namespace vri
