// Issue 17 at the command line: parameters that crashed or hung vri, work
// caps, refused non-finite output, strict scene keys, `compare`'s exit
// status, the transparent-image warning and the shape of error messages.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "cli_support.hpp"
#include "vri/io.hpp"

namespace vri {
namespace {

namespace fs = std::filesystem;
using test::ProcessResult;
using test::run;
using test::scene_with;

// Non-zero exit, exactly one line starting "vri: error: " that holds
// `fragment`, and none of `outputs` written.
void expect_refused(const std::string& args, const std::string& fragment, const test::TempDir& dir,
                    std::initializer_list<std::string> outputs = {"out.npy"}) {
  const ProcessResult r = run(args, dir);
  EXPECT_NE(r.code, 0) << args;
  EXPECT_NE(r.code, -1) << "crashed: " << args;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
  EXPECT_EQ(r.err.rfind("vri: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find(fragment), std::string::npos) << args << "\n" << r.err;
  for (const auto& o : outputs) EXPECT_FALSE(fs::exists(dir / o)) << args;
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const auto p = s.find(from);
  EXPECT_NE(p, std::string::npos) << from;
  return s.replace(p, from.size(), to);
}

// The good scene with its transfer function read from `file`.
std::string scene_with_tf_file(const test::TempDir& dir, const fs::path& file) {
  return scene_with(dir, replaced(test::kGoodScene, R"({"points": [[-6, 1, 0.5, 0, 0.5], [0, 0, 0, 1, 0]]})",
                                  R"({"file": ")" + file.string() + R"("})"));
}

// Issue 47, defect 6: 100 000 nested brackets in a scene or a transfer
// function exited 139 (the JSON library's recursive dump, quoting the value).
TEST(CliRobustness, DeepNestingIsRefusedWithOneLine) {
  test::TempDir dir;
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const std::string scene = scene_with(dir, replaced(test::kGoodScene, R"("eye": [5.5, 5.5, 40])", R"("eye": )" + deep));
  expect_refused("render " + scene + " -o " + (dir / "out.npy").string(), "nested deeper than 100 levels", dir);
  const auto tf = dir / "deep_tf.json";
  test::write_text(tf, R"({"points": )" + deep + "}");
  expect_refused("render " + scene_with_tf_file(dir, tf) + " -o " + (dir / "out.npy").string(),
                 "nested deeper than 100 levels", dir);
}

// Issue 47, defect 11: a FIFO given as scene or transfer function blocked
// forever (its open waits for a writer).
TEST(CliRobustness, AFifoIsRefusedNotWaitedOn) {
  test::TempDir dir;
  const fs::path fifo = dir / "fifo.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_refused("render " + fifo.string() + " -o " + (dir / "out.npy").string(), "not a regular file", dir);
  expect_refused("render " + scene_with_tf_file(dir, fifo) + " -o " + (dir / "out.npy").string(), "not a regular file",
                 dir);
}

// Issue 47, defect 12: one check per parameter wherever it is given.
TEST(CliRobustness, BackgroundOrthoHeightAndJitterAreCheckedEverywhere) {
  test::TempDir dir;
  const std::string out = " -o " + (dir / "out.npy").string();
  std::string scene = scene_with(dir, replaced(test::kGoodScene, R"("method":)", R"("background": [1e300, -5, 0.5], "method":)"));
  expect_refused("render " + scene + out, "background", dir);
  scene = scene_with(dir, replaced(test::kGoodScene, R"("width": 16)", R"("ortho_height": -3, "width": 16)"));
  expect_refused("render " + scene + out, "ortho_height", dir);
  scene = scene_with(dir, test::kGoodScene);
  expect_refused("render " + scene + out + " --method riemann --jitter -1",
                 "--jitter: expected an integer seed in [0, 2^53], found '-1'", dir);
  expect_refused("render " + scene + out + " --method riemann --jitter 1.5", "--jitter: expected an integer seed", dir);
  EXPECT_EQ(run("render " + scene + out + " --method riemann --jitter 7", dir).code, 0);
}

// Issue 47 defect 12: one rule per method parameter (check_method_parameter,
// vri/methods.hpp), so a value is refused in the same words from a scene file
// and from its flag; table_size 1, length_samples 1 and planes 0 rendered
// (with methods that do not read them), termination 2 and max_work 0.5 were
// refused in other words or by other checks.
TEST(CliRobustness, EveryMethodParameterHasOneRuleAndOneMessage) {
  test::TempDir dir;
  const std::string out = " -o " + (dir / "out.npy").string();
  struct Bad {
    const char *key, *value, *message;
  };
  for (const Bad& b : {Bad{"step", "-1", "method.step (--step): expected a finite number > 0, found -1"},
                       Bad{"tolerance", "0", "method.tolerance (--tolerance): expected a finite number > 0, found 0"},
                       Bad{"table_size", "1", "method.table_size (--table-size): expected an integer in [2, 4096], found 1"},
                       Bad{"table_size", "5000", "expected an integer in [2, 4096], found 5000"},
                       Bad{"iterations", "0", "method.iterations (--iterations): expected an integer in [1, 4096], found 0"},
                       Bad{"h0", "-2", "method.h0 (--h0): expected a finite number > 0, found -2"},
                       Bad{"hmin", "0", "method.hmin (--hmin): expected a finite number > 0, found 0"},
                       Bad{"hmax", "-1", "method.hmax (--hmax): expected a finite number > 0, found -1"},
                       Bad{"termination", "2", "method.termination (--termination): expected a number in [0, 1), found 2"},
                       Bad{"termination", "-0.5", "expected a number in [0, 1), found -0.5"},
                       Bad{"max_samples", "0.5", "method.max_samples (--max-samples): expected an integer in [1, 2^53], found 0.5"},
                       Bad{"max_work", "0", "method.max_work (--max-work): expected an integer in [1, 2^53], found 0"},
                       Bad{"length_samples", "1", "method.length_samples: expected an integer in [2, 4096], found 1"},
                       Bad{"planes", "1", "method.planes: expected 0 (the table size) or an integer in [2, 16384], found 1"},
                       Bad{"jitter", "-1", "method.jitter (--jitter): expected an integer in [0, 2^53], found -1"}}) {
    SCOPED_TRACE(b.key);
    const std::string given = std::string("\"") + b.key + "\": " + b.value;  // after the good scene's tolerance
    const std::string scene = scene_with(dir, replaced(test::kGoodScene, R"("tolerance": 1e-5)",
                                                       b.key == std::string("tolerance") ? given : R"("tolerance": 1e-5, )" + given));
    expect_refused("render " + scene + out, b.message, dir);
    std::string flag = b.key;
    std::replace(flag.begin(), flag.end(), '_', '-');
    if (flag == "length-samples" || flag == "planes" || flag == "jitter") continue;  // scene keys only, or read as text
    expect_refused("render " + scene_with(dir, test::kGoodScene) + out + " --" + flag + " " + b.value, b.message, dir);
  }
}

// Issue 47 defect 12: a message blames the value given, and prints numbers as
// %g (1e-300, not 0.000000).
TEST(CliRobustness, MessagesNameTheFlagGivenAndPrintItsNumber) {
  test::TempDir dir;
  const std::string scene = scene_with(dir, test::kGoodScene), out = " -o " + (dir / "out.npy").string();
  expect_refused("render " + scene + out + " --zoom 1e-300", "camera zoom 1e-300 makes fov_y 180 degrees", dir);
  expect_refused("render " + scene + out + " --method exact --tolerance 1e-300", "got 1e-300", dir);
  expect_refused("render " + scene + out + " --method riemann --step 1e-300", "method.step 1e-300", dir);
}

TEST(CliRobustness, RayStepMustBeFinite) {  // defect 4
  test::TempDir dir;
  const std::string scene = scene_with(dir, test::kGoodScene);
  expect_refused("ray " + scene + " --pixel 8 6 --step inf -o " + (dir / "r.csv").string(), "--step", dir, {"r.csv"});
  expect_refused("ray " + scene + " --pixel 8 6 --step nan -o " + (dir / "r.csv").string(), "--step", dir, {"r.csv"});
  // a step longer than the ray: one interval, no out-of-bounds read
  const ProcessResult r = run("ray " + scene + " --pixel 8 6 --step 1e300 -o " + (dir / "r.csv").string(), dir);
  EXPECT_EQ(r.code, 0) << r.err;
}

TEST(CliRobustness, RenderParametersMustBeFiniteAndPositive) {  // defect 4, flags
  test::TempDir dir;
  const std::string scene = scene_with(dir, test::kGoodScene), out = (dir / "out.npy").string();
  for (const char* flags : {"--method riemann --step inf", "--method riemann --step nan", "--method riemann --step 0",
                            "--method adaptive --hmin inf", "--method adaptive --h0 -1", "--method adaptive --hmax nan",
                            "--tolerance inf", "--method riemann --termination nan"})
    expect_refused("render " + scene + " -o " + out + " " + flags, "expected", dir);
  // ... and in the scene, naming the key path
  expect_refused("render " + scene_with(dir, replaced(test::kGoodScene, R"("tolerance": 1e-5)", R"("step": -2)"), "s.json") +
                     " -o " + out,
                 "method.step (--step): expected a finite number > 0, found -2", dir);
}

TEST(CliRobustness, ThreadCountIsCapped) {  // defect 5
  test::TempDir dir;
  const std::string scene = scene_with(dir, test::kGoodScene), out = (dir / "out.npy").string();
  expect_refused("render " + scene + " -o " + out + " --threads 10000000", "--threads: expected an integer in [0, 1024]",
                 dir);
  EXPECT_EQ(run("render " + scene + " -o " + out + " --threads 1024", dir).code, 0);
}

TEST(CliRobustness, WorkIsCappedBeforeRendering) {  // defect 11
  test::TempDir dir;
  const std::string out = (dir / "out.npy").string();
  // spacing 1e-6 on one axis: the voxel unit shrinks, 6e7 samples per ray
  const std::string thin = scene_with(
      dir, replaced(replaced(test::kGoodScene, R"("dims": [12, 12, 12]})", R"("dims": [12, 12, 12], "spacing": [1e-6, 1, 1]})"),
                    R"("name": "exact", "tolerance": 1e-5)", R"("name": "riemann", "step": 1)"));
  expect_refused("render " + thin + " -o " + out, "samples per ray", dir);
  expect_refused("render " + thin + " -o " + out, "--max-samples", dir);
  const std::string scene = scene_with(dir, test::kGoodScene, "good.json");
  expect_refused("render " + scene + " -o " + out + " --max-work 1000", "raise it with --max-work", dir);
  EXPECT_EQ(run("render " + scene + " -o " + out + " --max-work 1e6", dir).code, 0);
}

TEST(CliRobustness, NonFiniteImagesAreNotWritten) {  // defect 6
  test::TempDir dir;
  // extinction 1e308: adaptive's error control overflowed to inf and NaN
  // and wrote them with exit 0. Whatever the integrator gives, vri either
  // writes a finite image or refuses with one line and writes nothing.
  const std::string scene = scene_with(
      dir, replaced(test::kGoodScene, R"([[-6, 1, 0.5, 0, 0.5], [0, 0, 0, 1, 0]])",
                    R"([[-6, 1, 1, 1, 1e308], [0, 1, 1, 1, 1e308]])"));
  const auto out = dir / "out.npy";
  const ProcessResult r = run("render " + scene + " -o " + out.string() + " --method adaptive", dir);
  if (r.code == 0) {
    for (float v : read_npy(out).data) ASSERT_TRUE(std::isfinite(v));
  } else {
    EXPECT_EQ(r.err.rfind("vri: error: the rendered image holds ", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("non-finite values"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST(CliRobustness, UnknownSceneKeysSuggestTheNearest) {  // defect 12
  test::TempDir dir;
  const std::string out = (dir / "out.npy").string();
  const std::pair<std::string, std::string> typos[] = {
      {R"("transfer_function")", R"("trasnfer_function")"}, {R"("width")", R"("widht")"},
      {R"("tolerance")", R"("tolerence")"},                  {R"("dims")", R"("dimz")"},
      {R"([0, 0, 0, 1, 0]]})", R"([0, 0, 0, 1, 0]], "pionts": 1})"}};
  for (const auto& [from, to] : typos) {
    const std::string expect = from == R"([0, 0, 0, 1, 0]]})" ? "points" : from.substr(1, from.size() - 2);
    expect_refused("render " + scene_with(dir, replaced(test::kGoodScene, from, to), "typo.json") + " -o " + out,
                   "(did you mean '" + expect + "'?)", dir);
  }
  const std::string lit = replaced(test::kGoodScene, R"("method")", R"("lighting": {"ambiant": 0.2}, "method")");
  expect_refused("render " + scene_with(dir, lit, "lit.json") + " -o " + out, "lighting.ambiant: unknown key (did you mean 'ambient'?)", dir);
}

TEST(CliRobustness, UnknownSecondOrderBuilderIsAnError) {  // defect 12
  test::TempDir dir;
  for (const char* builder : {"fastt", "incremental"}) {
    const std::string scene = scene_with(
        dir, replaced(test::kGoodScene, R"("name": "exact", "tolerance": 1e-5)",
                      std::string(R"("name": "preint2", "table_size": 8, "builder": ")") + builder + "\""));
    expect_refused("render " + scene + " -o " + (dir / "out.npy").string(), "method.builder: expected", dir);
  }
}

TEST(CliRobustness, CompareExitsOneWhenPixelsAreOverTheTolerance) {  // defect 12, SPEC 11
  test::TempDir dir;
  const std::string scene = scene_with(dir, test::kGoodScene);
  const auto a = (dir / "a.npy").string(), b = (dir / "b.npy").string();
  ASSERT_EQ(run("render " + scene + " -o " + a, dir).code, 0);
  ASSERT_EQ(run("render " + scene + " -o " + b + " --method riemann --step 2", dir).code, 0);
  EXPECT_EQ(run("compare " + a + " " + a + " --tolerance 0", dir).code, 0);
  EXPECT_EQ(run("compare " + a + " " + b + " --tolerance 0", dir).code, 1);
  EXPECT_EQ(run("compare " + a + " " + b + " --tolerance 0 --max-share 1", dir).code, 0);
  EXPECT_EQ(run("compare " + a + " " + b + " --tolerance 1", dir).code, 0);
  EXPECT_EQ(run("compare " + a + " " + b + " --max-share 2", dir).code, 2);
}

// Issue 46, class 7 (SPEC §12): 0 within, 1 over, 2 on an error; a NaN is
// reported and fails whatever the share, even after finite pixels.
TEST(CliRobustness, CompareExitsTwoOnErrorsAndReportsNan) {
  test::TempDir dir;
  const auto a = (dir / "a.npy").string(), nan = (dir / "nan.npy").string(), small = (dir / "small.npy").string();
  std::vector<float> pixels(2 * 3 * 4, 0.25f);
  write_npy(a, {2, 3, 4}, pixels);
  pixels[4 * 4 + 3] = NAN;  // pixel 4's alpha, after finite ones
  write_npy(nan, {2, 3, 4}, pixels);
  write_npy(small, {1, 3, 4}, std::span<const float>(pixels.data(), 12));
  const ProcessResult over = run("compare " + a + " " + nan + " --max-share 1", dir);
  EXPECT_EQ(over.code, 1) << over.err;
  EXPECT_NE(over.out.find("a        0.166667         nan           nan           1"), std::string::npos) << over.out;
  EXPECT_EQ(run("compare " + a + " " + a, dir).code, 0);
  const ProcessResult missing = run("compare " + a + " " + (dir / "none.npy").string(), dir);
  EXPECT_EQ(missing.code, 2);
  EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
  EXPECT_EQ(run("compare " + a + " " + small, dir).code, 2);
  EXPECT_EQ(run("compare " + a + " " + a + " --tolerance -1", dir).code, 2);
}

TEST(CliRobustness, AllTransparentImagesAreExplained) {  // defect 12
  test::TempDir dir;
  const std::string out = (dir / "out.npy").string();
  const std::string away = replaced(test::kGoodScene, R"("target": [5.5, 5.5, 5.5])", R"("target": [5.5, 5.5, 80])");
  ProcessResult r = run("render " + scene_with(dir, away) + " -o " + out, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("vri: warning: every pixel is transparent: the camera looks away from the volume"),
            std::string::npos) << r.err;
  const std::string range = replaced(test::kGoodScene, R"([[-6, 1, 0.5, 0, 0.5], [0, 0, 0, 1, 0]])",
                                     R"([[100, 1, 1, 1, 0], [200, 1, 1, 1, 5]])");
  r = run("render " + scene_with(dir, range) + " -o " + out, dir);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("the transfer function is transparent over the data range"), std::string::npos) << r.err;
  r = run("render " + scene_with(dir, test::kGoodScene) + " -o " + out, dir);
  EXPECT_EQ(r.err.find("warning"), std::string::npos) << r.err;
}

TEST(CliRobustness, MessagesNameTheKeyAndEscapeTheInput) {  // defects 10, 14
  test::TempDir dir;
  const std::string out = (dir / "out.npy").string();
  expect_refused("render " + scene_with(dir, replaced(test::kGoodScene, R"("width": 16)", R"("width": -3)")) + " -o " + out,
                 "scene.json': camera.width: expected a positive integer, found -3", dir);
  const std::string seeded = replaced(test::kGoodScene, R"("builtin": "sphere")", R"("builtin": "random", "seed": 1e300)");
  expect_refused("render " + scene_with(dir, seeded) + " -o " + out, "volume.seed: expected an integer in [0, ", dir);
  // a control byte and a byte that is not UTF-8 come back as \xNN
  const std::string odd = replaced(test::kGoodScene, R"("builtin": "sphere")", "\"builtin\": \"sph\\u0007\\nere\"");
  expect_refused("render " + scene_with(dir, odd) + " -o " + out, R"(found "sph\u0007\nere")", dir);
  expect_refused("render " + scene_with(dir, "{\"volume\": \"\xff\n\"}") + " -o " + out, "\\xFF", dir);
  expect_refused("render " + scene_with(dir, "{\"volume\": ") + " -o " + out, "scene.json': malformed JSON", dir);
}

}  // namespace
}  // namespace vri
