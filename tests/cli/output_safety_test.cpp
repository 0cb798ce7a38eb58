// Issue 17, outputs: all of a command's files appear together or not at all,
// temporaries are created exclusively (a planted link is never followed),
// SIGTERM removes them, concurrent writers never mix, and memory limits fail
// cleanly.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.hpp"
#include "vri/io.hpp"

extern char** environ;

namespace vri {
namespace {

namespace fs = std::filesystem;
using test::ProcessResult;
using test::run;
using test::scene_with;

std::vector<std::string> listing(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

const std::string kAdaptive = "--method adaptive --tolerance 1e-3";

TEST(OutputSafety, AFailingSecondOutputLeavesNoFirst) {  // defect 7
  test::TempDir dir;
  const std::string scene = scene_with(dir, test::kGoodScene), out = (dir / "out.npy").string();
  const std::string nowhere = (dir / "no_such_dir").string();
  for (const std::string& args :
       {"render " + scene + " -o " + out + " " + kAdaptive + " --error-estimate " + nowhere + "/e.npy",
        "render " + scene + " -o " + out + " " + kAdaptive + " --trace-pixel 8 6 --trace " + nowhere + "/t.csv",
        "ray " + scene + " --pixel 8 6 -o " + (dir / "out.csv").string() + " --plot " + nowhere + "/p.svg"}) {
    const ProcessResult r = run(args, dir);
    EXPECT_EQ(r.code, 1) << args;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(listing(dir.path), (std::vector<std::string>{"scene.json", "stderr.txt", "stdout.txt"})) << args;
  }
}

TEST(OutputSafety, ALinkAtTheTargetIsReplacedNotFollowed) {  // defect 8
  test::TempDir dir;
  const std::string scene = scene_with(dir, test::kGoodScene);
  test::write_text(dir / "victim.txt", "keep");
  fs::create_symlink(dir / "victim.txt", dir / "out.npy");
  ASSERT_EQ(run("render " + scene + " -o " + (dir / "out.npy").string(), dir).code, 0);
  EXPECT_EQ(test::slurp(dir / "victim.txt"), "keep");
  EXPECT_FALSE(fs::is_symlink(dir / "out.npy"));
}

// Issue 47, defect 9: as root, `--trace /dev/null` replaced the device node
// with a CSV. A FIFO stands in for a device (no root needed to make one).
TEST(OutputSafety, ANonRegularFileAtTheTargetIsNeverReplaced) {
  test::TempDir dir;
  const std::string scene = scene_with(dir, test::kGoodScene);
  const fs::path fifo = dir / "out.npy";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const ProcessResult r = run("render " + scene + " -o " + fifo.string(), dir);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("is not a regular file"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_fifo(fifo));
  // --trace names a CSV, like `vri ray`'s output.
  const ProcessResult trace = run("render " + scene + " -o " + (dir / "a.npy").string() +
                                      " --method adaptive --trace-pixel 1 1 --trace " + (dir / "t.npy").string(),
                                  dir);
  EXPECT_EQ(trace.code, 1);
  EXPECT_NE(trace.err.find("must end in .csv"), std::string::npos) << trace.err;
  EXPECT_FALSE(fs::exists(dir / "a.npy"));
}

// Issue 47, defect 11: a write past the file-size limit (SIGXFSZ) killed vri
// with its temporary left, and a turntable that failed left an empty frames
// folder.
TEST(OutputSafety, TheFileSizeLimitFailsCleanly) {
  test::TempDir dir;
  const std::string scene = scene_with(dir, test::kGoodScene);
  ProcessResult r = run("render " + scene + " -o " + (dir / "out.npy").string(), dir, "ulimit -f 1; ");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  r = run("turntable " + scene + " -o " + (dir / "frames").string() + " --frames 3 -q --width 64 --height 64", dir,
          "ulimit -f 1; ");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_EQ(listing(dir.path), (std::vector<std::string>{"scene.json", "stderr.txt", "stdout.txt"}));
}

TEST(OutputSafety, ALinkAtTheTemporaryNameIsNotFollowed) {  // defect 8
  test::TempDir dir;
  test::write_text(dir / "victim.txt", "keep");
  // the first temporary name this process would use, planted as a link
  fs::create_symlink(dir / "victim.txt", dir / (".out.bin.tmp" + std::to_string(::getpid()) + ".0"));
  {
    OutputTransaction outputs;
    const std::string bytes = "new";
    outputs.stage(dir / "out.bin", std::as_bytes(std::span(bytes)));
    outputs.commit();
  }
  EXPECT_EQ(test::slurp(dir / "victim.txt"), "keep");
  EXPECT_EQ(test::slurp(dir / "out.bin"), "new");
}

TEST(OutputSafety, AnUncommittedTransactionLeavesNothing) {
  test::TempDir dir;
  {
    OutputTransaction outputs;
    const std::string bytes = "x";
    outputs.stage(dir / "a.bin", std::as_bytes(std::span(bytes)));
    outputs.stage(dir / "b.bin", std::as_bytes(std::span(bytes)));
  }
  EXPECT_TRUE(fs::is_empty(dir.path));
}

// A file staged in parts (a header, then pixels in place) holds the parts in
// order, empty ones included, and nothing else.
TEST(OutputSafety, PartsAreWrittenInOrder) {
  test::TempDir dir;
  const std::string header = "head", empty, body(100000, 'b');
  const std::span<const std::byte> parts[] = {std::as_bytes(std::span(header)), std::as_bytes(std::span(empty)),
                                              std::as_bytes(std::span(body))};
  write_file_atomically(dir / "parts.bin", parts);
  const auto got = read_file(dir / "parts.bin");
  const std::string all = header + body;
  ASSERT_EQ(got.size(), all.size());
  EXPECT_TRUE(std::equal(got.begin(), got.end(), std::as_bytes(std::span(all)).begin()));
  EXPECT_EQ(listing(dir.path), std::vector<std::string>{"parts.bin"});  // no temporary left
}

// Waits (without a time limit of its own) until `dir` holds a temporary.
bool temporary_appears(const fs::path& dir, pid_t pid) {
  for (;;) {
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().find(".tmp") != std::string::npos) return true;
    int status;
    if (::waitpid(pid, &status, WNOHANG) == pid) return false;  // finished first
    ::usleep(200);
  }
}

TEST(OutputSafety, SigtermRemovesTheTemporaries) {  // defect 7
  test::TempDir dir;
  // the image is staged, then the error estimate takes a while
  const std::string scene = scene_with(
      dir, test::kGoodScene.substr(0, test::kGoodScene.find(R"("width")")) + R"("width": 400, "height": 400},
      "method": {"name": "adaptive", "tolerance": 1e-9, "hmin": 0.001}})");
  const std::string out = (dir / "out.npy").string(), est = (dir / "est.npy").string();
  std::vector<std::string> args = {VRI_BINARY, "render", scene, "-o", out, "--error-estimate", est, "--threads", "1"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid;
  ASSERT_EQ(::posix_spawn(&pid, VRI_BINARY, nullptr, nullptr, argv.data(), environ), 0);
  ASSERT_TRUE(temporary_appears(dir.path, pid)) << "the render finished before a temporary was seen";
  ::kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  EXPECT_EQ(listing(dir.path), (std::vector<std::string>{"scene.json"}));
}

TEST(OutputSafety, ConcurrentWritersNeverMix) {  // item 6
  test::TempDir dir;
  const std::string scene = scene_with(dir, test::kGoodScene);
  const std::string out = (dir / "out.npy").string();
  // two different images, each rendered alone first
  ASSERT_EQ(run("render " + scene + " -o " + (dir / "a.npy").string() + " --width 64 --height 48", dir).code, 0);
  ASSERT_EQ(run("render " + scene + " -o " + (dir / "b.npy").string() + " --width 64 --height 48 --method riemann",
                dir).code, 0);
  const std::string a = test::slurp(dir / "a.npy"), b = test::slurp(dir / "b.npy");
  std::string cmd;
  for (int k = 0; k < 8; ++k)
    cmd += std::string(VRI_BINARY) + " render " + scene + " -o " + out + " --width 64 --height 48" +
           (k % 2 ? " --method riemann" : "") + " 2>/dev/null & ";
  cmd += "wait";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  const std::string got = test::slurp(out);
  EXPECT_TRUE(got == a || got == b) << "a mixed file of " << got.size() << " bytes";
  for (const auto& name : listing(dir.path)) EXPECT_EQ(name.find(".tmp"), std::string::npos) << name;
}

TEST(OutputSafety, MemoryLimitsFailCleanly) {  // item 6
#ifdef __SANITIZE_ADDRESS__
  // ASan maps terabytes of shadow memory at start, which no ulimit -v allows.
  GTEST_SKIP() << "ulimit -v cannot be tested under AddressSanitizer";
#endif
  // Cross-built, vri runs under qemu-user, whose own JIT buffer (128 MiB) no
  // such limit leaves room for.
  if (VRI_EMULATED) GTEST_SKIP() << "ulimit -v limits the emulator itself, not vri";
  test::TempDir dir;
  const std::string big = scene_with(
      dir, test::kGoodScene.substr(0, test::kGoodScene.find("[12, 12, 12]")) + "[800, 800, 800]" +
               test::kGoodScene.substr(test::kGoodScene.find("[12, 12, 12]") + 12));
  for (const char* limit : {"100000", "300000", "1000000"}) {
    const ProcessResult r =
        run("render " + big + " -o " + (dir / "out.npy").string(), dir, std::string("ulimit -v ") + limit + "; ");
    EXPECT_EQ(r.code, 1) << limit << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("vri: error: ", 0), 0u) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out.npy"));
  }
}

}  // namespace
}  // namespace vri
