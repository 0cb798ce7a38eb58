// --max-memory: the budget consulted before big allocations (issue 17).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "test_support.hpp"

namespace vri {
namespace {

struct Result {
  int code;
  std::string err;
};

Result vri_with(const std::string& args, const test::TempDir& dir) {
  const auto err = dir / "stderr.txt";
  const int status = std::system((std::string(VRI_BINARY) + " " + args + " >/dev/null 2>" + err.string()).c_str());
  std::stringstream ss;
  ss << std::ifstream(err).rdbuf();
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ss.str()};
}

TEST(MaxMemory, RefusesAVolumeOverTheBudgetAndSaysHowToRaiseIt) {
  test::TempDir dir;
  test::write_text(dir / "s.json", R"({"volume": {"builtin": "sphere", "dims": [40, 40, 40]},
    "transfer_function": {"points": [[-6, 1, 0.5, 0, 0.5], [0, 0, 0, 1, 0]]},
    "camera": {"eye": [20, 20, 90], "target": [20, 20, 20], "width": 4, "height": 3},
    "method": {"name": "riemann", "step": 1}})");
  const std::string render = "render " + (dir / "s.json").string() + " -o " + (dir / "a.npy").string();
  Result r = vri_with(render + " --max-memory 100K", dir);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("a built-in volume of 64000 samples would need 250 KiB (256000 bytes), over the memory "
                       "limit of 100 KiB; raise it with --max-memory"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "a.npy"));
  r = vri_with(render + " --max-memory 12Q", dir);
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--max-memory expects a size"), std::string::npos) << r.err;
  r = vri_with(render + " --max-memory 64M", dir);
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir / "a.npy"));
}

// The budget bounds the whole process: the volume's samples stay counted, so
// a lit render whose gradient field alone fits but not beside the volume is
// refused before the gradients are allocated (they were not, before).
TEST(MaxMemory, TheVolumeStaysCountedAgainstWhatComesAfterIt) {
  test::TempDir dir;
  test::write_text(dir / "s.json", R"({"volume": {"builtin": "sphere", "dims": [40, 40, 40]},
    "transfer_function": {"points": [[-6, 1, 0.5, 0, 0.5], [0, 0, 0, 1, 0]]},
    "camera": {"eye": [20, 20, 90], "target": [20, 20, 20], "width": 4, "height": 3},
    "lighting": {"enabled": true}, "method": {"name": "riemann", "step": 1}})");
  const std::string render = "render " + (dir / "s.json").string() + " -o " + (dir / "a.npy").string();
  // 250 KiB of samples, then 750 KiB of gradients: each under 900 KiB, not both.
  Result r = vri_with(render + " --max-memory 900K", dir);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("the lighting gradient field (3 floats per grid point) would need 750 KiB (768000 bytes), "
                       "over the memory limit of 900 KiB with 250 KiB already held"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "a.npy"));
  r = vri_with(render + " --max-memory 2M", dir);
  EXPECT_EQ(r.code, 0) << r.err;
}

}  // namespace
}  // namespace vri
