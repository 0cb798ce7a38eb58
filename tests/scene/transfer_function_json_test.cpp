// The transfer-function forms of issue 20 (src/scene/transfer_function_json.hpp,
// docs/SCENES.md "Transfer functions"): named colour maps with an opacity
// curve, "range" as [lo, hi], "data" or percentiles, rescaled points, and
// every refusal.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "scene/transfer_function_json.hpp"
#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/scene.hpp"
#include "scene/value_range.hpp"
#include "vri/transfer_function.hpp"

namespace vri {
namespace {

const std::string kCamera = R"("camera": {"eye": [20, 20, 60], "target": [20, 20, 20], "width": 8, "height": 6})";

TransferFunction tf_of(const std::string& json, const Volume* volume = nullptr) {
  return parse_transfer_function(json, "tf", volume);
}

// 0, 1, ..., 999 (x + 10 y + 100 z on a 10^3 grid).
Volume ramp() {
  return test::volume_from({10, 10, 10}, [](double x, double y, double z) { return x + 10 * y + 100 * z; });
}

TEST(TransferFunctionJson, ColormapSpreadsOverTheRange) {
  const TransferFunction tf = tf_of(R"({"colormap": "viridis", "range": [10, 20]})");
  EXPECT_EQ(tf.s_lo(), 10);
  EXPECT_EQ(tf.s_hi(), 20);
  const Colormap& m = *find_colormap("viridis");
  for (double x : {0.0, 0.13, 0.5, 0.77, 1.0}) {
    const TfSample v = tf(10 + 10 * x);
    const auto c = m.at(x);
    EXPECT_NEAR(v.r, c[0], 1e-12);
    EXPECT_NEAR(v.g, c[1], 1e-12);
    EXPECT_NEAR(v.b, c[2], 1e-12);
    EXPECT_NEAR(v.tau, x, 1e-12);  // the default opacity: tau 0 -> 1 over the range
  }
  // The colour map's points are the breakpoints (the default ramp adds none).
  EXPECT_EQ(tf.points().size(), m.points.size());
}

TEST(TransferFunctionJson, BreakpointsAreTheUnionOfColourAndOpacity) {
  const TransferFunction tf =
      tf_of(R"({"colormap": "grayscale", "opacity": [[0, 0], [0.3, 0], [1, 0.5]], "range": [0, 100]})");
  EXPECT_EQ(tf.breakpoints(), (std::vector<double>{0, 30, 100}));
  EXPECT_NEAR(tf(30).r, 0.3, 1e-12);  // colour interpolated at the opacity's point
  EXPECT_NEAR(tf(65).tau, 0.25, 1e-12);
  EXPECT_EQ(tf(20).tau, 0);
  // A step in the opacity (two points at one x) stays a step.
  const TransferFunction step =
      tf_of(R"({"colormap": "viridis", "opacity": [[0, 0], [0.5, 0], [0.5, 2], [1, 2]], "range": [0, 1]})");
  EXPECT_EQ(step(0.4999).tau, 0);
  EXPECT_EQ(step(0.5).tau, 2);
  const auto c = find_colormap("viridis")->at(0.5);
  EXPECT_NEAR(step(0.5).g, c[1], 1e-12);
}

TEST(TransferFunctionJson, UnitDistanceMakesOpacityAlpha) {
  const TransferFunction tf =
      tf_of(R"({"colormap": "grayscale", "opacity": [[0, 0], [1, 0.5]], "unit_distance": 2, "range": [0, 1]})");
  EXPECT_NEAR(tf(1).tau, std::log(2.0) / 2, 1e-15);
  EXPECT_NEAR(tf(0.5).tau, std::log(2.0) / 4, 1e-15);  // per point, then linear in tau (SPEC §3)
}

TEST(TransferFunctionJson, DataRangeIsTheVolumesMinAndMax) {
  const Scene s = parse_scene(R"({"volume": {"builtin": "marschner_lobb", "dims": [9, 9, 9]},
                                  "transfer_function": {"colormap": "magma", "range": "data"}, )" + kCamera + "}",
                              ".");
  EXPECT_EQ(s.transfer_function.s_lo(), s.grid().min_value());
  EXPECT_EQ(s.transfer_function.s_hi(), s.grid().max_value());
  // A colour map without "range" is "data".
  const Scene d = parse_scene(R"({"volume": {"builtin": "sphere", "dims": [8, 8, 8]},
                                  "transfer_function": {"colormap": "inferno"}, )" + kCamera + "}",
                              ".");
  EXPECT_EQ(d.transfer_function.s_lo(), d.grid().min_value());
  EXPECT_EQ(d.transfer_function.s_hi(), d.grid().max_value());
  // A mesh's range is its point scalars'.
  const Scene m = parse_scene(R"({"volume": {"builtin": "tetrahedralized", "grid": {"builtin": "sphere", "dims": [6, 6, 6]}},
                                  "transfer_function": {"colormap": "plasma"}, "method": {"name": "tet-raycast"}, )" +
                                  kCamera + "}",
                              ".");
  const auto& scalars = m.mesh().scalars();
  EXPECT_EQ(m.transfer_function.s_lo(), *std::min_element(scalars.begin(), scalars.end()));
  EXPECT_EQ(m.transfer_function.s_hi(), *std::max_element(scalars.begin(), scalars.end()));
}

TEST(TransferFunctionJson, PercentilesOfARamp) {
  const Volume v = ramp();
  // numpy.percentile(numpy.arange(1000), [1, 99]) = [9.99, 989.01]
  const TransferFunction tf = tf_of(R"({"colormap": "cividis", "range": {"percentiles": [1, 99]}})", &v);
  EXPECT_NEAR(tf.s_lo(), 9.99, 1e-9);
  EXPECT_NEAR(tf.s_hi(), 989.01, 1e-9);
  const ValueRange all = percentile_range(v, 0, 100);
  EXPECT_EQ(all.lo, 0);
  EXPECT_EQ(all.hi, 999);
  const ValueRange mid = percentile_range(v, 50, 50);
  EXPECT_DOUBLE_EQ(mid.lo, 499.5);
  // In a scene the volume is the scene's.
  const Scene s = parse_scene(R"({"transfer_function": {"points": [[0, 0, 0, 0, 0], [1, 1, 1, 1, 1]],
                                  "range": {"percentiles": [25, 75]}}, )" + kCamera + "}",
                              ramp(), ".");
  EXPECT_NEAR(s.transfer_function.s_lo(), 249.75, 1e-9);
  EXPECT_NEAR(s.transfer_function.s_hi(), 749.25, 1e-9);
}

// Above 64 Mi samples the percentiles come from a 65536-bin histogram: within one bin.
TEST(TransferFunctionJson, PercentilesOfAHugeVolumeFromTheHistogram) {
  const std::array<int, 3> dims{512, 512, 257};
  const std::size_t slice = 512 * 512, n = slice * 257;
  ASSERT_GT(n, kExactPercentileSamples);
  std::vector<std::uint8_t> samples(n);
  for (std::size_t k = 0; k < 257; ++k)
    std::fill_n(samples.begin() + std::ptrdiff_t(k * slice), slice, std::uint8_t((k * 7) % 256));
  // The exact percentiles from the counts: every value v = (7 k) mod 256 holds one
  // slice, value 0 two (k = 0 and 256).
  std::vector<double> sorted_values;
  for (std::size_t k = 0; k < 257; ++k) sorted_values.push_back(double((k * 7) % 256));
  std::sort(sorted_values.begin(), sorted_values.end());
  const auto exact = [&](double p) {  // numpy's linear rule on the expanded samples
    const double rank = p / 100 * double(n - 1);
    const auto at = [&](std::size_t i) { return sorted_values[i / slice]; };
    const auto k = std::size_t(std::floor(rank));
    return at(k) + (rank - double(k)) * (at(std::min(k + 1, n - 1)) - at(k));
  };
  const Volume v = GridVolume(dims, GridVolume::Samples(std::move(samples)));
  const double bin = 255.0 / kPercentileBins;
  for (const auto& [lo, hi] : {std::pair{1.0, 99.0}, {10.0, 90.0}, {0.0, 100.0}, {37.5, 62.5}}) {
    const ValueRange r = percentile_range(v, lo, hi);
    EXPECT_NEAR(r.lo, exact(lo), bin) << lo;
    EXPECT_NEAR(r.hi, exact(hi), bin) << hi;
  }
}

TEST(TransferFunctionJson, PointsAreRescaledFromTheirSpanOntoTheRange) {
  const TransferFunction tf =
      tf_of(R"({"points": [[0, 0, 0, 0, 0], [10, 1, 0, 0, 1], [20, 1, 1, 1, 3]], "range": [100, 300]})");
  EXPECT_EQ(tf.breakpoints(), (std::vector<double>{100, 200, 300}));
  EXPECT_EQ(tf(200).tau, 1);
  const TransferFunction op = tf_of(
      R"({"opacity_points": [[5, 1, 0, 0, 0], [15, 0, 0, 1, 0.5]], "unit_distance": 2, "range": [-1, 1]})");
  EXPECT_EQ(op.s_lo(), -1);
  EXPECT_EQ(op.s_hi(), 1);
  EXPECT_NEAR(op(1).tau, std::log(2.0) / 2, 1e-15);
  // "data" on points: the preset follows any volume.
  const Volume v = ramp();
  const TransferFunction d = tf_of(R"({"points": [[0, 0, 0, 0, 0], [1, 1, 1, 1, 1]], "range": "data"})", &v);
  EXPECT_EQ(d.s_lo(), 0);
  EXPECT_EQ(d.s_hi(), 999);
  // A single point (no span) lands on the range's low end.
  EXPECT_EQ(tf_of(R"({"points": [[7, 1, 1, 1, 1]], "range": [2, 3]})").s_lo(), 2);
}

TEST(TransferFunctionJson, AConstantVolumeStillGivesATransferFunction) {
  const Volume v = test::volume_from({4, 4, 4}, [](double, double, double) { return 5.0; });
  const TransferFunction tf = tf_of(R"({"colormap": "viridis"})", &v);
  EXPECT_EQ(tf.s_lo(), 5);
  EXPECT_EQ(tf.s_hi(), 5 + 5 * TransferFunctionRequest::kWiden);
}

void expect_refused(const std::string& json, const std::string& fragment, const Volume* volume = nullptr) {
  try {
    tf_of(json, volume);
    ADD_FAILURE() << "accepted: " << json;
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_EQ(msg.rfind("tf", 0), 0u) << msg;
  }
}

TEST(TransferFunctionJson, RefusesWithOneClearLine) {
  expect_refused(R"({"colormap": "jet", "range": [0, 1]})",
                 "tf: colormap: unknown colour map 'jet' (known: viridis, magma, inferno, plasma, cividis, grayscale, "
                 "cool_to_warm, rainbow_uniform)");
  expect_refused(R"({"colormap": 3, "range": [0, 1]})", "tf: colormap: expected a string, found 3");
  expect_refused(R"({"colormap": "viridis", "range": [5, 3]})", "tf: range: lo 5 is above hi 3");
  expect_refused(R"({"colormap": "viridis", "range": [5]})", "tf: range: expected an array of 2 finite numbers");
  expect_refused(R"({"colormap": "viridis", "range": "dta"})",
                 R"(tf: range: expected [lo, hi], "data" or {"percentiles": [p_lo, p_hi]}, found "dta")");
  expect_refused(R"({"colormap": "viridis", "range": {"percentiles": [50, 10]}})",
                 "tf: range.percentiles: expected 0 <= p_lo <= p_hi <= 100, found [50,10]");
  expect_refused(R"({"colormap": "viridis", "range": {"percentiles": [-1, 10]}})", "range.percentiles");
  expect_refused(R"({"colormap": "viridis", "range": {"percentile": [1, 10]}})",
                 "tf: range: expected [lo, hi], \"data\" or");
  expect_refused(R"({"colormap": "viridis", "range": {"percentiles": [1, 10], "bins": 3}})",
                 "tf: range.bins: unknown key (known: percentiles)");
  // Ranges that need the volume, without one (vri table --tf, Python dicts).
  expect_refused(R"({"colormap": "viridis", "range": "data"})", R"(tf: range: "data" needs a volume; give [lo, hi])");
  expect_refused(R"({"points": [[0, 0, 0, 0, 0]], "range": {"percentiles": [1, 99]}})",
                 R"(tf: range: {"percentiles": ...} needs a volume; give [lo, hi])");
  expect_refused(R"({"colormap": "viridis"})", "tf: colormap: without 'range' it spans the volume's data");
  // Opacity curves.
  expect_refused(R"({"colormap": "viridis", "range": [0, 1], "opacity": [[0, 0], [1.5, 1]]})",
                 "tf: opacity[1]: x = 1.5 is outside [0, 1] (a fraction of the range)");
  expect_refused(R"({"colormap": "viridis", "range": [0, 1], "opacity": [[0.5, 0], [0.2, 1]]})",
                 "tf: opacity[1]: x = 0.2 is below the previous 0.5");
  expect_refused(R"({"colormap": "viridis", "range": [0, 1], "opacity": [[0, -1]]})", "tf: opacity[0]: tau must be >= 0");
  expect_refused(R"({"colormap": "viridis", "range": [0, 1], "opacity": [[0, 0], [1, 1]], "unit_distance": 1})",
                 "tf: opacity[1]: alpha must be in [0, 1) (1 is opaque at any distance), got 1");
  expect_refused(R"({"colormap": "viridis", "range": [0, 1], "opacity": [[0, 0.1]], "unit_distance": 0})",
                 "tf: unit_distance: expected a finite number > 0");
  expect_refused(R"({"colormap": "viridis", "range": [0, 1], "opacity": []})", "tf: opacity: expected a non-empty array");
  expect_refused(R"({"colormap": "viridis", "range": [0, 1], "opacity": [[0, 1, 2]]})",
                 "tf: opacity[0]: expected an array of 2 finite numbers");
  // Keys that do not go together, and typos.
  expect_refused(R"({"colormap": "viridis", "points": [[0, 0, 0, 0, 0]]})",
                 "tf: give one of 'points', 'opacity_points', 'colormap' and 'paraview', not both 'points' and 'colormap'");
  expect_refused(R"({"range": [0, 1]})", "tf: needs 'points', 'opacity_points', 'colormap' or 'paraview'");
  expect_refused(R"({"colormap": "viridis", "name": "x", "range": [0, 1]})", "tf: name: applies to 'paraview' only");
  expect_refused(R"({"points": [[0, 0, 0, 0, 0]], "opacity": [[0, 1]]})", "tf: opacity: applies to 'colormap' and 'paraview'");
  expect_refused(R"({"colormap": "viridis", "range": [0, 1], "unit_distance": 1})",
                 "tf: unit_distance: applies to 'opacity_points' and 'opacity'");
  expect_refused(R"({"colourmap": "viridis"})", "tf: colourmap: unknown key (did you mean 'colormap'?)");
  expect_refused(R"({"points": [[0, 0, 0, 0, 0]], "file": "x.json"})", "tf: file: unknown key");
  expect_refused(R"([1])", "tf: expected a JSON object");
  // The ParaView form names its key and the file.
  expect_refused(R"({"paraview": 7})", "tf: paraview: expected a string, found 7");
  const std::string presets = test::source_path("tests/data/tf/paraview_presets.json");
  expect_refused(R"({"paraview": ")" + presets + R"("})",
                 "tf: paraview: ParaView colour map '" + presets + "': holds 7 presets; say which with \"name\": 'Lab Ramp', 'Diverging Pair'");
  expect_refused(R"({"paraview": ")" + presets + R"(", "name": "Nope"})", "no preset named 'Nope' (it holds 'Lab Ramp'");
}

TEST(TransferFunctionJson, SceneErrorsNameTheSceneAndKey) {
  try {
    parse_scene(R"({"volume": {"builtin": "sphere", "dims": [8, 8, 8]}, "transfer_function": {"colormap": "virdis"}, )" +
                    kCamera + "}",
                ".", "scene 'a.json'");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("scene 'a.json': transfer_function.colormap: unknown colour map 'virdis'", 0), 0u)
        << e.what();
  }
}

TEST(TransferFunctionJson, ParaviewPathsAreRelativeToTheFileThatNamesThem) {
  test::TempDir dir;
  std::filesystem::create_directories(dir.path / "tf");
  std::filesystem::copy_file(test::source_path("tests/data/tf/paraview_single.json"), dir.path / "tf/cm.json");
  test::write_text(dir.path / "tf/t.json", R"({"paraview": "cm.json", "range": [0, 1]})");
  const TransferFunction tf = load_transfer_function(dir.path / "tf/t.json");
  EXPECT_EQ(tf.s_hi(), 1);
  test::write_text(dir.path / "s.json", R"({"volume": {"builtin": "sphere", "dims": [8, 8, 8]},
      "transfer_function": {"paraview": "tf/cm.json", "range": "data"}, )" + kCamera + "}");
  const Scene s = load_scene(dir.path / "s.json");
  EXPECT_EQ(s.transfer_function.s_lo(), s.grid().min_value());
  test::write_text(dir.path / "s2.json", R"({"volume": {"builtin": "sphere", "dims": [8, 8, 8]},
      "transfer_function": {"file": "tf/t.json"}, )" + kCamera + "}");
  EXPECT_EQ(load_scene(dir.path / "s2.json").transfer_function.s_hi(), 1);
  // A transfer-function file asking for "data" takes the scene's volume.
  test::write_text(dir.path / "tf/d.json", R"({"colormap": "viridis", "range": "data"})");
  test::write_text(dir.path / "s3.json", R"({"volume": {"builtin": "sphere", "dims": [8, 8, 8]},
      "transfer_function": {"file": "tf/d.json"}, )" + kCamera + "}");
  const Scene s3 = load_scene(dir.path / "s3.json");
  EXPECT_EQ(s3.transfer_function.s_hi(), s3.grid().max_value());
  // ... and without one says so.
  try {
    load_transfer_function(dir.path / "tf/d.json");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("d.json': range: \"data\" needs a volume; give [lo, hi]"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace vri
