// riemann's jitter (riemann.hpp, issue 20): the steps still cover the ray,
// the image is a function of the rays and the seed alone, every path gives
// it, and it turns the wood-grain rings of a coarse step into noise that a
// blur removes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>
#include <string>

#include "methods/riemann/float_riemann.hpp"  // jitter_fraction
#include "test_support.hpp"
#include "vri/error.hpp"
#include "methods/exact/exact.hpp"
#include "vri/methods.hpp"
#include "methods/riemann/riemann.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"
#include "volume/builtin_volumes.hpp"

namespace vri {
namespace {

const FastPath kDouble{.float_math = false};

// A constant field: any steps that cover [t0, t1] exactly sum to the closed
// form, so a jittered march that dropped or doubled its front piece fails.
TEST(RiemannJitter, StepsStillCoverTheRay) {
  const GridVolume volume({5, 5, 9}, std::vector<float>(5 * 5 * 9, 100.0f));
  const TransferFunction tf({{0, 0.2, 0.4, 0.8, 0.3}, {200, 0.2, 0.4, 0.8, 0.3}});
  const double alpha = 1 - std::exp(-0.3 * 8);
  for (double step : {1.0, 0.7, 3.0, 20.0})
    for (std::uint64_t seed : {0u, 1u, 99u}) {
      const RiemannIntegrator plain(volume, tf, step, {}, kDouble, seed), fast(volume, tf, step, {}, {}, seed);
      for (double x : {0.3, 2.3, 3.9}) {
        const Ray ray{{x, 1.7, -5}, {0, 0, 1}};  // through z = 0 .. 8: L = 8
        EXPECT_NEAR(plain.integrate(ray)[3], alpha, 1e-12) << step << " " << seed;
        EXPECT_NEAR(plain.integrate(ray)[2], 0.8 * alpha, 1e-12) << step << " " << seed;
        EXPECT_NEAR(fast.integrate(ray)[3], alpha, 2e-6) << step << " " << seed;
      }
    }
}

// Each step is sampled u of the way in: on tau = x / 8 over x in [0, 7]
// with steps of 2 (the last one of 1), the depth is
// sum_k (t_k + u h_k) / 8 h_k.
TEST(RiemannJitter, SamplesSitUOfTheWayIntoTheirStep) {
  const auto vol = test::volume_from({9, 2, 2}, [](double x, double, double) { return x; });
  const TransferFunction tf({{0, 1, 1, 1, 0}, {8, 1, 1, 1, 1}});  // tau = x / 8
  const Ray ray{{-1, 0.25, 0.25}, {1, 0, 0}};                      // x = 0 .. 8
  const Ray short_ray{{9, 0.25, 0.25}, {-1, 0, 0}};                // x = 8 .. 0
  for (std::uint64_t seed : {1u, 5u, 77u}) {
    const double u = detail::jitter_fraction(ray, seed);
    ASSERT_GT(u, 0);
    ASSERT_LT(u, 1);
    double depth = 0;
    for (double t = 0; t < 8; t += 2) depth += (t + 2 * u) / 8 * 2;
    EXPECT_NEAR(RiemannIntegrator(vol, tf, 2.0, {}, kDouble, seed).integrate(ray)[3], 1 - std::exp(-depth), 1e-12);
    // Steps of 3 from x = 8 down: [8, 5], [5, 2], [2, 0] (the last of 2).
    const double v = detail::jitter_fraction(short_ray, seed);
    const double reversed = (8 - 3 * v) / 8 * 3 + (5 - 3 * v) / 8 * 3 + (2 - 2 * v) / 8 * 2;
    EXPECT_NEAR(RiemannIntegrator(vol, tf, 3.0, {}, kDouble, seed).integrate(short_ray)[3], 1 - std::exp(-reversed),
                1e-12);
  }
}

// Skipping empty macro cells changes no bit of a jittered march: the leaps
// ask for the run that holds each sample, not the one that holds its step's
// front. Zero (transparent) up to x = 8, 100 beyond, so the macro cell
// [0, 8] is empty and [8, 16] is not; steps of 3 from x = 0: the step
// [6, 9] has its sample at 6 + 3u, past the empty run's end at 8 when
// u > 2/3 (s > 10 there once u > 0.7). A march that asked at the step's
// front leapt over that sample (up to 1.3e-3 on 6 pixels of the engine at
// 512 x 512, step 0.5, seed 7, before).
TEST(RiemannJitter, SkippingChangesNoBit) {
  const auto vol = test::volume_from({20, 3, 3}, [](double x, double, double) { return x <= 8 ? 0.0 : 100.0; });
  const TransferFunction tf({{0, 1, 1, 1, 0}, {10, 1, 1, 1, 0}, {100, 1, 0.5, 0.2, 2}});
  const Ray ray{{-1, 1.2, 1.3}, {1, 0, 0}};
  int late = 0;  // seeds whose sample of [6, 9] lies past x = 8.1
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    late += detail::jitter_fraction(ray, seed) > 0.7 ? 1 : 0;
    for (const bool float_math : {false, true}) {
      const RiemannIntegrator plain(vol, tf, 3.0, {}, {.skip_empty = false, .float_math = float_math}, seed);
      const RiemannIntegrator skip(vol, tf, 3.0, {}, {.skip_empty = true, .float_math = float_math}, seed);
      EXPECT_EQ(plain.integrate(ray), skip.integrate(ray)) << seed << (float_math ? " float" : " double");
    }
  }
  EXPECT_GT(late, 3);
}

// Over u the sum of the optical depth is exact in expectation (the mean of
// f(t_k + u h) over u is f's mean over the step): on tau = x / 8 over
// x in [0, 8] (depth 4) the plain left sum at step 2 gives 3, the mean over
// 4096 seeds 4 to within its standard error.
TEST(RiemannJitter, OpticalDepthIsExactInExpectation) {
  const auto vol = test::volume_from({9, 2, 2}, [](double x, double, double) { return x; });
  const TransferFunction tf({{0, 1, 1, 1, 0}, {8, 1, 1, 1, 1}});
  const Ray ray{{-1, 0.25, 0.25}, {1, 0, 0}};
  auto depth = [](const Rgba& c) { return -std::log1p(-c[3]); };
  EXPECT_NEAR(depth(RiemannIntegrator(vol, tf, 2.0, {}, kDouble).integrate(ray)), 3.0, 1e-12);
  double sum = 0;
  constexpr int kSeeds = 4096;
  for (int seed = 0; seed < kSeeds; ++seed)
    sum += depth(RiemannIntegrator(vol, tf, 2.0, {}, kDouble, seed).integrate(ray));
  // One draw is 3 + 2u, uniform on [3, 5]: the mean's standard error is 1 / sqrt(3 kSeeds).
  EXPECT_NEAR(sum / kSeeds, 4.0, 4 / std::sqrt(3.0 * kSeeds));
}

Scene marschner_lobb_scene(int size) {
  Scene scene = load_scene(test::source_path("scenes/marschner_lobb.json"));
  scene.camera.width = scene.camera.height = size;
  return scene;
}

Image render_riemann(const Scene& scene, double step, std::optional<std::uint64_t> seed, bool float_math,
                     int threads) {
  MethodSpec m;
  m.name = "riemann";
  m.step = step;
  m.jitter = seed;
  m.fast.float_math = float_math;
  const auto integrator = make_integrator(m, scene.grid(), scene.transfer_function, scene.lighting);
  return render(Camera(scene.camera), *integrator, {.threads = threads});
}

// The same bytes for any thread count and from packets or ray by ray; the
// float path within float rounding of the double one; another seed, another image.
TEST(RiemannJitter, DeterministicAndTheSameOnEveryPath) {
  const Scene scene = marschner_lobb_scene(64);
  const Image one = render_riemann(scene, 2, 3, true, 1), two = render_riemann(scene, 2, 3, true, 2);
  EXPECT_EQ(test::pixels(one), test::pixels(two));
  const Image dbl = render_riemann(scene, 2, 3, false, 2);
  double max_diff = 0;
  for (std::size_t i = 0; i < one.data().size(); ++i)
    max_diff = std::max(max_diff, double(std::abs(one.data()[i] - dbl.data()[i])));
  EXPECT_LT(max_diff, 1e-4);
  EXPECT_NE(test::pixels(render_riemann(scene, 2, 4, true, 2)), test::pixels(one));
  EXPECT_NE(test::pixels(render_riemann(scene, 2, std::nullopt, true, 2)), test::pixels(one));
}

// Rings are an error shared by neighbouring pixels (samples at the same
// depths behind the box face); jitter makes it differ from pixel to pixel.
// Against exact at step 2 on Marschner-Lobb (96 x 96), the correlation of
// the error with the next pixel's falls from 0.44 to about 0 (noise), and
// the error itself falls too (51 to 40, summed over the image).
TEST(RiemannJitter, TurnsRingsIntoNoise) {
  const Scene scene = marschner_lobb_scene(96);
  const Image exact = render(Camera(scene.camera), ExactIntegrator(scene.grid(), scene.transfer_function, 1e-6));
  struct Stats {
    double error, correlation;
  };
  auto stats = [&](const Image& image) {
    const int W = image.width(), H = image.height();
    auto e = [&](int x, int y) { return double(image.pixel(x, y)[1]) - exact.pixel(x, y)[1]; };
    double sum = 0, sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
    int n = 0;
    for (int y = 0; y < H; ++y)
      for (int x = 0; x + 1 < W; ++x) {
        if (exact.pixel(x, y)[3] < 0.05) continue;  // inside the volume's image
        const double a = e(x, y), b = e(x + 1, y);
        sum += std::abs(a), sa += a, sb += b, saa += a * a, sbb += b * b, sab += a * b, ++n;
      }
    const double cov = sab / n - sa / n * sb / n;
    return Stats{sum, cov / std::sqrt((saa / n - sa / n * sa / n) * (sbb / n - sb / n * sb / n))};
  };
  const Stats plain = stats(render_riemann(scene, 2, std::nullopt, true, 0));
  const Stats jittered = stats(render_riemann(scene, 2, 11, true, 0));
  std::printf("step 2: summed |error| %.1f plain, %.1f jittered; neighbour correlation %.3f plain, %.3f jittered\n",
              plain.error, jittered.error, plain.correlation, jittered.correlation);
  EXPECT_LT(jittered.error, plain.error);
  EXPECT_GT(plain.correlation, 0.3);
  EXPECT_LT(std::abs(jittered.correlation), 0.1);
}

TEST(RiemannJitter, OtherMethodsRefuseIt) {
  Scene scene = marschner_lobb_scene(8);
  for (const char* name : {"preint1", "preint2", "exact", "adaptive"}) {
    MethodSpec m;
    m.name = name;
    m.jitter = 1;
    try {
      make_integrator(m, scene.grid(), scene.transfer_function, scene.lighting);
      ADD_FAILURE() << name;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("jitter applies to riemann only"), std::string::npos) << e.what();
    }
  }
}

TEST(RiemannJitter, SceneKeyIsTheSeed) {
  const std::string text = R"({"volume": {"builtin": "marschner_lobb"},
      "transfer_function": {"points": [[0, 1, 1, 1, 0], [255, 1, 1, 1, 1]]}, "camera": {"fit": true},
      "method": {"name": "riemann", "jitter": 42}})";
  EXPECT_EQ(parse_scene(text, ".", "s").method.jitter, std::optional<std::uint64_t>(42));
  for (const char* bad : {"-1", "1.5", "\"x\"", "1e300"}) {
    std::string t = text;
    t.replace(t.find("42"), 2, bad);
    EXPECT_THROW(parse_scene(t, ".", "s"), Error) << bad;
  }
}

}  // namespace
}  // namespace vri
