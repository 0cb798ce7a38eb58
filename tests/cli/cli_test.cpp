// End-to-end tests of the vri program: real invocations, exit codes, the one
// line on stderr, and no output file left behind on failure.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "cli_support.hpp"
#include "vri/io.hpp"

namespace vri {
namespace {

using test::ProcessResult;
using test::run;
using test::scene_with;
const std::string& kGood = test::kGoodScene;

TEST(Cli, RendersComparesAndOverrides) {
  test::TempDir dir;
  const std::string scene = scene_with(dir, kGood);
  const auto a = dir / "a.npy", b = dir / "b.npy", png = dir / "a.png";
  ProcessResult r = run("render " + scene + " -o " + a.string() + " --threads 2", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  const auto img = read_npy(a);
  EXPECT_EQ(img.shape, (std::vector<std::size_t>{12, 16, 4}));
  r = run("render " + scene + " -o " + b.string() + " --method riemann --step 0.5 --width 16 --height 12", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  r = run("render " + scene + " -o " + b.string() + " --method preint2 --step 0.5 --table-size 16 --iterations 4", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  r = run("render " + scene + " -o " + png.string() + " --width 7 --height 5", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(png));
  const auto csv = dir / "ray.csv", svg = dir / "ray.svg";
  r = run("ray " + scene + " --pixel 8 6 -o " + csv.string() + " --plot " + svg.string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("xi0"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(csv));
  EXPECT_TRUE(std::filesystem::exists(svg));
  r = run("compare " + a.string() + " " + a.string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("a        0.000000"), std::string::npos) << r.out;
  r = run("compare " + a.string() + " " + b.string() + " --tolerance 0", dir);
  ASSERT_EQ(r.code, 1) << "pixels over the tolerance: exit 1 (SPEC 11) " << r.err;
  EXPECT_EQ(r.out.find("a        0.000000"), std::string::npos) << "riemann differs from exact: " << r.out;
}

// Each bad input: non-zero exit, exactly one line on stderr, no output file.
// Empty-space skipping changes no byte; early termination reports its bound;
// both can come from the scene too.
TEST(Cli, FastPathFlagsAndSceneKeys) {
  test::TempDir dir;
  const std::string scene = scene_with(dir, kGood);
  const auto a = dir / "a.npy", b = dir / "b.npy";
  for (const char* method : {"riemann", "preint1"}) {
    ASSERT_EQ(run("render " + scene + " -o " + a.string() + " --method " + method, dir).code, 0);
    ASSERT_EQ(run("render " + scene + " -o " + b.string() + " --method " + method + " --no-skip", dir).code, 0);
    EXPECT_EQ(read_npy(a).data, read_npy(b).data) << method;
    const ProcessResult r = run("render " + scene + " -o " + b.string() + " --method " + method + " --termination 0.5", dir);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_NE(r.err.find("early termination below transmittance 0.5: "), std::string::npos) << r.err;
  }
  std::string keyed = kGood;
  keyed.replace(keyed.find(R"("name": "exact")"), 15, R"("name": "riemann", "termination": 0.5, "skip_empty": false)");
  const ProcessResult r = run("render " + scene_with(dir, keyed) + " -o " + a.string(), dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("early termination below transmittance 0.5: "), std::string::npos) << r.err;
}

TEST(Cli, BadInputIsRefusedCleanly) {
  test::TempDir dir;
  const std::string good = scene_with(dir, kGood);
  test::write_text(dir / "broken.json", "{\"volume\": ");
  test::write_text(dir / "unsorted.json", R"({"volume": {"builtin": "sphere", "dims": [8, 8, 8]},
    "transfer_function": {"points": [[1, 1, 1, 1, 1], [0, 1, 1, 1, 1]]},
    "camera": {"eye": [0, 0, 9], "target": [0, 0, 0]}})");
  test::write_text(dir / "huge.json", R"({"volume": {"builtin": "random", "dims": [4096, 4096, 4096]},
    "transfer_function": {"points": [[0, 1, 1, 1, 1]]}, "camera": {"eye": [0, 0, 9], "target": [0, 0, 0]}})");
  test::write_text(dir / "short.raw", std::string(100, 'x'));
  test::write_text(dir / "shortraw.json", R"({"volume": {"file": "short.raw", "dims": [8, 8, 8]},
    "transfer_function": {"points": [[0, 1, 1, 1, 1]]}, "camera": {"eye": [0, 0, 9], "target": [0, 0, 0]}})");
  const auto out = (dir / "out.npy").string();
  const std::vector<std::string> cases = {
      "render " + (dir / "missing.json").string() + " -o " + out,
      "render " + (dir / "broken.json").string() + " -o " + out,
      "render " + (dir / "unsorted.json").string() + " -o " + out,
      "render " + (dir / "huge.json").string() + " -o " + out,
      "render " + (dir / "shortraw.json").string() + " -o " + out,
      "render " + good + " -o " + out + " --method nonsense",
      "render " + good + " -o " + out + " --method riemann --step -1",
      "render " + good + " -o " + out + " --method preint2 --table-size 8 --iterations 0",
      "render " + good + " -o " + out + " --method preint2-dual --table-size 512",
      "render " + good + " -o " + out + " --width 0",
      "render " + good + " -o " + out + " --width 100000 --height 100000",
      "render " + good + " -o " + out + " --tolerance 5",
      "render " + good + " -o " + out + " --threads -3",
      "render " + good + " -o " + out + " --method preint1 --termination 1.5",
      "render " + good + " -o " + out + " --method exact --termination 0.1",
      "render " + good + " -o " + (dir / "out.tiff").string(),
      "render " + good + " -o " + (dir / "no_such_dir" / "x.npy").string(),
      "render " + good,
      "frobnicate",
      "compare " + out + " " + out,
      "ray " + good + " --pixel 0 0 -o " + (dir / "miss.csv").string(),   // misses the volume
      "ray " + good + " --pixel 99 0 -o " + (dir / "far.csv").string(),   // outside the image
      "ray " + good + " --pixel 8 6 -o " + (dir / "r.txt").string(),
  };
  for (const auto& args : cases) {
    const ProcessResult r = run(args, dir);
    EXPECT_NE(r.code, 0) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("vri: error: ", 0), 0u) << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << args;
    for (const char* f : {"miss.csv", "far.csv", "r.txt"}) EXPECT_FALSE(std::filesystem::exists(dir / f)) << args;
  }
  // nothing but stdout/stderr captures was left in the folder
  for (const auto& e : std::filesystem::directory_iterator(dir.path))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

// preint2-dual keeps its own default table size (64) when the command line
// names it over a scene written for another method: the bundled lit scenes
// say "table_size": 256 for preint1, which as a second-order length table
// would need 3 GiB (issue 16, item 5).
TEST(Cli, Preint2DualDefaultsWorkOnEveryBundledGridScene) {
  test::TempDir dir;
  int grids = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::source_path("scenes"))) {
    if (entry.path().filename().string().rfind("blunt_fin", 0) == 0) continue;  // tetrahedral meshes
    const auto out = dir / (entry.path().stem().string() + ".npy");
    const ProcessResult r =
        run("render " + entry.path().string() + " -o " + out.string() + " --method preint2-dual --width 12 --height 12", dir);
    EXPECT_EQ(r.code, 0) << entry.path() << ": " << r.err;
    EXPECT_TRUE(std::filesystem::exists(out)) << entry.path();
    ++grids;
  }
  EXPECT_GE(grids, 14);
}

}  // namespace
}  // namespace vri
