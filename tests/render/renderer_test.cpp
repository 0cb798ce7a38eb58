#include "vri/render.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "test_support.hpp"
#include "camera/screen_footprint.hpp"
#include "methods/exact/exact.hpp"
#include "vri/methods.hpp"
#include "methods/preint/preint1.hpp"
#include "methods/riemann/riemann.hpp"
#include "vri/scene.hpp"

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

// The method, casting every ray (no footprint).
class CastEveryRay final : public Integrator {
 public:
  explicit CastEveryRay(const Integrator& method) : method_(method) {}
  Rgba integrate(const Ray& ray) const override { return method_.integrate(ray); }
  void integrate_row(const Ray* rays, int n, Rgba* out) const override { method_.integrate_row(rays, n, out); }
  std::string_view name() const override { return method_.name(); }

 private:
  const Integrator& method_;
};

// The renderer casts only the rays that may meet a method's footprint (the
// volume's box; with skipping the runs of non-empty macro cells inside
// their box) and leaves the other pixels at zero: the same bytes as casting
// every ray, for every grid method, with and without skipping and
// termination, lit and unlit, seen from around the volume in perspective
// and in parallel. The data is two balls in opposite corners of an uneven
// grid: many rays pass beside both, or between them inside their box.
TEST(Renderer, FootprintCullingKeepsTheBytes) {
  const Vec3 centres[] = {{30, 27, 34}, {8, 7, 9}};
  const auto volume = test::volume_from(
      {40, 36, 44},
      [&](double x, double y, double z) {
        double v = 0;
        for (const Vec3& c : centres) {
          const Vec3 d = Vec3{x, y, z} - c;
          v = std::max(v, 1 - std::sqrt(dot(d, d)) / 7);
        }
        return v;
      },
      {1, 1.25, 0.8}, {3, -2, 1});
  const TransferFunction tf({{0, 0, 0, 0, 0}, {0.3, 0.2, 0.5, 1, 0}, {0.6, 1, 0.6, 0.2, 0.8}, {1, 1, 1, 1, 3}});
  MethodSpec methods[] = {{.name = "riemann", .step = 0.7}, {.name = "preint1", .step = 0.9},
                          {.name = "preint2", .step = 1.1}, {.name = "preint2-dual"},
                          {.name = "exact", .tolerance = 1e-4}, {.name = "adaptive", .tolerance = 1e-3},
                          {.name = "adaptive", .tolerance = 1e-3, .strategy = "guaranteed"}};
  for (MethodSpec& m : methods) m.table_size = 64, m.table_size_given = true, m.iterations = 4;
  int views = 0, culled_more = 0;
  for (const bool lit : {false, true})
    for (const FastPath fast : {FastPath{.skip_empty = false}, FastPath{}, FastPath{.termination = 0.05}})
      for (MethodSpec spec : methods) {
        const bool grid_walk = spec.name == "exact" || spec.name == "adaptive";
        if ((grid_walk && (lit || fast.termination > 0)) || (spec.name == "preint2-dual" && lit)) continue;
        spec.fast = fast;
        const Lighting lighting{.enabled = lit};
        const auto method = make_integrator(spec, volume, tf, lighting);
        for (int view = 0; view < 4; ++view) {
          CameraSpec cam;
          const double a = 1.1 + 1.7 * view;
          cam.target = {25, 20, 20};
          cam.eye = cam.target + Vec3{90 * std::cos(a), 90 * std::sin(a), 40.0 * (view - 1.5)};
          cam.up = {0, 0, 1};
          cam.width = 44, cam.height = 34;
          if (view % 2) cam.projection = Projection::Orthographic, cam.ortho_height = 70;
          const Camera camera(cam);
          const Image culled = render(camera, *method, {.threads = 2, .tile_size = 9});
          const Image all = render(camera, CastEveryRay(*method), {.threads = 2, .tile_size = 9});
          const std::string what = spec.name + (spec.name == "adaptive" ? " " + spec.strategy : "") +
                                   (lit ? " lit" : "") + " skip " +
                                   std::to_string(fast.skip_empty) + " termination " +
                                   std::to_string(fast.termination) + " view " + std::to_string(view);
          ASSERT_EQ(0, std::memcmp(culled.data().data(), all.data().data(), all.data().size() * sizeof(float)))
              << what;
          float alpha = 0;
          for (int i = 3; i < int(all.data().size()); i += 4) alpha += all.data()[i];
          ASSERT_GT(alpha, 5) << what << ": the ball must be in view";
          // The footprint leaves out pixels whose rays would meet the volume's box.
          const Footprint* footprint = method->footprint();
          ASSERT_TRUE(footprint) << what;
          const ScreenFootprint small(camera, *footprint), whole(camera, Footprint{volume.whole_box(), {}});
          for (int y = 0; y < cam.height; y += 2) {
            const auto s = small.rows(y, y + 2), w = whole.rows(y, y + 2);
            for (int x = w.x0; x < w.x1; ++x) {
              const int bx = x / 4 * 4;
              culled_more += !(x >= s.x0 && x < s.x1 && small.sees(bx, std::min(cam.width, bx + 4), y, y + 2));
            }
          }
          ++views;
        }
      }
  EXPECT_GT(views, 100);
  EXPECT_GT(culled_more, 10000) << "skipping's footprint must be smaller than the volume's box";
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
