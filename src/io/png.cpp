#include "vri/io/png.hpp"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "vri/core/error.hpp"
#include "vri/io/file_io.hpp"

namespace vri {

namespace {

void append_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<std::byte>*>(png_get_io_ptr(png));
  const auto* p = reinterpret_cast<const std::byte*>(data);
  out->insert(out->end(), p, p + length);
}

}  // namespace

void write_png(const std::filesystem::path& path, const Image& image, Vec3 background) {
  const int W = image.width(), H = image.height();
  std::vector<unsigned char> rgba(std::size_t(W) * H * 4);
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const float* p = image.pixel(x, y);
      unsigned char* q = rgba.data() + (std::size_t(y) * W + x) * 4;
      for (int c = 0; c < 3; ++c) {
        const double v = std::clamp(double(p[c]) + (1.0 - p[3]) * background[c], 0.0, 1.0);
        q[c] = static_cast<unsigned char>(std::lround(std::isnan(v) ? 0.0 : v * 255.0));
      }
      q[3] = 255;
    }
  std::vector<std::byte> encoded;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    throw Error("libpng: out of memory");
  }
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw Error("libpng failed to encode '" + path.string() + "'");
  }
  png_set_write_fn(png, &encoded, append_bytes, nullptr);
  png_set_IHDR(png, info, W, H, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < H; ++y) png_write_row(png, rgba.data() + std::size_t(y) * W * 4);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  write_file_atomically(path, encoded);
}

}  // namespace vri
