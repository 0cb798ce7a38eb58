// `vri render` with the adaptive method's flags: --strategy, --h0/--hmin/--hmax,
// --error-estimate and --trace, and their errors.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "vri/io.hpp"

namespace vri {
namespace {

namespace fs = std::filesystem;

struct Dir {
  fs::path path = fs::temp_directory_path() / ("vri_adaptive_cli_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
  Dir() { fs::create_directories(path); }
  ~Dir() { fs::remove_all(path); }
};

int vri(const std::string& args) {
  const std::string cmd = std::string(VRI_BINARY) + " render " + VRI_SOURCE_DIR + "/scenes/engine.json --width 12 --height 9 " +
                          args + " 2>/dev/null";
  return std::system(cmd.c_str());
}

TEST(AdaptiveFlags, WritesImageEstimateAndTrace) {
  Dir d;
  const fs::path img = d.path / "a.npy", est = d.path / "e.npy", csv = d.path / "t.csv";
  ASSERT_EQ(vri("-o " + img.string() + " --method adaptive --strategy guaranteed --tolerance 0.01 --error-estimate " +
                est.string() + " --trace-pixel 6 4 --trace " + csv.string()),
            0);
  const NpyArray e = read_npy(est);
  EXPECT_EQ(e.shape, (std::vector<std::size_t>{9, 12, 4}));
  float total = 0;
  for (float v : e.data) {
    EXPECT_GE(v, 0.f);
    total += v;
  }
  EXPECT_GT(total, 0.f);
  std::ifstream in(csv);
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header, "integral,t,h,alpha");
  EXPECT_EQ(first.rfind("outer,", 0), 0u);
}

TEST(AdaptiveFlags, ErrorsLeaveNoFiles) {
  Dir d;
  const fs::path img = d.path / "a.npy", est = d.path / "e.npy", csv = d.path / "t.csv";
  EXPECT_NE(vri("-o " + img.string() + " --method riemann --error-estimate " + est.string()), 0);
  EXPECT_NE(vri("-o " + img.string() + " --method adaptive --tolerance 0.01 --strategy sideways"), 0);
  EXPECT_NE(vri("-o " + img.string() + " --method adaptive --tolerance 0.01 --hmin 1 --h0 0.5"), 0);
  EXPECT_NE(vri("-o " + img.string() + " --method adaptive --tolerance 0.01 --trace-pixel 12 0 --trace " + csv.string()), 0);
  EXPECT_NE(vri("-o " + img.string() + " --method adaptive --tolerance 0.01 --trace " + csv.string()), 0);
  EXPECT_FALSE(fs::exists(img));
  EXPECT_FALSE(fs::exists(est));
  EXPECT_FALSE(fs::exists(csv));
}

}  // namespace
}  // namespace vri
