// `vri camera`: the printed camera is the one `vri render` uses - a scene
// holding it (eye, target, up; no fit) renders the same bytes as the fitted,
// turned and zoomed original.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_support.hpp"

namespace vri::test {
namespace {

TEST(CameraCommand, PrintsTheCameraRenderUses) {
  TempDir dir;
  const std::string scene = source_path("scenes/bonsai.json");  // "fit", up +y, azimuth, elevation
  const std::string motion = " --width 48 --height 32 --azimuth 25 --elevation -10 --zoom 1.3";
  const ProcessResult printed = run("camera " + scene + motion, dir);
  ASSERT_EQ(printed.code, 0) << printed.err;
  const nlohmann::json camera = nlohmann::json::parse(printed.out);
  EXPECT_EQ(camera["width"], 48);
  EXPECT_EQ(camera["height"], 32);
  EXPECT_EQ(camera["projection"], "perspective");

  nlohmann::json frozen = nlohmann::json::parse(slurp(scene));
  frozen["camera"] = camera;
  frozen["volume"]["file"] = source_path("data/bonsai.nrrd");
  frozen["transfer_function"]["file"] = source_path("presets/bonsai.json");
  write_text(dir / "frozen.json", frozen.dump());
  const std::string flags = " --method preint1 --step 2 --threads 1 -q";
  ASSERT_EQ(run("render " + scene + motion + flags + " -o " + (dir / "a.png").string(), dir).code, 0);
  ASSERT_EQ(run("render " + (dir / "frozen.json").string() + flags + " -o " + (dir / "b.png").string(), dir).code, 0);
  EXPECT_EQ(slurp(dir / "a.png"), slurp(dir / "b.png"));
}

TEST(CameraCommand, RefusesBadScenesWithOneLine) {
  TempDir dir;
  const ProcessResult r = run("camera " + (dir / "missing.json").string(), dir);
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.err.find("missing.json"), std::string::npos) << r.err;
  const ProcessResult z = run("camera " + source_path("scenes/neghip.json") + " --zoom -1", dir);
  EXPECT_NE(z.code, 0);
  EXPECT_NE(z.err.find("zoom"), std::string::npos) << z.err;
}

}  // namespace
}  // namespace vri::test
