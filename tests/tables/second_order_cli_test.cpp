// `vri table --order 2` end to end (SPEC §10): shape (N, N, N, 4), the
// entries of the builder, refusals without output.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include "test_support.hpp"
#include "vri/io.hpp"
#include "vri/scene.hpp"
#include "tables/second_order_table.hpp"

namespace vri {
namespace {

int vri_table(const std::string& args, const test::TempDir& dir) {
  const std::string cmd = std::string(VRI_BINARY) + " table --tf " + test::source_path("presets/bonsai.json") +
                          " --order 2 " + args + " 2>" + (dir / "stderr.txt").string();
  return WEXITSTATUS(std::system(cmd.c_str()));
}

TEST(SecondOrderTableCommand, WritesTheSpecShapeAndTheBuildersEntries) {
  const test::TempDir dir;
  const auto out = dir / "t.npy";
  const TransferFunction bonsai = load_transfer_function(test::source_path("presets/bonsai.json"));
  const DiscreteTf tf(bonsai, 12);
  for (const std::string builder : {"plain", "fast"}) {
    ASSERT_EQ(vri_table("--size 12 --length 1.5 --iterations 9 --builder " + builder + " -o " + out.string(), dir),
              0);
    const NpyArray a = read_npy(out);
    EXPECT_EQ(a.shape, (std::vector<std::size_t>{12, 12, 12, 4}));
    const SecondOrderTable t = make_second_order_builder(builder)->build(tf, 1.5, 9);
    for (std::size_t k = 0; k < a.data.size(); ++k) ASSERT_EQ(a.data[k], t.data()[k]) << builder;
  }
  // The defaults: fast, 8 chords, length 1.
  ASSERT_EQ(vri_table("--size 10 -o " + out.string(), dir), 0);
  const SecondOrderTable t = make_second_order_builder("fast")->build(DiscreteTf(bonsai, 10), 1.0, 8);
  const NpyArray a = read_npy(out);
  for (std::size_t k = 0; k < a.data.size(); ++k) ASSERT_EQ(a.data[k], t.data()[k]);
}

TEST(SecondOrderTableCommand, BadArgumentsFailWithoutOutput) {
  const test::TempDir dir;
  const auto out = dir / "t.npy";
  for (const std::string args :
       {"--size 8 --builder incremental", "--size 8 --iterations 0", "--size 8 --iterations 4097",
        "--size 407", "--size 8 --length 0", "--size 8 --lengths 3 --max-length 2", "--size 1"}) {
    EXPECT_NE(vri_table(args + " -o " + out.string(), dir), 0) << args;
    EXPECT_FALSE(std::filesystem::exists(out)) << args;
  }
}

}  // namespace
}  // namespace vri
