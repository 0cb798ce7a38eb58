#pragma once
// Image: H x W premultiplied RGBA floats, row 0 at the top (SPEC §7).
#include <cstddef>
#include <vector>

#include "vri/core/rgba.hpp"

namespace vri {

class Image {
 public:
  Image() = default;
  Image(int width, int height) : width_(width), height_(height), data_(std::size_t(width) * height * 4, 0.f) {}

  int width() const { return width_; }
  int height() const { return height_; }
  float* pixel(int x, int y) { return data_.data() + (std::size_t(y) * width_ + x) * 4; }
  const float* pixel(int x, int y) const { return data_.data() + (std::size_t(y) * width_ + x) * 4; }
  void set(int x, int y, const Rgba& v) {
    float* p = pixel(x, y);
    for (int c = 0; c < 4; ++c) p[c] = static_cast<float>(v[c]);
  }
  const std::vector<float>& data() const { return data_; }
  std::vector<float>& data() { return data_; }

 private:
  int width_ = 0, height_ = 0;
  std::vector<float> data_;
};

}  // namespace vri
