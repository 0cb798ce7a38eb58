// A volume file where a scene stands (SPEC §12: `vri render VOLUME -o OUT
// [--colormap NAME] [--opacity ramp|sigmoid] [--range data|pLO,pHI|LO,HI]`):
// the same bytes as a scene holding the transfer function `vri info`
// suggests, the fitted camera and preint1; the look's flags change the
// picture and are checked; each problem is one line and exit status 1.
#include <gtest/gtest.h>

#include <string>

#include "cli/cli_support.hpp"

namespace vri::test {
namespace {

const std::string kSize = " --width 40 --height 30 -q";

// The `{"points": ...}` line `vri info FILE` prints.
std::string suggested_tf(const std::string& file, const TempDir& dir) {
  const ProcessResult info = run("info " + file, dir);
  EXPECT_EQ(info.code, 0) << info.err;
  const auto at = info.out.find("{\"points\":");
  return at == std::string::npos ? "" : info.out.substr(at, info.out.find('\n', at) - at);
}

TEST(VolumeRender, IsTheSceneOfTheSuggestedTransferFunction) {
  TempDir dir;
  for (const std::string name : {"data/engine.nrrd", "tests/data/volume/base64_zlib.vti", "data/tetra_mesh_small_ascii.vtk"}) {
    const std::string file = source_path(name);
    const bool mesh = name.find("tetra") != std::string::npos;
    const std::string scene = scene_with(dir, R"({"volume": {"file": ")" + file + R"("}, "transfer_function": )" +
                                                  suggested_tf(file, dir) +
                                                  R"(, "camera": {"fit": true, "width": 512, "height": 512},
                                                      "method": )" +
                                                  (mesh ? R"({"name": "tet-raycast"})" : R"({"name": "preint1", "step": 1})") +
                                                  "}");
    const ProcessResult from_volume = run("render " + file + " -o " + (dir / "v.npy").string() + kSize, dir);
    ASSERT_EQ(from_volume.code, 0) << from_volume.err;
    EXPECT_NE(from_volume.err.find(mesh ? "'tet-raycast'" : "'preint1'"), std::string::npos) << from_volume.err;
    const ProcessResult from_scene = run("render " + scene + " -o " + (dir / "s.npy").string() + kSize, dir);
    ASSERT_EQ(from_scene.code, 0) << from_scene.err;
    EXPECT_TRUE(slurp(dir / "v.npy") == slurp(dir / "s.npy")) << name;
  }
}

TEST(VolumeRender, ColourMapOpacityAndRangeChangeThePicture) {
  TempDir dir;
  const std::string file = source_path("data/engine.nrrd");
  const auto render = [&](const std::string& flags, const std::string& out) {
    const ProcessResult r = run("render " + file + " -o " + (dir / out).string() + kSize + flags, dir);
    EXPECT_EQ(r.code, 0) << flags << ": " << r.err;
    return slurp(dir / out);
  };
  const std::string plain = render("", "plain.npy");
  const std::string viridis = render(" --colormap viridis", "viridis.npy");
  const std::string sigmoid = render(" --colormap viridis --opacity sigmoid", "sigmoid.npy");
  const std::string narrow = render(" --colormap viridis --range p50,p99.5", "narrow.npy");
  const std::string ranged = render(" --range 60,200", "ranged.npy");
  EXPECT_TRUE(viridis != plain);
  EXPECT_TRUE(sigmoid != viridis);
  EXPECT_TRUE(narrow != viridis);
  EXPECT_TRUE(ranged != plain);
  // --range data is the colour map's default: the same bytes.
  EXPECT_TRUE(render(" --colormap viridis --range data", "data.npy") == viridis);
  // The default colour map is ParaView's.
  EXPECT_TRUE(render(" --opacity ramp", "ramp.npy") == render(" --colormap cool_to_warm", "cool.npy"));
}

TEST(VolumeRender, BadLooksAndScenesAreOneLine) {
  TempDir dir;
  const std::string file = source_path("data/engine.nrrd"), out = " -o " + (dir / "x.png").string() + kSize;
  const auto refused = [&](const std::string& args, const std::string& fragment) {
    const ProcessResult r = run(args, dir);
    EXPECT_EQ(r.code, 1) << args;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "x.png")) << args;
  };
  refused("render " + file + out + " --opacity linear", "--opacity: expected ramp or sigmoid, found 'linear'");
  refused("render " + file + out + " --range 5", "--range: expected data, pLO,pHI (percentiles, such as p1,p99) or LO,HI, found '5'");
  refused("render " + file + out + " --range p1,99", "found 'p1,99'");
  refused("render " + file + out + " --colormap virdis", "unknown colour map 'virdis'");
  refused("render " + source_path("scenes/engine.json") + out + " --colormap viridis",
          "--colormap, --opacity and --range apply to a volume file; a scene sets its \"transfer_function\"");
  refused("render " + source_path("data/neghip_64x64x64_uint8.raw") + out, "dims");
}

}  // namespace
}  // namespace vri::test
