#include "vri/render/renderer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "test_support.hpp"
#include "vri/integrators/exact.hpp"
#include "vri/integrators/preint1.hpp"
#include "vri/integrators/riemann.hpp"
#include "vri/scene/scene.hpp"

namespace vri {
namespace {

TEST(Renderer, SameBytesWithAnyThreadCountAndTileSize) {
  Scene scene = load_scene(test::source_path("scenes/fuel.json"));
  scene.camera.width = 45;
  scene.camera.height = 37;
  const Camera cam(scene.camera);
  const ExactIntegrator exact(scene.grid(), scene.transfer_function, 1e-5);
  const RiemannIntegrator riemann(scene.grid(), scene.transfer_function, 0.7);
  for (const Integrator* integ : {static_cast<const Integrator*>(&exact), static_cast<const Integrator*>(&riemann)}) {
    const Image one = render(cam, *integ, {.threads = 1});
    double alpha_sum = 0;
    for (int y = 0; y < 37; ++y)
      for (int x = 0; x < 45; ++x) alpha_sum += one.pixel(x, y)[3];
    EXPECT_GT(alpha_sum, 10) << "the scene must not be empty";
    for (RenderOptions opt : {RenderOptions{2, 16}, RenderOptions{3, 7}, RenderOptions{8, 1}, RenderOptions{0, 64}}) {
      const Image other = render(cam, *integ, opt);
      ASSERT_EQ(0, std::memcmp(one.data().data(), other.data().data(), one.data().size() * sizeof(float)))
          << integ->name() << " threads " << opt.threads;
    }
  }
}

// The renderer hands rays over in blocks of 4 x 2 pixels (odd tile and image
// sizes leave partial blocks): each pixel still gets its own ray's integral.
// preint1 marches them as packets of 8 where the CPU has AVX2.
TEST(Renderer, EveryPixelGetsItsOwnRaysIntegral) {
  Scene scene = load_scene(test::source_path("scenes/neghip.json"));
  scene.camera.width = 29;
  scene.camera.height = 19;
  const Camera cam(scene.camera);
  const Preint1Integrator preint1(scene.grid(), scene.transfer_function, 1.0, 256, "incremental");
  for (const int tile : {16, 7, 5, 1}) {
    const Image img = render(cam, preint1, {.threads = 2, .tile_size = tile});
    for (int y = 0; y < 19; ++y)
      for (int x = 0; x < 29; ++x) {
        const Rgba want = preint1.integrate(cam.ray(x, y));
        for (int c = 0; c < 4; ++c)
          ASSERT_EQ(img.pixel(x, y)[c], static_cast<float>(want[c])) << "tile " << tile << " pixel " << x << " " << y;
      }
  }
}

TEST(Renderer, ABlobLandsOnThePredictedPixel) {
  // A narrow Gaussian blob centred at c = (14, 6, 10), seen from (10, 10, 40)
  // looking at (10, 10, 10) with fov 60 on 64 x 64 pixels: c - eye = (4, -4, -30),
  // so x = 4/30, y = -4/30 in view units and px = py = (1 + (4/30)/tan 30deg) * 32 = 39.39.
  const Vec3 c{14, 6, 10};
  const auto vol = test::volume_from({21, 21, 21}, [&](double x, double y, double z) {
    const Vec3 d = Vec3{x, y, z} - c;
    return std::exp(-dot(d, d) / 2);
  });
  const TransferFunction tf({{0.2, 1, 1, 1, 0}, {1, 1, 1, 1, 5}});
  CameraSpec spec;
  spec.eye = {10, 10, 40};
  spec.target = {10, 10, 10};
  spec.fov_y = 60;
  spec.width = spec.height = 64;
  const Image img = render(Camera(spec), ExactIntegrator(vol, tf, 1e-6));
  int bx = -1, by = -1;
  float best = -1;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x)
      if (img.pixel(x, y)[3] > best) {
        best = img.pixel(x, y)[3];
        bx = x;
        by = y;
      }
  EXPECT_EQ(bx, 39);
  EXPECT_EQ(by, 39);
  EXPECT_GT(best, 0.5);
  EXPECT_EQ(img.pixel(10, 10)[3], 0.f);
}

}  // namespace
}  // namespace vri
