#include "vri/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "vri/error.hpp"

namespace vri {
namespace {

CameraSpec looking_down_z(Projection p) {
  CameraSpec s;
  s.eye = {0, 0, 10};
  s.target = {0, 0, 0};
  s.up = {0, 1, 0};
  s.fov_y = 90;  // tan(45 deg) = 1
  s.width = 200;
  s.height = 100;
  s.projection = p;
  s.ortho_height = 4;
  return s;
}

TEST(Camera, PerspectiveRaysFollowTheSpecFormula) {
  const Camera cam(looking_down_z(Projection::Perspective));
  // pixel (0, 0): x = (2*0.5/200 - 1) * 1 * 2 = -1.99, y = (1 - 2*0.5/100) * 1 = 0.99
  const Ray r = cam.ray(0, 0);
  const Vec3 expect = normalize({-1.99, 0.99, -1});
  EXPECT_NEAR(r.dir.x, expect.x, 1e-15);
  EXPECT_NEAR(r.dir.y, expect.y, 1e-15);
  EXPECT_NEAR(r.dir.z, expect.z, 1e-15);
  EXPECT_DOUBLE_EQ(r.origin.z, 10);
}

TEST(Camera, APointLandsOnThePredictedPixel) {
  // Perspective: the world point (x, y, 0) is seen at x/10, y/10 in view units.
  const Camera persp(looking_down_z(Projection::Perspective));
  const auto p = persp.project({5, -2.5, 0});
  ASSERT_TRUE(p);
  // px = (0.5 / 2 + 1) * 200 / 2 = 125, py = (1 + 0.25) * 100 / 2 = 62.5
  EXPECT_NEAR(p->first, 125, 1e-12);
  EXPECT_NEAR(p->second, 62.5, 1e-12);
  // ...and the ray through that pixel's centre passes next to the point.
  const Ray r = persp.ray(125, 62);
  const double t = (0 - r.origin.z) / r.dir.z;
  EXPECT_NEAR(r.at(t).x, 5 + 0.5 * 10 * 2 * 2 / 200.0, 1e-9);
  // Orthographic: ortho_height 4, so x spans [-4, 4] over 200 pixels.
  const Camera ortho(looking_down_z(Projection::Orthographic));
  const auto q = ortho.project({1, 1, -3});
  ASSERT_TRUE(q);
  EXPECT_NEAR(q->first, 125, 1e-12);
  EXPECT_NEAR(q->second, 25, 1e-12);
  const Ray o = ortho.ray(124, 24);
  EXPECT_NEAR(o.origin.x, (2 * 124.5 / 200 - 1) * 2 * 2, 1e-12);
  EXPECT_NEAR(o.origin.y, (1 - 2 * 24.5 / 100) * 2, 1e-12);
  EXPECT_DOUBLE_EQ(o.dir.z, -1);
}

TEST(Camera, UpVectorFixesTheRollAndRowZeroIsTheTop) {
  CameraSpec s = looking_down_z(Projection::Perspective);
  s.up = {1, 0, 0};  // world +x is now screen up
  const Camera cam(s);
  EXPECT_GT(cam.ray(100, 0).dir.x, 0);   // top row looks towards +x
  EXPECT_LT(cam.ray(100, 99).dir.x, 0);  // bottom row towards -x
}

TEST(Camera, RejectsBadSpecs) {
  auto bad = [](auto change) {
    CameraSpec s = looking_down_z(Projection::Perspective);
    change(s);
    EXPECT_THROW(Camera{s}, Error);
  };
  bad([](CameraSpec& s) { s.target = s.eye; });
  bad([](CameraSpec& s) { s.up = {0, 0, 3}; });  // parallel to the view
  bad([](CameraSpec& s) { s.up = {0, 0, 0}; });
  bad([](CameraSpec& s) { s.fov_y = 0; });
  bad([](CameraSpec& s) { s.fov_y = 180; });
  bad([](CameraSpec& s) { s.width = 0; });
  bad([](CameraSpec& s) { s.height = -5; });
  bad([](CameraSpec& s) { s.width = 100000; });
  bad([](CameraSpec& s) { s.width = 16384; s.height = 16384; });
  bad([](CameraSpec& s) { s.projection = Projection::Orthographic; s.ortho_height = 0; });
  bad([](CameraSpec& s) { s.eye.x = NAN; });
}

}  // namespace
}  // namespace vri
