// ParaView colour-map import (transfer/paraview_colormap.hpp) against
// VTK's own tables: tools/make_colormaps.py wrote the presets
// (tests/data/tf/paraview_presets.json: Lab, CIELAB, Diverging, HSV with and
// without wrap, Step, RGB with a jump; opacity with midpoint and sharpness) and
// what VTK 9.1's vtkColorTransferFunction and vtkPiecewiseFunction make of
// them (paraview_expected.json).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "vri/scene.hpp"
#include "transfer/paraview_colormap.hpp"

namespace vri {
namespace {

namespace fs = std::filesystem;
const fs::path kTf = VRI_SOURCE_DIR "/tests/data/tf";

nlohmann::json load(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

TransferFunction import(const std::string& file, const std::string& name, const std::string& extra = "") {
  nlohmann::json j = {{"paraview", file}};
  if (!name.empty()) j["name"] = name;
  std::string text = j.dump();
  if (!extra.empty()) text = text.substr(0, text.size() - 1) + ", " + extra + "}";
  return parse_transfer_function(text, "test", nullptr, kTf);
}

// Where a curve steps (two nodes at one x; every node of a Step map; a sharp
// opacity node's midpoint): VTK and vri agree on either side, not on the exact x.
bool near_any(double x, const std::vector<double>& at, double span) {
  for (double a : at)
    if (std::abs(x - a) <= 1e-9 * span) return true;
  return false;
}

TEST(ParaviewColormap, ColoursAndOpacityMatchVtkWithin1Over256) {
  const auto presets = load(kTf / "paraview_presets.json");
  const auto single = load(kTf / "paraview_single.json");
  const auto expected = load(kTf / "paraview_expected.json")["presets"];
  std::vector<std::pair<std::string, nlohmann::json>> all;
  for (const auto& p : presets) all.push_back({"paraview_presets.json", p});
  all.push_back({"paraview_single.json", single[0]});
  ASSERT_EQ(all.size(), expected.size());
  for (const auto& [file, p] : all) {
    const std::string name = p["Name"];
    SCOPED_TRACE(name);
    const TransferFunction tf = import(file, file == "paraview_single.json" ? "" : name);
    const auto& e = expected[name];
    const auto rgb = p["RGBPoints"].get<std::vector<double>>();
    std::vector<double> jumps;
    for (std::size_t i = 0; i + 4 < rgb.size(); i += 4)
      if (rgb[i] == rgb[i + 4] || p["ColorSpace"] == "Step") jumps.insert(jumps.end(), {rgb[i], rgb[i + 4]});
    const double span = rgb[rgb.size() - 4] - rgb[0];
    double worst = 0;
    int compared = 0;
    for (std::size_t k = 0; k < e["x"].size(); ++k) {
      const double x = e["x"][k];
      if (near_any(x, jumps, span)) continue;
      const TfSample v = tf(x);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs((&v.r)[c] - e["rgb"][k][c].get<double>()));
      ++compared;
    }
    EXPECT_LT(worst, 1.0 / 256);
    EXPECT_GT(compared, 190);
    if (!p.contains("Points")) continue;
    const auto pts = p["Points"].get<std::vector<double>>();
    std::vector<double> steps;
    for (std::size_t i = 0; i + 4 < pts.size(); i += 4)
      if (pts[i + 3] > 0.99) steps.push_back(pts[i] + std::clamp(pts[i + 2], 1e-5, 1 - 1e-5) * (pts[i + 4] - pts[i]));
    double worst_alpha = 0;
    for (std::size_t k = 0; k < e["opacity_x"].size(); ++k) {
      const double x = e["opacity_x"][k];
      if (near_any(x, steps, span)) continue;
      worst_alpha = std::max(worst_alpha, std::abs(-std::expm1(-tf(x).tau) - e["alpha"][k].get<double>()));
    }
    EXPECT_LT(worst_alpha, 1.0 / 256);
  }
}

TEST(ParaviewColormap, FewPiecesForLinearMaps) {
  // RGB: the file's own nodes (the jump at 0.5 kept as two points).
  const auto map = parse_paraview_colormap(text_of(kTf / "paraview_presets.json"), "presets", "RGB Jump");
  const auto colors = linear_colors(map);
  ASSERT_EQ(colors.size(), 4u);
  EXPECT_EQ(colors[1].x, 0.5);
  EXPECT_EQ(colors[2].x, 0.5);
  EXPECT_EQ(colors[1].r, 1.0);
  EXPECT_EQ(colors[2].b, 1.0);
  // Collinear RGB nodes merge.
  const auto line = parse_paraview_colormap(
      R"([{"Name": "l", "RGBPoints": [0, 0, 0, 0, 1, 0.25, 0.25, 0.25, 4, 1, 1, 1]}])", "t");
  EXPECT_EQ(linear_colors(line).size(), 2u);
  // A smooth Lab or Diverging curve: tens of pieces, not thousands.
  const auto lab = linear_colors(parse_paraview_colormap(text_of(kTf / "paraview_presets.json"), "presets", "Lab Ramp"));
  EXPECT_LT(lab.size(), 40u);
  EXPECT_GT(lab.size(), 3u);
}

TEST(ParaviewColormap, OpacityCurveIsVtksPiecewiseFunction) {
  // Linear (sharpness 0, midpoint 0.5), the midpoint moved, and a sharp step.
  EXPECT_DOUBLE_EQ(opacity_curve(0.25, 0.2, 0.6, 0.5, 0), 0.3);
  EXPECT_DOUBLE_EQ(opacity_curve(0.2, 0.0, 1.0, 0.2, 0), 0.5);  // reaches the middle value at the midpoint
  EXPECT_EQ(opacity_curve(0.49, 0.1, 0.9, 0.5, 1.0), 0.1);
  EXPECT_EQ(opacity_curve(0.51, 0.1, 0.9, 0.5, 1.0), 0.9);
  // A sharp curve stays within its ends and passes the middle at the midpoint.
  EXPECT_NEAR(opacity_curve(0.3, 0.0, 1.0, 0.3, 0.6), 0.5, 1e-12);
  const auto taus = linear_opacity({{0, 0.0, 0.5, 0}, {1, 0.5, 0.5, 0}});
  EXPECT_EQ(taus.front().tau, 0);
  EXPECT_NEAR(taus.back().tau, std::log(2.0), 1e-15);
  EXPECT_GT(taus.size(), 2u);  // linear in alpha is not linear in tau: more points
}

TEST(ParaviewColormap, RangeRescalesTheFilesSpan) {
  const TransferFunction own = import("paraview_presets.json", "Lab Ramp");
  EXPECT_EQ(own.s_lo(), -50);
  EXPECT_EQ(own.s_hi(), 150);
  const TransferFunction moved = import("paraview_presets.json", "Lab Ramp", R"("range": [0, 1])");
  EXPECT_EQ(moved.s_lo(), 0);
  EXPECT_EQ(moved.s_hi(), 1);
  for (double x : {0.1, 0.37, 0.5, 0.92}) {
    const TfSample a = own(-50 + 200 * x), b = moved(x);
    EXPECT_NEAR(a.r, b.r, 1e-9);
    EXPECT_NEAR(a.g, b.g, 1e-9);
    EXPECT_NEAR(a.tau, b.tau, 1e-9);
  }
}

TEST(ParaviewColormap, OpacityOverrideAndDefault) {
  // "opacity" replaces the file's Points, x a fraction of the RGBPoints' span.
  const TransferFunction tf = import("paraview_presets.json", "Lab Ramp", R"("opacity": [[0, 0], [0.5, 2], [1, 2]])");
  EXPECT_NEAR(tf(-50).tau, 0, 1e-15);
  EXPECT_NEAR(tf(0).tau, 1, 1e-12);
  EXPECT_NEAR(tf(50).tau, 2, 1e-12);
  // No Points: the default ramp, tau 0 -> 1 over the span.
  const TransferFunction steps = import("paraview_presets.json", "Steps");
  EXPECT_NEAR(steps(0).tau, 0, 1e-15);
  EXPECT_NEAR(steps(0.25).tau, 0.25, 1e-12);
  EXPECT_NEAR(steps(1).tau, 1, 1e-15);
}

void expect_error(const std::string& json, const std::string& name, const std::string& part) {
  try {
    parse_paraview_colormap(json, "ParaView colour map 'x.json'", name);
    ADD_FAILURE() << "accepted: " << json;
  } catch (const Error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(part), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_EQ(msg.rfind("ParaView colour map 'x.json': ", 0), 0u) << msg;
  }
}

TEST(ParaviewColormap, RefusesMalformedPresetsWithOneClearLine) {
  const std::string two = R"([{"Name": "A", "RGBPoints": [0, 0, 0, 0]}, {"Name": "B", "RGBPoints": [0, 1, 1, 1]}])";
  expect_error(two, "", "holds 2 presets; say which with \"name\": 'A', 'B'");
  expect_error(two, "C", "no preset named 'C' (it holds 'A', 'B')");
  expect_error("{ nope", "", "malformed JSON");
  expect_error("[]", "", "expected a JSON array of ParaView colour-map presets");
  expect_error("42", "", "expected a JSON array");
  expect_error(R"([{"Name": "A", "RGBPoints": [0, 0, 0, 0, 1, 1, 1]}])", "",
               "preset 'A': RGBPoints: length 7 is not a multiple of 4");
  expect_error(R"([{"Name": "A", "RGBPoints": [1, 0, 0, 0, 0, 1, 1, 1]}])", "",
               "RGBPoints: x must not decrease: point 1 has x = 0 after 1");
  expect_error(R"([{"Name": "A", "RGBPoints": [0, 0, 1.5, 0]}])", "",
               "RGBPoints: point 0: colour component 1.5 is outside [0, 1]");
  expect_error(R"([{"Name": "A", "RGBPoints": [0, 0, "x", 0]}])", "", "RGBPoints[2]: expected a finite number");
  expect_error(R"([{"Name": "A", "RGBPoints": []}])", "", "RGBPoints: expected a non-empty array");
  expect_error(R"([{"Name": "A"}])", "", "preset 'A': has no RGBPoints");
  expect_error(R"([{"Name": "A", "ColorSpace": "Lab/CIEDE2000", "RGBPoints": [0, 0, 0, 0]}])", "",
               "ColorSpace: expected RGB, HSV, Lab, CIELAB, Diverging or Step, found \"Lab/CIEDE2000\" "
               "(not supported)");
  expect_error(R"([{"Name": "A", "ColorSpace": "Jet", "RGBPoints": [0, 0, 0, 0]}])", "", "ColorSpace");
  expect_error(R"([{"Name": "A", "IndexedColors": [1, 0, 0], "RGBPoints": [0, 0, 0, 0]}])", "", "indexed");
  expect_error(R"([{"Name": "A", "UseLogScale": true, "RGBPoints": [1, 0, 0, 0]}])", "", "UseLogScale");
  expect_error(R"([{"Name": "A", "HSVWrap": 2, "RGBPoints": [1, 0, 0, 0]}])", "", "HSVWrap");
  expect_error(R"([{"Name": "A", "RGBPoints": [0, 0, 0, 0], "Points": [0, 0, 0.5]}])", "",
               "Points: length 3 is not a multiple of 4");
  expect_error(R"([{"Name": "A", "RGBPoints": [0, 0, 0, 0], "Points": [0, 1.2, 0.5, 0]}])", "",
               "Points: point 0: alpha 1.2");
  expect_error(R"([{"Name": "A", "RGBPoints": [0, 0, 0, 0], "Points": [0, 0.2, 1.5, 0]}])", "", "midpoint 1.5");
  expect_error(R"([{"Name": "A", "RGBPoints": [0, 0, 0, 0], "Points": [0, 0.2, 0.5, -1]}])", "", "sharpness -1");
  expect_error(R"([{"Name": "A", "RGBPoints": [0, 0, 0, 0], "Points": [1, 0.2, 0.5, 0, 0, 0.2, 0.5, 0]}])", "",
               "Points: x must not decrease");
  // A single object is one preset; a file of one needs no name.
  EXPECT_EQ(parse_paraview_colormap(R"({"Name": "Solo", "RGBPoints": [0, 0, 0, 0]})", "t").name, "Solo");
}

// ParaView's alpha 1 (opaque at any distance) is read as 1 - 2^-24: the
// largest finite extinction, 24 ln 2 per unit distance (issue 51 item 6).
TEST(ParaviewColormap, OpaqueAlphaIsTheLargestFiniteExtinction) {
  test::TempDir dir;
  std::ofstream(dir.path / "opaque.json")
      << R"([{"Name": "O", "RGBPoints": [0, 0, 0, 0, 1, 1, 1, 1], "Points": [0, 0, 0.5, 0, 1, 1, 0.5, 0]}])";
  const TransferFunction tf = parse_transfer_function(R"({"paraview": "opaque.json"})", "tf", nullptr, dir.path);
  EXPECT_DOUBLE_EQ(tf.points().back().tau, 24 * std::log(2.0));
  EXPECT_DOUBLE_EQ(tf.points().front().tau, 0);
  // alpha of the largest extinction: 1 - 2^-24 over a unit distance
  EXPECT_NEAR(-std::expm1(-tf.points().back().tau), 1 - 0x1p-24, 1e-15);
  const TransferFunction given =
      parse_transfer_function(R"({"paraview": "opaque.json", "opacity": [[0, 0], [1, 3]]})", "tf", nullptr, dir.path);
  EXPECT_DOUBLE_EQ(given.points().back().tau, 3);
}

TEST(ParaviewColormap, MissingFileIsAFileErrorNamingTheKey) {
  try {
    parse_transfer_function(R"({"paraview": "nowhere.json"})", "tf", nullptr, kTf);
    ADD_FAILURE();
  } catch (const FileError& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind("tf: paraview: cannot open '", 0), 0u) << msg;
  }
}

}  // namespace
}  // namespace vri
