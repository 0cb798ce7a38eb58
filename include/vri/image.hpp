#pragma once
// Image: H x W premultiplied RGBA floats, row 0 at the top (SPEC §7).
// The pixels are ZeroedFloats: from 1 MiB up (a 512 x 512 image is 4 MiB)
// they start on zero pages of 2 MiB, so a frame does not pay a 4 KiB page
// fault per 1024 pixels (vri/memory.hpp).
#include <cstddef>
#include <span>
#include <utility>

#include "vri/geometry.hpp"
#include "vri/memory.hpp"

namespace vri {

class Image {
 public:
  Image() = default;
  Image(int width, int height) : width_(width), height_(height), data_(std::size_t(width) * height * 4, "an image") {}

  int width() const { return width_; }
  int height() const { return height_; }
  float* pixel(int x, int y) { return data_.data() + (std::size_t(y) * width_ + x) * 4; }
  const float* pixel(int x, int y) const { return data_.data() + (std::size_t(y) * width_ + x) * 4; }
  void set(int x, int y, const Rgba& v) {
    float* p = pixel(x, y);
    for (int c = 0; c < 4; ++c) p[c] = static_cast<float>(v[c]);
  }
  std::span<const float> data() const { return {data_.data(), data_.size()}; }
  std::span<float> data() { return {data_.data(), data_.size()}; }
  // The pixels, moved out (the image is left empty), for owners such as a
  // NumPy array.
  ZeroedFloats release() && {
    width_ = height_ = 0;
    return std::move(data_);
  }

 private:
  int width_ = 0, height_ = 0;
  ZeroedFloats data_;
};

}  // namespace vri
