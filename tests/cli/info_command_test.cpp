// `vri info`: what a file holds, read by its format; raw needs --dims; the
// histogram plot is a PNG; errors are one line and a non-zero exit.
#include <gtest/gtest.h>

#include "cli/cli_support.hpp"

namespace vri::test {
namespace {

TEST(InfoCommand, DescribesAVtiFile) {
  TempDir dir;
  const ProcessResult r = run("info " + source_path("tests/data/volume/base64_zlib.vti") + " --plot " +
                                  (dir / "h.png").string(),
                              dir);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("(VTK XML image data)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("dims: 11 x 7 x 5 (385 samples)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("spacing: 0.5 1.25 2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("origin: 1 -2 3"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("suggested transfer function"), std::string::npos) << r.out;
  const std::string png = slurp(dir / "h.png");
  EXPECT_EQ(png.substr(1, 3), "PNG");
}

TEST(InfoCommand, RawNeedsDimsAndCountsEverySample) {
  TempDir dir;
  const std::string raw = source_path("data/neghip_64x64x64_uint8.raw");
  const ProcessResult refused = run("info " + raw, dir);
  EXPECT_EQ(refused.code, 1);
  EXPECT_NE(refused.err.find("give --dims X Y Z"), std::string::npos) << refused.err;
  const ProcessResult r = run("info " + raw + " --dims 64 64 64 --bins 4", dir);
  ASSERT_EQ(r.code, 0) << r.err;
  // The four bins' counts add up to 64^3.
  long long total = 0;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);)
    if (line.find(" | ") != std::string::npos) total += std::stoll(line.substr(line.find_last_of(' ') + 1));
  EXPECT_EQ(total, 64LL * 64 * 64);
}

TEST(InfoCommand, DescribesTiffStacksAndSliceFolders) {
  TempDir dir;
  const ProcessResult stack = run("info " + source_path("tests/data/volume/tiff_u16_lzw.tif"), dir);
  ASSERT_EQ(stack.code, 0) << stack.err;
  EXPECT_NE(stack.out.find("(TIFF)"), std::string::npos) << stack.out;
  EXPECT_NE(stack.out.find("dims: 9 x 6 x 4 (216 samples)"), std::string::npos) << stack.out;
  EXPECT_NE(stack.out.find("stored as: uint16"), std::string::npos) << stack.out;
  const ProcessResult folder = run("info " + source_path("tests/data/volume/tiff_slices"), dir);
  ASSERT_EQ(folder.code, 0) << folder.err;
  EXPECT_NE(folder.out.find("dims: 6 x 5 x 11 (330 samples)"), std::string::npos) << folder.out;
  const ProcessResult rgb = run("info " + source_path("tests/data/volume/tiff_err_rgb.tif"), dir);
  EXPECT_EQ(rgb.code, 1);
  EXPECT_EQ(std::count(rgb.err.begin(), rgb.err.end(), '\n'), 1) << rgb.err;
}

TEST(InfoCommand, MeshesAndBadInput) {
  TempDir dir;
  const ProcessResult mesh = run("info " + source_path("data/blunt_fin_tet.vtk") + " --scalars density", dir);
  ASSERT_EQ(mesh.code, 0) << mesh.err;
  EXPECT_NE(mesh.out.find("tetrahedra: 187318"), std::string::npos) << mesh.out;
  EXPECT_NE(run("info " + (dir / "missing.nrrd").string(), dir).code, 0);
  EXPECT_NE(run("info " + source_path("tests/data/volume/npy_u1.npy") + " --bins 0", dir).code, 0);
  const ProcessResult plot = run("info " + source_path("tests/data/volume/npy_u1.npy") + " --plot " +
                                     (dir / "h.txt").string(), dir);
  EXPECT_NE(plot.code, 0);
  EXPECT_FALSE(std::filesystem::exists(dir / "h.txt"));
}

}  // namespace
}  // namespace vri::test
