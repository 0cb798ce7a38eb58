#include "vri/io.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "vri/error.hpp"

namespace vri {

namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<std::byte>*>(png_get_io_ptr(png));
  const auto* p = reinterpret_cast<const std::byte*>(data);
  out->insert(out->end(), p, p + length);
}

}  // namespace

std::vector<std::uint8_t> composite_rgba8(const Image& image, Vec3 background) {
  const int W = image.width(), H = image.height();
  std::vector<std::uint8_t> rgba(std::size_t(W) * H * 4);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const float* p = image.pixel(x, y);
      std::uint8_t* q = rgba.data() + (std::size_t(y) * W + x) * 4;
      for (int c = 0; c < 3; ++c) {
        const double v = std::clamp(double(p[c]) + (1.0 - p[3]) * background[c], 0.0, 1.0);
        q[c] = static_cast<std::uint8_t>(std::lround(std::isnan(v) ? 0.0 : v * 255.0));
      }
      q[3] = 255;
    }
  return rgba;
}

std::vector<std::byte> encode_png(std::span<const std::uint8_t> pixels, int width, int height, int channels, int bits) {
  if (channels != 1 && channels != 4) throw Error("PNG: 1 or 4 channels, not " + std::to_string(channels));
  if (bits != 8 && bits != 16) throw Error("PNG: 8 or 16 bits a channel, not " + std::to_string(bits));
  const std::size_t row = std::size_t(width) * channels * (bits / 8);
  if (pixels.size() != row * height) throw Error("PNG: pixel count does not match the size");
  std::vector<std::byte> encoded;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    throw Error("libpng: out of memory");
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw Error("libpng failed to encode an image");
  }
  png_set_write_fn(png, &encoded, append_bytes, nullptr);
  png_set_IHDR(png, info, width, height, bits, channels == 4 ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_GRAY,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // Fast over small: the viewer sends every final frame as this PNG, and zlib's
  // default level with libpng's adaptive filters took 30 ms for 512 x 512.
  png_set_compression_level(png, 1);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_write_info(png, info);
  for (int y = 0; y < height; ++y)
    png_write_row(png, const_cast<png_bytep>(pixels.data() + std::size_t(y) * row));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return encoded;
}

std::vector<std::byte> encode_png(const Image& image, Vec3 background, PngFormat format) {
  if (format.bits != 8 && format.bits != 16) throw Error("PNG: 8 or 16 bits a channel, not " + std::to_string(format.bits));
  if (!format.transparent && format.bits == 8)
    return encode_png(composite_rgba8(image, background), image.width(), image.height(), 4);
  const int W = image.width(), H = image.height(), bytes = format.bits / 8;
  const double top = format.bits == 16 ? 65535.0 : 255.0;
  std::vector<std::uint8_t> out(std::size_t(W) * H * 4 * bytes);
  auto put = [&](std::size_t at, double v) {
    const auto q = static_cast<std::uint32_t>(std::lround(std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0) * top));
    if (bytes == 2) {
      out[at * 2] = std::uint8_t(q >> 8);  // PNG's 16-bit samples are big-endian
      out[at * 2 + 1] = std::uint8_t(q & 0xff);
    } else {
      out[at] = std::uint8_t(q);
    }
  };
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const float* p = image.pixel(x, y);
      const std::size_t at = (std::size_t(y) * W + x) * 4;
      const double a = p[3];
      for (int c = 0; c < 3; ++c)
        // Transparent: PNG's alpha is straight, so the colour is C / alpha.
        put(at + c, format.transparent ? (a > 0 ? p[c] / a : 0.0) : p[c] + (1.0 - a) * background[c]);
      put(at + 3, format.transparent ? a : 1.0);
    }
  return encode_png(out, W, H, 4, format.bits);
}

void write_png(const std::filesystem::path& path, const Image& image, Vec3 background, PngFormat format) {
  write_file_atomically(path, encode_png(image, background, format));
}

}  // namespace vri
