#pragma once
// NumPy .npy files of float32 (written) and float32/float64 (read), C order.
#include <cstddef>
#include <filesystem>
#include <span>
#include <vector>

#include "vri/render/image.hpp"

namespace vri {

struct NpyArray {
  std::vector<std::size_t> shape;
  std::vector<float> data;
};

// Throws vri::Error for anything but a little-endian float32/float64 C-order array.
NpyArray read_npy(const std::filesystem::path& path);
void write_npy(const std::filesystem::path& path, const std::vector<std::size_t>& shape,
               std::span<const float> data);
// Shape (H, W, 4): the premultiplied (r, g, b, alpha) before any background.
void write_npy(const std::filesystem::path& path, const Image& image);

}  // namespace vri
