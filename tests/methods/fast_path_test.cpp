// The fast path of riemann, preint1, preint2 and preint2-dual (fast_path.hpp)
// against the plain one, pixel by pixel: empty-space skipping changes no bit
// (on the float paths of the first three and on every double path), early termination
// changes a pixel by at most its threshold, the float paths stay within 1e-4
// per channel of the double paths, their packets of rays give the bytes of
// their scalar marches, and all give the same bytes with any thread count.
#include "methods/fast_path.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <typeinfo>
#include <vector>

#include "methods/march/float_packet.hpp"
#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"
#include "vri/render.hpp"  // termination_bound
#include "vri/scene.hpp"
#include "tables/zero_opacity.hpp"
#include "volume/builtin_volumes.hpp"
#include "volume/empty_space.hpp"
#include "volume/macro_cells.hpp"
#include "volume/transparent_cells.hpp"

namespace vri {
namespace {

Image render_with(const Scene& scene, MethodSpec spec, const FastPath& fast, const Lighting& lighting = {},
                  const RenderOptions& options = {}) {
  spec.fast = fast;
  const auto integrator = make_integrator(spec, scene.grid(), scene.transfer_function, lighting);
  return render(Camera(scene.camera), *integrator, options);
}

Scene small(const std::string& scene_file, int size) {
  Scene scene = load_scene(test::source_path(scene_file));
  scene.camera.width = scene.camera.height = size;
  return scene;
}

const FastPath kPlain{.skip_empty = false};
const FastPath kSkip{.skip_empty = true};
const FastPath kPlainDouble{.skip_empty = false, .float_math = false};
const FastPath kSkipDouble{.skip_empty = true, .float_math = false};

double max_difference(const Image& a, const Image& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.data().size(); ++i) worst = std::max(worst, std::abs(double(a.data()[i]) - b.data()[i]));
  return worst;
}

void expect_same_bytes(const Image& a, const Image& b, const std::string& what) {
  ASSERT_EQ(a.data().size(), b.data().size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.data().size(); ++i) differ += a.data()[i] != b.data()[i] ? 1 : 0;
  EXPECT_EQ(differ, 0u) << what;
}

TEST(FastPath, SkippingChangesNoBitOnNeghip) {
  const Scene scene = small("scenes/neghip.json", 96);
  for (const char* name : {"riemann", "preint1"})
    for (double step : {1.0, 0.37}) {
      const MethodSpec spec{.name = name, .step = step};
      expect_same_bytes(render_with(scene, spec, kPlain), render_with(scene, spec, kSkip),
                        std::string(name) + " step " + std::to_string(step));
    }
  for (const char* name : {"riemann", "preint1"})
    for (double step : {1.0, 0.37}) {
      const MethodSpec spec{.name = name, .step = step};
      expect_same_bytes(render_with(scene, spec, kPlainDouble), render_with(scene, spec, kSkipDouble),
                        std::string(name) + " double step " + std::to_string(step));
    }
}

// preint2's slabs of two steps, whose parabolas reach beyond their samples
// (cells classified with TableOrder::Second), with either table builder.
TEST(FastPath, Preint2SkippingChangesNoBitOnNeghip) {
  const Scene scene = small("scenes/neghip.json", 64);
  for (const char* builder : {"fast", "plain"})
    for (double step : {1.0, 0.37}) {
      const MethodSpec spec{.name = "preint2", .step = step, .table_size = 64, .iterations = 16, .builder = builder};
      expect_same_bytes(render_with(scene, spec, kPlain), render_with(scene, spec, kSkip),
                        std::string("preint2 ") + builder + " step " + std::to_string(step));
      expect_same_bytes(render_with(scene, spec, kPlainDouble), render_with(scene, spec, kSkipDouble),
                        std::string("preint2 double ") + builder + " step " + std::to_string(step));
    }
}

// preint2-dual's cell segments: a segment inside a run of empty macro cells is
// not sampled, and the next one takes its front at the same position; on the
// float path neither is a segment of a transparent cell inside a non-empty
// macro cell (classified for second-order entries, as the integrator does:
// many such cells on both volumes).
TEST(FastPath, Preint2DualSkippingChangesNoBit) {
  for (const char* file : {"scenes/neghip.json", "scenes/bonsai.json"}) {
    const Scene scene = small(file, 48);
    const GridVolume& volume = scene.grid();
    const ZeroOpacity zero(DiscreteTf(scene.transfer_function, 32), TableOrder::Second);
    const MacroCells macro(volume);
    const EmptySpace space(macro, zero);
    const double margin = interpolation_margin(volume);
    const TransparentCells cells(volume, space, ZeroOpacityBins(zero, volume.min_value() - margin, volume.max_value() + margin),
                                 margin);
    EXPECT_GT(cells.count(), 1000u) << file;
    const MethodSpec spec{.name = "preint2-dual", .table_size = 32, .table_size_given = true, .iterations = 8};
    expect_same_bytes(render_with(scene, spec, kPlain), render_with(scene, spec, kSkip), file);
    expect_same_bytes(render_with(scene, spec, kPlainDouble), render_with(scene, spec, kSkipDouble),
                      std::string(file) + " double");
  }
  const Scene scene = small("scenes/neghip_lit.json", 40);
  Lighting lighting = scene.lighting;
  for (const char* mode : {"sampled", "interpolated"}) {
    lighting.mode = mode;
    const MethodSpec spec{.name = "preint2-dual", .table_size = 24, .table_size_given = true, .iterations = 8};
    expect_same_bytes(render_with(scene, spec, kPlain, lighting), render_with(scene, spec, kSkip, lighting),
                      std::string("preint2-dual ") + mode);
  }
}

// fuel at preint2-dual's 64-entry table: its transfer function leaves zero
// at 10, inside the bin 8.1..12.1, which ends the zero run at the table
// scalar 8.1 (ZeroOpacity, TableOrder::Second); its background of zeros then
// lies (b - a)/8 inside that run, so most macro cells are empty and skipped,
// and the image keeps its bytes.
TEST(FastPath, Preint2DualSkipsFuelsBackgroundAtItsDefaultTable) {
  const Scene scene = small("scenes/fuel.json", 48);
  const MacroCells cells(scene.grid());
  const EmptySpace space(cells, ZeroOpacity(DiscreteTf(scene.transfer_function, 64), TableOrder::Second));
  EXPECT_GT(space.empty_count(), cells.count() * 8 / 10);
  const MethodSpec spec{.name = "preint2-dual", .iterations = 8};
  expect_same_bytes(render_with(scene, spec, kPlain), render_with(scene, spec, kSkip), "fuel");
  expect_same_bytes(render_with(scene, spec, kPlainDouble), render_with(scene, spec, kSkipDouble), "fuel double");
}

TEST(FastPath, SkippingChangesNoBitWithLighting) {
  const Scene scene = small("scenes/neghip_lit.json", 64);
  Lighting lighting = scene.lighting;
  for (const char* mode : {"sampled", "interpolated"}) {
    lighting.mode = mode;
    const MethodSpec spec{.name = "preint1", .step = 1};
    expect_same_bytes(render_with(scene, spec, kPlain, lighting), render_with(scene, spec, kSkip, lighting),
                      std::string("preint1 ") + mode);
    expect_same_bytes(render_with(scene, spec, kPlainDouble, lighting),
                      render_with(scene, spec, kSkipDouble, lighting), std::string("preint1 double ") + mode);
  }
  for (const char* mode : {"sampled", "interpolated"}) {
    lighting.mode = mode;
    const MethodSpec spec{.name = "preint2", .step = 1, .table_size = 48, .iterations = 16};
    expect_same_bytes(render_with(scene, spec, kPlain, lighting), render_with(scene, spec, kSkip, lighting),
                      std::string("preint2 ") + mode);
  }
  const MethodSpec spec{.name = "riemann", .step = 0.5};
  expect_same_bytes(render_with(scene, spec, kPlain, lighting), render_with(scene, spec, kSkip, lighting),
                    "riemann lit");
}

// Every table builder leaves exact zeros where the transfer function is empty.
TEST(FastPath, SkippingChangesNoBitWithAnyTableBuilder) {
  const Scene scene = small("scenes/neghip.json", 48);
  for (const char* builder : {"brute", "incremental", "sliced", "engel"}) {
    const MethodSpec spec{.name = "preint1", .step = 1, .table_size = 128, .builder = builder};
    expect_same_bytes(render_with(scene, spec, kPlain), render_with(scene, spec, kSkip), builder);
  }
}

// A shell around a sphere, dims not multiples of 8, through random transfer
// functions (runs of zero opacity, spikes, steps), seen head-on along z by an
// orthographic camera whose rays and samples lie on grid planes and macro-cell
// faces, and from an oblique perspective camera.
TEST(FastPath, SkippingChangesNoBitOnRandomTransferFunctionsAndAlignedRays) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 4; ++trial) {
    Scene scene{sphere_distance({37, 45, 29}, 12), test::random_tf(rng, 20, 0.5), {}, {}, {0, 0, 0}, {}};
    // scalars span [-12, 20]; shift the function so some runs fall on the data
    std::vector<ControlPoint> points = scene.transfer_function.points();
    for (auto& p : points) p.s -= 12;
    scene.transfer_function = TransferFunction(points);
    scene.camera.width = scene.camera.height = 40;
    scene.camera.projection = Projection::Orthographic;
    scene.camera.eye = {18.5, 22.5, 60};
    scene.camera.target = {18.5, 22.5, 0};
    scene.camera.ortho_height = 40;  // 40 pixels 1 apart: rays at whole x and y, samples at whole z
    for (int view = 0; view < 2; ++view) {
      if (view == 1) {
        scene.camera.projection = Projection::Perspective;
        scene.camera.eye = {80, -40, 50};
        scene.camera.target = {18, 22, 14};
        scene.camera.up = {0, 0, 1};
      }
      // (preint2-dual's packets leap over the empty runs: the segments after
      // a leap must be the plain walk's.)
      for (const char* name : {"riemann", "preint1", "preint2", "preint2-dual"}) {
        const MethodSpec spec{.name = name, .step = 1, .table_size = 32, .table_size_given = true, .iterations = 8};
        expect_same_bytes(render_with(scene, spec, kPlain), render_with(scene, spec, kSkip),
                          std::string(name) + " trial " + std::to_string(trial) + " view " + std::to_string(view));
      }
      for (const char* name : {"riemann", "preint1", "preint2"}) {
        const MethodSpec spec{.name = name, .step = 1, .table_size = 64, .iterations = 16};
        expect_same_bytes(render_with(scene, spec, kPlainDouble), render_with(scene, spec, kSkipDouble),
                          std::string(name) + " double trial " + std::to_string(trial) + " view " +
                              std::to_string(view));
      }
    }
  }
}

// Early termination drops at most the remaining transmittance T < threshold:
// alpha changes by less than the threshold, and so does each colour (unlit
// colours are at most 1).
TEST(FastPath, TerminationChangesAPixelByAtMostItsThreshold) {
  const Scene scene = small("scenes/bonsai.json", 40);
  for (const char* name : {"riemann", "preint1", "preint2", "preint2-dual"}) {
    const MethodSpec spec{.name = name, .step = 1, .table_size = 32, .table_size_given = true, .iterations = 8};
    const Image plain = render_with(scene, spec, kPlain);
    for (double eps : {0.3, 0.05}) {
      const Image cut = render_with(scene, spec, {.skip_empty = true, .termination = eps});
      double worst = 0;
      int changed = 0;
      for (std::size_t i = 0; i < plain.data().size(); ++i) {
        const double d = std::abs(double(plain.data()[i]) - cut.data()[i]);
        worst = std::max(worst, d);
        changed += d > 0 ? 1 : 0;
      }
      EXPECT_LE(worst, eps) << name << " " << eps;
      EXPECT_GT(changed, 0) << name << " " << eps;  // it did stop some rays
      const TerminationBound bound = termination_bound(cut, eps);
      EXPECT_GT(bound.pixels, 0);
      EXPECT_LT(bound.max_remaining, eps);
    }
  }
}

// The float paths composite in double (FrontToBack, ray_steps.hpp): what
// parts them from the double path is each sample's float roundings, which do
// not add up along the ray as a float sum did. Engine at fine steps, where
// compositing in float was 8.7e-6 (riemann, h = 0.05) and 2.9e-6 (preint1,
// h = 0.1) from the double path at 48^2, and 3.8e-5 at h = 0.02, 512^2.
TEST(FastPath, FloatPathsCompositeInDouble) {
  const Scene scene = small("scenes/engine.json", 48);
  for (const auto& [name, step] : {std::pair{"riemann", 0.05}, std::pair{"preint1", 0.1}}) {
    const MethodSpec spec{.name = name, .step = step};
    EXPECT_LE(max_difference(render_with(scene, spec, kSkip), render_with(scene, spec, kSkipDouble)), 1e-6) << name;
  }
}

// The float paths of riemann, preint1 and preint2 (float_riemann.hpp,
// float_march.hpp, lit: float_shading.hpp) against their double paths, the reference:
// within 1e-4 per channel on the bundled scenes (neghip at two steps), lit or
// not, and not the same image (the float path is the one taken).
TEST(FastPath, FloatPathIsWithin1e4OfTheDoublePath) {
  for (const char* file : {"scenes/neghip.json", "scenes/engine.json", "scenes/bonsai.json"})
    for (const char* name : {"riemann", "preint1", "preint2", "preint2-dual"}) {
      const Scene scene = small(file, 40);
      for (double step : {1.0, 0.37}) {
        if (step != 1.0 && std::string(file) != "scenes/neghip.json") continue;  // keeps the program under 3 s
        if (step != 1.0 && std::string(name) == "preint2-dual") continue;  // no step
        const MethodSpec spec{.name = name, .step = step, .table_size = 32, .table_size_given = true, .iterations = 8};
        const double worst = max_difference(render_with(scene, spec, kSkip), render_with(scene, spec, kSkipDouble));
        EXPECT_LE(worst, 1e-4) << name << " " << file << " step " << step;
        EXPECT_GT(worst, 0) << name << " " << file << " step " << step;
      }
    }
  // Lit: the scalar samples (both modes) and the table lookups (sampled) in float.
  const Scene scene = small("scenes/neghip_lit.json", 48);
  Lighting lighting = scene.lighting;
  for (const char* mode : {"sampled", "interpolated"}) {
    lighting.mode = mode;
    for (const MethodSpec& spec : {MethodSpec{.name = "preint1", .step = 1},
                                   MethodSpec{.name = "preint2-dual", .table_size = 24, .table_size_given = true,
                                              .iterations = 8}}) {
      const double worst =
          max_difference(render_with(scene, spec, kSkip, lighting), render_with(scene, spec, kSkipDouble, lighting));
      EXPECT_LE(worst, 1e-4) << spec.name << " " << mode;
      EXPECT_GT(worst, 0) << spec.name << " " << mode;
    }
  }
}

// The packets of 8 rays of riemann, preint1, preint2 and unlit preint2-dual
// (float_packet.hpp; render hands 4 x 2 blocks of a tile to integrate_row) against
// integrate, ray by ray: the same bytes, with skipping (preint2-dual's packets
// leap where its scalar march walks), with and without termination. Skipped where
// there are no packets (both would be the scalar march): a build with
// VRI_SIMD off or for another target than x86-64, or a CPU without AVX2.
TEST(FastPath, PacketsGiveTheBytesOfTheScalarFloatPath) {
  if (!detail::packets_available())
    GTEST_SKIP() << "no AVX2 ray packets in this build or on this CPU (src/core/simd.hpp)";
  for (const char* file : {"scenes/neghip.json", "scenes/engine.json", "scenes/bonsai.json"}) {
    const Scene scene = small(file, 32);
    const Camera camera(scene.camera);
    for (const char* name : {"riemann", "preint1", "preint2", "preint2-dual"})
      for (const FastPath& fast : {kSkip, FastPath{.skip_empty = true, .termination = 0.05}}) {
        const bool dual = std::string(name) == "preint2-dual";  // (32 lengths: a smaller table builds faster)
        MethodSpec spec{.name = name, .step = 1, .table_size = dual ? 32 : 64, .table_size_given = true, .iterations = 16};
        spec.fast = fast;
        const auto integrator = make_integrator(spec, scene.grid(), scene.transfer_function);
        const Image packets = render(camera, *integrator, {.threads = 1, .tile_size = 32});
        Image single(camera.width(), camera.height());
        for (int y = 0; y < camera.height(); ++y)
          for (int x = 0; x < camera.width(); ++x) single.set(x, y, integrator->integrate(camera.ray(x, y)));
        expect_same_bytes(packets, single,
                          std::string(name) + " " + file + " termination " + std::to_string(fast.termination));
      }
  }
}

// preint2-dual's packets leap over runs of empty macro cells where its
// scalar march walks every cell: after a leap they must stand where the walk
// stands (the next planes, the segment the run ends in), whatever rounding
// puts the run's end just before or after a cell face. Sparse data (most
// macro cells empty, runs ending on every face), rays from macro faces and
// grid lines along axes, face and space diagonals and at random, in packets
// of 8: each pixel the scalar march's bytes.
TEST(FastPath, DualPacketsLeapToTheWalksNextSegment) {
  if (!detail::packets_available())
    GTEST_SKIP() << "no AVX2 ray packets in this build or on this CPU (src/core/simd.hpp)";
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(0, 1);
  const GridVolume volume =
      test::volume_from({41, 41, 41}, [&](double, double, double) { return u(rng) < 1.4e-3 ? 15.0 + 10 * u(rng) : 0.0; });
  const TransferFunction tf({{10, 1, 0.5, 0.2, 0}, {20, 0.2, 1, 0.5, 0.5}, {30, 0.5, 0.2, 1, 0}, {40, 1, 1, 1, 0}});
  const MethodSpec spec{.name = "preint2-dual", .table_size = 16, .table_size_given = true, .iterations = 4,
                        .fast = kSkip};
  const auto integrator = make_integrator(spec, volume, tf);
  std::vector<Ray> rays;
  for (int k = 0; k < 24000; ++k) rays.push_back(test::ray_along_faces(rng, k));
  std::vector<Rgba> packets(rays.size());
  integrator->integrate_row(rays.data(), static_cast<int>(rays.size()), packets.data());
  int differ = 0, seen = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const Rgba one = integrator->integrate(rays[i]);
    differ += one != packets[i] ? 1 : 0;
    seen += one[3] > 0 ? 1 : 0;
  }
  EXPECT_EQ(differ, 0);
  EXPECT_GT(seen, 500);  // many rays reach matter behind their runs
  // The bundled views at full size: a leap that started the walk again at the
  // skipped segment's front, not its end, changed 2 of neghip's 262144 pixels.
  for (const char* file : {"scenes/neghip.json", "scenes/engine.json"}) {
    const Scene scene = small(file, 512);
    const auto dual = make_integrator({.name = "preint2-dual", .fast = kSkip}, scene.grid(), scene.transfer_function);
    const Camera camera(scene.camera);
    const Image image = render(camera, *dual, {.threads = 2});
    Image single(camera.width(), camera.height());
    for (int y = 0; y < camera.height(); ++y)
      for (int x = 0; x < camera.width(); ++x) single.set(x, y, dual->integrate(camera.ray(x, y)));
    expect_same_bytes(image, single, file);
  }
}

// neghip's samples v mapped to a*v + b in storage type T, and its transfer
// function mapped the same way, beside the float volume of those values.
template <class T>
void expect_storage_gives_float_bytes(double a, double b) {
  const Scene scene = small("scenes/neghip.json", 32);
  const std::vector<float> v = test::floats(scene.grid());
  std::vector<T> typed(v.size());
  std::vector<float> same(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) same[i] = static_cast<float>(typed[i] = static_cast<T>(a * v[i] + b));
  const GridVolume stored(scene.grid().dims(), std::move(typed)), floats(scene.grid().dims(), std::move(same));
  ASSERT_EQ(stored.bytes(), stored.size() * sizeof(T));
  std::vector<ControlPoint> points = scene.transfer_function.points();
  for (ControlPoint& p : points) p.s = a * p.s + b;
  const TransferFunction tf(points);
  const Camera camera(scene.camera);
  for (const char* name : {"riemann", "preint1"}) {
    const MethodSpec spec{.name = name, .step = 1};
    const auto on_stored = make_integrator(spec, stored, tf), on_floats = make_integrator(spec, floats, tf);
    const Image image = render(camera, *on_stored, {.threads = 1});
    EXPECT_GT(max_difference(image, Image(camera.width(), camera.height())), 0.05) << name;  // not blank
    expect_same_bytes(image, render(camera, *on_floats, {.threads = 1}), name + std::string(" ") + typeid(T).name());
    Image single(camera.width(), camera.height());  // preint1: its packets against its scalar march
    for (int y = 0; y < camera.height(); ++y)
      for (int x = 0; x < camera.width(); ++x) single.set(x, y, on_stored->integrate(camera.ray(x, y)));
    expect_same_bytes(image, single, name + std::string(" ray by ray ") + typeid(T).name());
  }
}

TEST(FastPath, EveryStorageTypeGivesTheBytesOfTheFloatVolume) {
  expect_storage_gives_float_bytes<std::uint8_t>(1, 0);
  expect_storage_gives_float_bytes<std::uint16_t>(256, 3);      // both bytes of each sample in use
  expect_storage_gives_float_bytes<std::int16_t>(250, -32000);  // negative and positive samples
}

// The lit float paths (float_shading.hpp, float_march.hpp, dual_march.hpp:
// riemann, and preint1, preint2 and preint2-dual in both modes): within 1e-4
// of the lit double paths, their packets the bytes of their scalar marches,
// skipping exact.
TEST(FastPath, LitFloatPathsAndPackets) {
  const std::pair<const char*, const char*> cases[] = {
      {"riemann", "sampled"},      {"preint1", "sampled"},           {"preint1", "interpolated"},
      {"preint2", "sampled"},      {"preint2", "interpolated"},      {"preint2-dual", "sampled"},
      {"preint2-dual", "interpolated"}};  // riemann has no modes
  for (const char* file : {"scenes/neghip_lit.json", "scenes/marschner_lobb_lit.json"})
    for (const auto& [name, mode] : cases) {
      const Scene scene = small(file, 40);
      Lighting lighting = scene.lighting;
      lighting.mode = mode;
      const std::string what = std::string(name) + " " + mode + " " + file;
      const bool dual = std::string(name) == "preint2-dual";  // (32 lengths: a smaller table builds faster)
      const MethodSpec spec{.name = name, .step = 0.5, .table_size = dual ? 32 : 64, .table_size_given = true,
                            .iterations = 16};
      const Image fast = render_with(scene, spec, kSkip, lighting);
      const double worst = max_difference(fast, render_with(scene, spec, kSkipDouble, lighting));
      EXPECT_LE(worst, 1e-4) << what;
      EXPECT_GT(worst, 0) << what;
      expect_same_bytes(fast, render_with(scene, spec, kPlain, lighting), what + " skipping");
      MethodSpec with_fast = spec;
      with_fast.fast = kSkip;
      const auto integrator = make_integrator(with_fast, scene.grid(), scene.transfer_function, lighting);
      const Camera camera(scene.camera);
      Image single(camera.width(), camera.height());
      for (int y = 0; y < camera.height(); ++y)
        for (int x = 0; x < camera.width(); ++x) single.set(x, y, integrator->integrate(camera.ray(x, y)));
      expect_same_bytes(render(camera, *integrator, {.threads = 1, .tile_size = 40}), single, what + " packets");
    }
}

TEST(FastPath, SameBytesWithAnyThreadCount) {
  const Scene scene = small("scenes/neghip.json", 64);
  for (const char* name : {"riemann", "preint1", "preint2", "preint2-dual"}) {
    const MethodSpec spec{.name = name, .step = 1, .table_size = 32, .table_size_given = true, .iterations = 8};
    const FastPath fast{.skip_empty = true, .termination = 0.02};
    const Image one = render_with(scene, spec, fast, {}, {.threads = 1, .tile_size = 16});
    expect_same_bytes(one, render_with(scene, spec, fast, {}, {.threads = 2, .tile_size = 7}), name);
    expect_same_bytes(one, render_with(scene, spec, fast, {}, {.threads = 3, .tile_size = 64}), name);
  }
}

TEST(FastPath, BadThresholdsAndUnsupportedMethodsAreErrors) {
  const Scene scene = small("scenes/neghip.json", 8);
  for (double bad : {-0.1, 1.0, std::nan("")})
    EXPECT_THROW(render_with(scene, {.name = "preint1"}, {.termination = bad}), Error) << bad;
  EXPECT_THROW(render_with(scene, {.name = "exact"}, {.termination = 0.01}), Error);
  EXPECT_THROW(render_with(scene, {.name = "adaptive"}, {.termination = 0.01}), Error);
  EXPECT_THROW(render_with(scene, {.name = "preint2-dual"}, {.termination = 1.0}), Error);
}

}  // namespace
}  // namespace vri
