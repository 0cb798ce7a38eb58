// `vri turntable`: frame i is the scene turned by 360 i / N degrees, the same
// PNG bytes as `vri render --azimuth`; bad requests write nothing.
#include <gtest/gtest.h>

#include "cli/cli_support.hpp"

namespace vri::test {
namespace {

const std::string kFlags = " --method preint1 --width 40 --height 30 --threads 1 -q";

TEST(Turntable, FramesAreRendersTurnedAboutUp) {
  TempDir dir;
  const std::string scene = source_path("scenes/neghip.json");
  const ProcessResult r = run("turntable " + scene + " --frames 6 -o " + (dir / "orbit").string() + kFlags, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  for (int i = 0; i < 6; ++i) {
    const auto png = dir / "orbit" / ("frame_000" + std::to_string(i) + ".png");
    ASSERT_TRUE(std::filesystem::exists(png)) << png;
    const auto single = dir / ("single" + std::to_string(i) + ".png");
    ASSERT_EQ(run("render " + scene + " -o " + single.string() + " --azimuth " + std::to_string(60 * i) + kFlags, dir)
                  .code,
              0);
    EXPECT_EQ(slurp(png), slurp(single)) << i;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "orbit" / "frame_0006.png"));
  EXPECT_NE(slurp(dir / "orbit" / "frame_0000.png"), slurp(dir / "orbit" / "frame_0001.png"));
}

TEST(Turntable, DegreesJitterAndAlphaReachEveryFrame) {
  TempDir dir;
  const std::string scene = source_path("scenes/marschner_lobb.json");
  const std::string flags = " --method riemann --step 2 --jitter 9 --background none --width 24 --height 24 -q";
  ASSERT_EQ(run("turntable " + scene + " --frames 3 --degrees 90 -o " + (dir / "o").string() + flags, dir).code, 0);
  ASSERT_EQ(run("render " + scene + " -o " + (dir / "f2.png").string() + " --azimuth 60" + flags, dir).code, 0);
  EXPECT_EQ(slurp(dir / "o" / "frame_0002.png"), slurp(dir / "f2.png"));
}

TEST(Turntable, RefusesBadRequestsAndWritesNothing) {
  TempDir dir;
  const std::string scene = source_path("scenes/neghip.json");
  const struct {
    std::string args, message;
  } cases[] = {
      {" --frames 0 -o " + (dir / "a").string(), "--frames must be"},
      {" --frames 2 -o " + (dir / "a.png").string(), "must be a folder"},
      {" --frames 2 -o " + (dir / "a.mp4").string() + " --background none", "not to video"},
      {" --frames 2 -o " + (dir / "a").string() + " --method preint1 --jitter 1", "jitter applies to riemann only"},
      {" --frames 2 -o " + (dir / "a").string() + " --degrees nan", "finite"},
  };
  for (const auto& c : cases) {
    const ProcessResult r = run("turntable " + scene + c.args + " --width 8 --height 8 -q", dir);
    EXPECT_EQ(r.code, 1) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << ": " << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "a")) << c.args;
    EXPECT_FALSE(std::filesystem::exists(dir / "a.mp4")) << c.args;
  }
  write_text(dir / "file", "x");
  const ProcessResult r = run("turntable " + scene + " --frames 2 -o " + (dir / "file").string() + kFlags, dir);
  EXPECT_NE(r.err.find("is not a folder"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace vri::test
