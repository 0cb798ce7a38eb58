// `vri render` on mesh scenes: every mesh method from the command line, and
// methods that do not fit the volume kind refused with one line and no file.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

#include "test_support.hpp"
#include "vri/io.hpp"

namespace vri {
namespace {

int run(const std::string& args, const test::TempDir& dir, std::string& err) {
  const auto err_path = dir / "stderr.txt";
  const int status = std::system((std::string(VRI_BINARY) + " " + args + " 2>" + err_path.string()).c_str());
  std::ifstream in(err_path);
  std::stringstream ss;
  ss << in.rdbuf();
  err = ss.str();
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(MeshCli, RendersEveryMeshMethodAndRefusesMismatches) {
  test::TempDir dir;
  const auto scene = dir / "mesh.json";
  test::write_text(scene, R"({"volume": {"file": ")" + test::source_path("data/tetra_mesh_small_ascii.vtk") + R"("},
    "transfer_function": {"points": [[0, 0, 0, 1, 0.05], [4, 1, 0, 0, 0.3]]},
    "camera": {"eye": [30, 20, 25], "target": [0, 0, 0], "width": 12, "height": 10},
    "method": {"name": "exact", "table_size": 32, "length_samples": 8, "planes": 16}})");
  std::string err;
  for (const char* method : {"exact", "tet-raycast", "pt", "pt-cylindrical"}) {
    const auto out = dir / (std::string(method) + ".npy");
    ASSERT_EQ(run("render " + scene.string() + " --method " + method + " -o " + out.string(), dir, err), 0) << err;
    const auto img = read_npy(out);
    EXPECT_EQ(img.shape, (std::vector<std::size_t>{10, 12, 4})) << method;
    double alpha = 0;
    for (std::size_t i = 3; i < img.data.size(); i += 4) alpha += img.data[i];
    EXPECT_GT(alpha, 5) << method;
  }
  const auto bad = dir / "bad.npy";
  EXPECT_EQ(run("render " + scene.string() + " --method riemann -o " + bad.string(), dir, err), 1);
  EXPECT_NE(err.find("works on regular grids only"), std::string::npos) << err;
  const auto grid = dir / "grid.json";
  test::write_text(grid, R"({"volume": {"builtin": "sphere", "dims": [6, 6, 6]},
    "transfer_function": {"points": [[0, 1, 1, 1, 0.1]]}, "camera": {"eye": [2, 2, 20], "target": [2, 2, 2]}})");
  EXPECT_EQ(run("render " + grid.string() + " --method pt -o " + bad.string(), dir, err), 1);
  EXPECT_NE(err.find("method 'pt' needs a tetrahedral mesh"), std::string::npos) << err;
  EXPECT_EQ(run("render " + grid.string() + " --method tet-raycast -o " + bad.string(), dir, err), 1);
  EXPECT_NE(err.find("needs a tetrahedral mesh"), std::string::npos) << err;
  EXPECT_FALSE(std::filesystem::exists(bad));
}

}  // namespace
}  // namespace vri
