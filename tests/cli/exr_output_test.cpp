// `vri render -o x.exr`: the float image of the .npy, channel for channel,
// read back with OpenEXR itself; PNG with alpha and 16-bit PNG flags; bad
// combinations refused before any work.
#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <gtest/gtest.h>

#include "cli/cli_support.hpp"
#include "vri/io.hpp"

namespace vri::test {
namespace {

TEST(ExrOutput, HoldsTheNpyFloatsExactly) {
  TempDir dir;
  const std::string scene = source_path("scenes/neghip.json");
  const std::string common = " --method preint1 --width 40 --height 30 --threads 1 -q";
  ASSERT_EQ(run("render " + scene + " -o " + (dir / "a.exr").string() + common, dir).code, 0);
  ASSERT_EQ(run("render " + scene + " -o " + (dir / "a.npy").string() + common, dir).code, 0);
  const NpyArray npy = read_npy(dir / "a.npy");
  Imf::InputFile file((dir / "a.exr").c_str());
  const Imath::Box2i box = file.header().dataWindow();
  const int W = box.max.x - box.min.x + 1, H = box.max.y - box.min.y + 1;
  ASSERT_EQ(W, 40);
  ASSERT_EQ(H, 30);
  std::vector<float> rgba(std::size_t(W) * H * 4);
  Imf::FrameBuffer frame;
  const char* names[] = {"R", "G", "B", "A"};
  for (int c = 0; c < 4; ++c)
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(rgba.data() + c), 4 * sizeof(float),
                                      std::size_t(W) * 4 * sizeof(float)));
  file.setFrameBuffer(frame);
  file.readPixels(box.min.y, box.max.y);
  EXPECT_EQ(rgba, npy.data);
}

TEST(ExrOutput, PngFlagsAndRefusals) {
  TempDir dir;
  const std::string scene = source_path("scenes/neghip.json") + " --method preint1 --width 16 --height 16 -q";
  EXPECT_EQ(run("render " + scene + " -o " + (dir / "t.png").string() + " --background none --png-bits 16", dir).code,
            0);
  EXPECT_EQ(slurp(dir / "t.png").substr(1, 3), "PNG");
  const ProcessResult bad = run("render " + scene + " -o " + (dir / "t.npy").string() + " --png-bits 16", dir);
  EXPECT_NE(bad.code, 0);
  EXPECT_NE(bad.err.find("apply to .png output"), std::string::npos) << bad.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "t.npy"));
  EXPECT_NE(run("render " + scene + " -o " + (dir / "u.png").string() + " --background 2,0,0", dir).code, 0);
  EXPECT_EQ(run("render " + scene + " -o " + (dir / "v.png").string() + " --background 0.1,0.2,0.3", dir).code, 0);
}

}  // namespace
}  // namespace vri::test
