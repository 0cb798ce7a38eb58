// Frame encodings: the final PNG is the bytes `vri render` writes, the JPEG
// decodes to the composite within JPEG's error, and the error map's grey
// levels and statistics follow their definitions.
#include "frame_encoding.hpp"

#include <gtest/gtest.h>
#include <png.h>
#include <turbojpeg.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "vri/error.hpp"
#include "vri/io.hpp"

namespace vri::viewer {
namespace {

Image gradient_image(int W, int H) {
  Image image(W, H);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const double a = double(x) / (W - 1);
      image.set(x, y, {0.8 * a, 0.5 * a * double(y) / (H - 1), 0.2 * a, a});
    }
  return image;
}

TEST(FrameEncoding, FinalPngIsTheBytesVriRenderWrites) {
  const Image image = gradient_image(37, 21);
  const auto path = std::filesystem::temp_directory_path() / "vri_frame_encoding_test.png";
  write_png(path, image, {0.1, 0.2, 0.3});
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  const std::vector<std::byte> png = encode_png(image, {0.1, 0.2, 0.3});
  ASSERT_EQ(png.size(), file.size());
  EXPECT_EQ(std::memcmp(png.data(), file.data(), png.size()), 0);
}

TEST(FrameEncoding, JpegDecodesToTheComposite) {
  const Image image = gradient_image(64, 48);
  const Vec3 background{0.1, 0.2, 0.3};
  const std::vector<std::byte> jpeg = encode_jpeg(image, background, 95);
  tjhandle tj = tjInitDecompress();
  int W = 0, H = 0, sub = 0, space = 0;
  auto* data = reinterpret_cast<unsigned char*>(const_cast<std::byte*>(jpeg.data()));
  ASSERT_EQ(tjDecompressHeader3(tj, data, jpeg.size(), &W, &H, &sub, &space), 0);
  ASSERT_EQ(W, 64);
  ASSERT_EQ(H, 48);
  std::vector<unsigned char> rgb(std::size_t(W) * H * 3);
  ASSERT_EQ(tjDecompress2(tj, data, jpeg.size(), rgb.data(), W, 0, H, TJPF_RGB, 0), 0);
  tjDestroy(tj);
  const std::vector<std::uint8_t> expected = composite_rgba8(image, background);
  double worst = 0;
  for (std::size_t i = 0; i < std::size_t(W) * H; ++i)
    for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(double(rgb[3 * i + c]) - expected[4 * i + c]));
  EXPECT_LE(worst, 12);  // a smooth ramp at quality 95 with 4:2:0 chroma
}

TEST(FrameEncoding, ErrorMapLevelsAndStatistics) {
  Image frame(4, 1), reference(4, 1);
  // Errors 0, 1e-6 (level 0), 1e-3 (level 127.5 -> 128), 0.5 in alpha (level 255 * (log10 0.5 + 6) / 6).
  frame.set(1, 0, {1e-6, 0, 0, 0});
  frame.set(2, 0, {0, 1e-3, 0, 0});
  frame.set(3, 0, {0, 0, 0, 0.5});
  const ErrorMap m = error_map(frame, reference, 1e-4);
  EXPECT_DOUBLE_EQ(m.share_over, 0.5);
  EXPECT_NEAR(m.max, 0.5, 1e-7);
  EXPECT_NEAR(m.rms, std::sqrt((1e-12 + 1e-6 + 0.25) / 16), 1e-7);
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_memory(&png, m.png.data(), m.png.size()));
  ASSERT_EQ(png.width, 4u);
  png.format = PNG_FORMAT_GRAY;
  std::vector<std::uint8_t> levels(4);
  ASSERT_TRUE(png_image_finish_read(&png, nullptr, levels.data(), 0, nullptr));
  EXPECT_EQ(levels, (std::vector<std::uint8_t>{0, 0, 128, std::uint8_t(std::lround(255 * (std::log10(0.5) + 6) / 6))}));
  // Another tolerance changes the share alone.
  const ErrorMap m2 = error_map(frame, reference, 0.6);
  EXPECT_EQ(m2.share_over, 0);
  EXPECT_EQ(m2.png, m.png);
  EXPECT_THROW(error_map(frame, Image(3, 1), 1e-3), Error);
}

}  // namespace
}  // namespace vri::viewer
