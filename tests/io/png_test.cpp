#include "vri/io.hpp"

#include <gtest/gtest.h>
#include <png.h>

#include <cstdio>
#include <cstring>

#include "test_support.hpp"
#include "vri/error.hpp"

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

namespace vri {
namespace {

// The samples of a PNG exactly as stored (libpng, no transforms), 16-bit ones
// assembled from their big-endian bytes.
std::vector<unsigned> samples(const std::vector<std::byte>& file, int& bits, int& channels) {
  struct Source {
    const std::byte* p;
  } source{file.data()};
  png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  png_set_read_fn(png, &source, [](png_structp pp, png_bytep out, png_size_t n) {
    auto* src = static_cast<Source*>(png_get_io_ptr(pp));
    std::memcpy(out, src->p, n);
    src->p += n;
  });
  png_read_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
  bits = png_get_bit_depth(png, info);
  channels = png_get_channels(png, info);
  const png_uint_32 W = png_get_image_width(png, info), H = png_get_image_height(png, info);
  png_bytepp rows = png_get_rows(png, info);
  std::vector<unsigned> out;
  for (png_uint_32 y = 0; y < H; ++y)
    for (png_uint_32 i = 0; i < W * png_uint_32(channels); ++i)
      out.push_back(bits == 16 ? unsigned(rows[y][2 * i]) << 8 | rows[y][2 * i + 1] : rows[y][i]);
  png_destroy_read_struct(&png, &info, nullptr);
  return out;
}

TEST(Png, TransparentKeepsAlphaAndStraightColour) {
  Image image(2, 1);
  image.set(0, 0, {0.2, 0.1, 0.0, 0.5});  // premultiplied: straight colour 0.4, 0.2, 0
  const std::vector<std::byte> png = encode_png(image, {1, 1, 1}, {.transparent = true});
  int bits = 0, channels = 0;
  const std::vector<unsigned> s = samples(png, bits, channels);
  EXPECT_EQ(bits, 8);
  EXPECT_EQ(s, (std::vector<unsigned>{102, 51, 0, 128, 0, 0, 0, 0}));  // round(0.4*255) = 102, alpha 127.5 -> 128
  // The default is still SPEC §7's composite, opaque.
  EXPECT_EQ(encode_png(image, {1, 1, 1}), encode_png(composite_rgba8(image, {1, 1, 1}), 2, 1, 4));
}

TEST(Png, SixteenBitsKeepTheFinerValues) {
  Image image(1, 1);
  image.set(0, 0, {0.123456, 0.5, 1.0, 1.0});
  int bits = 0, channels = 0;
  const std::vector<unsigned> s = samples(encode_png(image, {0, 0, 0}, {.bits = 16}), bits, channels);
  ASSERT_EQ(bits, 16);
  ASSERT_EQ(channels, 4);
  EXPECT_EQ(s, (std::vector<unsigned>{8091, 32768, 65535, 65535}));  // round(0.123456 * 65535) = 8091
  EXPECT_THROW(encode_png(image, {0, 0, 0}, {.bits = 12}), Error);
}

}  // namespace
}  // namespace vri
