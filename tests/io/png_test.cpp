#include "vri/io/png.hpp"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>

#include "test_support.hpp"

namespace vri {
namespace {

std::vector<unsigned char> decode(const std::filesystem::path& path, int& w, int& h) {
  png_image img{};
  img.version = PNG_IMAGE_VERSION;
  EXPECT_TRUE(png_image_begin_read_from_file(&img, path.c_str()));
  img.format = PNG_FORMAT_RGBA;
  std::vector<unsigned char> px(PNG_IMAGE_SIZE(img));
  EXPECT_TRUE(png_image_finish_read(&img, nullptr, px.data(), 0, nullptr));
  w = img.width;
  h = img.height;
  return px;
}

TEST(Png, CompositesOverTheBackgroundAndRounds) {
  test::TempDir dir;
  Image img(2, 1);
  img.set(0, 0, {0.2, 0.4, 0.0, 0.5});  // + 0.5 * bg
  img.set(1, 0, {1.3, 0.0, 0.0, 1.0});  // clamped
  write_png(dir / "o.png", img, {0.2, 1.0, 0.0});
  int w, h;
  const auto px = decode(dir / "o.png", w, h);
  ASSERT_EQ(w, 2);
  ASSERT_EQ(h, 1);
  EXPECT_EQ(px[0], 77);   // (0.2 + 0.1) * 255 = 76.5 -> 77
  EXPECT_EQ(px[1], 230);  // (0.4 + 0.5) * 255 = 229.5 -> 230
  EXPECT_EQ(px[2], 0);
  EXPECT_EQ(px[3], 255);
  EXPECT_EQ(px[4], 255);
  EXPECT_EQ(px[5], 0);
}

}  // namespace
}  // namespace vri
