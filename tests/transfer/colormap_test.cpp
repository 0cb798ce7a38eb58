// The named colour maps (vri/transfer_function.hpp) against their dense
// references: matplotlib's 256 entries, VTK's diverging "Cool to Warm",
// ParaView's "Rainbow Uniform" (tests/data/tf/colormap_reference.json, written
// by tools/make_colormaps.py from Debian's matplotlib and python3-vtk9).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

#include "vri/transfer_function.hpp"

namespace vri {
namespace {

constexpr double kTol = 1.0 / 512;

nlohmann::json reference() {
  std::ifstream in(VRI_SOURCE_DIR "/tests/data/tf/colormap_reference.json");
  return nlohmann::json::parse(in);
}

void expect_color(const Colormap& m, double x, double r, double g, double b, double tol = kTol) {
  const auto c = m.at(x);
  EXPECT_NEAR(c[0], r, tol) << m.name << " at " << x;
  EXPECT_NEAR(c[1], g, tol) << m.name << " at " << x;
  EXPECT_NEAR(c[2], b, tol) << m.name << " at " << x;
}

TEST(Colormap, EveryMapReproducesItsDenseReferenceWithin1Over512) {
  const auto ref = reference();
  ASSERT_EQ(ref.size(), colormap_names().size());
  for (const std::string& name : colormap_names()) {
    SCOPED_TRACE(name);
    const Colormap* m = find_colormap(name);
    ASSERT_NE(m, nullptr);
    ASSERT_TRUE(ref.contains(name));
    double worst = 0;
    for (const auto& p : ref[name]["points"]) {
      const auto c = m->at(p[0].get<double>());
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(c[k] - p[k + 1].get<double>()));
    }
    EXPECT_LT(worst, kTol);
    // The points span [0, 1], ascending, inside the colour cube.
    EXPECT_EQ(m->points.front().x, 0.0);
    EXPECT_EQ(m->points.back().x, 1.0);
    for (std::size_t i = 0; i < m->points.size(); ++i) {
      const auto& p = m->points[i];
      if (i > 0) {
        EXPECT_GT(p.x, m->points[i - 1].x);
      }
      for (double v : {p.r, p.g, p.b}) EXPECT_TRUE(v >= 0 && v <= 1);
    }
    // Few pieces: the reason for reducing (generator: 21 to 29; 1 for grayscale).
    EXPECT_LE(m->points.size(), 33u);
  }
}

// matplotlib 3.6.3's entries 0, 64, 128, 255 as matplotlib.colormaps[name](i)
// gives them; vri places entry i at x = i/255 (as ParaView's "(matplotlib)"
// presets do), and matplotlib's cmap(i/255) is entry i too.
TEST(Colormap, MatplotlibEntriesAtIOver255) {
  struct Sample {
    const char* map;
    int entry;
    double r, g, b;
  };
  const Sample samples[] = {
      {"viridis", 0, 0.267004, 0.004874, 0.329415},   {"viridis", 64, 0.229739, 0.322361, 0.545706},
      {"viridis", 128, 0.127568, 0.566949, 0.550556}, {"viridis", 255, 0.993248, 0.906157, 0.143936},
      {"magma", 0, 0.001462, 0.000466, 0.013866},     {"magma", 64, 0.316654, 0.07169, 0.48538},
      {"magma", 128, 0.716387, 0.214982, 0.47529},    {"magma", 255, 0.987053, 0.991438, 0.749504},
      {"inferno", 0, 0.001462, 0.000466, 0.013866},   {"inferno", 64, 0.3415, 0.062325, 0.429425},
      {"inferno", 128, 0.735683, 0.215906, 0.330245}, {"inferno", 255, 0.988362, 0.998364, 0.644924},
      {"plasma", 0, 0.050383, 0.029803, 0.527975},    {"plasma", 64, 0.494877, 0.01199, 0.657865},
      {"plasma", 128, 0.798216, 0.280197, 0.469538},  {"plasma", 255, 0.940015, 0.975158, 0.131326},
      {"cividis", 0, 0.0, 0.135112, 0.304751},        {"cividis", 64, 0.263738, 0.307831, 0.422789},
      {"cividis", 128, 0.488697, 0.485318, 0.471008}, {"cividis", 255, 0.995737, 0.909344, 0.217772},
  };
  for (const auto& s : samples) expect_color(*find_colormap(s.map), s.entry / 255.0, s.r, s.g, s.b);
  // The ends are kept exactly.
  expect_color(*find_colormap("viridis"), 0, 0.267004, 0.004874, 0.329415, 0);
  expect_color(*find_colormap("viridis"), 1, 0.993248, 0.906157, 0.143936, 0);
}

TEST(Colormap, CoolToWarmIsVtksDivergingMap) {
  const Colormap& m = *find_colormap("cool_to_warm");
  // VTK 9.1 vtkColorTransferFunction, SetColorSpaceToDiverging, 0 -> (0.231373,
  // 0.298039, 0.752941), 1 -> (0.705882, 0.0156863, 0.14902): GetColor(0.5), (0.25).
  expect_color(m, 0.5, 0.8653951965183807, 0.8654102100698873, 0.8653955608359496);
  expect_color(m, 0.25, 0.5533181413379932, 0.6886345213333457, 0.9951879148673727);
  // At 0 VTK gives the node's colour; at 1 the Lab round trip of the other end
  // (its formulas' constants are not exact inverses), which vri keeps.
  expect_color(m, 0, 0.231373, 0.298039, 0.752941, 1e-15);
  expect_color(m, 1, 0.7058796931083611, 0.015812728299754632, 0.14902112591054137, 1e-15);
}

TEST(Colormap, RainbowUniformIsParaViewsPreset) {
  const Colormap& m = *find_colormap("rainbow_uniform");
  // RGBPoints of ParaView's "Rainbow Uniform" (Remoting/Views/ColorMaps.json).
  expect_color(m, 0, 0.02, 0.3813, 0.9981);
  expect_color(m, 0.5, 0.9995285432627147, 0.9995193706781492, 0.0134884641450013);
  expect_color(m, 0.7142857142857143, 0.9994, 0.5773, 0.2172);
  expect_color(m, 1, 0.6837, 0.05, 0.4139);
  // Between two points it is linear in RGB.
  expect_color(m, 0.5 * (0.42857142857142855 + 0.4523809523809524), 0.5 * (0.6439 + 0.762401813),
               0.5 * (0.9773 + 0.984669591), 0.5 * (0.0469 + 0.034600153));
}

TEST(Colormap, GrayscaleIsOnePiece) {
  const Colormap& m = *find_colormap("grayscale");
  ASSERT_EQ(m.points.size(), 2u);
  expect_color(m, 0.3, 0.3, 0.3, 0.3, 1e-15);
}

TEST(Colormap, NamesMatchWithoutCaseSpacesAsUnderscores) {
  EXPECT_EQ(colormap_names(), (std::vector<std::string>{"viridis", "magma", "inferno", "plasma", "cividis", "grayscale",
                                                       "cool_to_warm", "rainbow_uniform"}));
  EXPECT_EQ(find_colormap("VIRIDIS"), find_colormap("viridis"));
  EXPECT_EQ(find_colormap("Cool to Warm")->name, "cool_to_warm");
  EXPECT_EQ(find_colormap("Rainbow-Uniform")->name, "rainbow_uniform");
  EXPECT_EQ(find_colormap("coolwarm"), nullptr);  // one name each
  EXPECT_EQ(find_colormap("jet"), nullptr);
  EXPECT_EQ(find_colormap(""), nullptr);
}

TEST(Colormap, EndColoursHeldOutside) {
  const Colormap& m = *find_colormap("plasma");
  expect_color(m, -3, m.points.front().r, m.points.front().g, m.points.front().b, 0);
  expect_color(m, 7, m.points.back().r, m.points.back().g, m.points.back().b, 0);
  expect_color(m, std::nan(""), m.points.front().r, m.points.front().g, m.points.front().b, 0);
}

}  // namespace
}  // namespace vri
