// `vri table` end to end (SPEC §10): shapes, the builders, errors without output.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "test_support.hpp"
#include "vri/io.hpp"

namespace vri {
namespace {

int vri_table(const std::string& args, const test::TempDir& dir) {
  const std::string cmd = std::string(VRI_BINARY) + " table --tf " + test::source_path("presets/bonsai.json") +
                          " " + args + " 2>" + (dir / "stderr.txt").string();
  return WEXITSTATUS(std::system(cmd.c_str()));
}

TEST(TableCommand, WritesTheSpecShapes) {
  const test::TempDir dir;
  const auto one = dir / "one.npy", many = dir / "many.npy";
  ASSERT_EQ(vri_table("--size 16 --length 1.5 -o " + one.string(), dir), 0);
  const NpyArray a = read_npy(one);
  EXPECT_EQ(a.shape, (std::vector<std::size_t>{16, 16, 4}));
  ASSERT_EQ(vri_table("--size 16 --lengths 3 --max-length 3 --builder brute -o " + many.string(), dir), 0);
  const NpyArray b = read_npy(many);
  EXPECT_EQ(b.shape, (std::vector<std::size_t>{3, 16, 16, 4}));
  // Slice 0 is length 0 (empty); slice 1 is length 1.5, the first table.
  for (std::size_t k = 0; k < 16 * 16 * 4; ++k) {
    ASSERT_EQ(b.data[k], 0.0f);
    ASSERT_NEAR(b.data[16 * 16 * 4 + k], a.data[k], 1e-5);
  }
  EXPECT_GT(a.data[4 * (16 * 15 + 15) + 3], 0.5f);  // the opaque end of bonsai's TF
}

TEST(TableCommand, BadArgumentsFailWithoutOutput) {
  const test::TempDir dir;
  const auto out = dir / "t.npy";
  for (const std::string args : {"--builder fastest", "--lengths 3", "--size 1", "--order 3", "--length -1",
                                 "--builder sliced --accumulation 10bit"}) {
    EXPECT_NE(vri_table(args + " -o " + out.string(), dir), 0) << args;
    EXPECT_FALSE(std::filesystem::exists(out)) << args;
  }
}

}  // namespace
}  // namespace vri
