#pragma once
// NumPy .npy files of float32 (written) and float32/float64 (read), C order;
// and volumes from .npy (NumPy NEP 1, numpy.lib.format; SPEC §11).
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "vri/image.hpp"
#include "vri/volume/grid_volume.hpp"

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

// A volume from a 3-D array indexed [z, y, x] (SPEC §11): dims are
// (shape[2], shape[1], shape[0]), spacing 1, origin 0. Format versions 1.0,
// 2.0 and 3.0; C or Fortran order (transposed into x-fastest storage); dtypes
// bool (as 0/1), int8..int64, uint8..uint64, float16/32/64 in either byte
// order. uint8 (and bool), uint16, int16 and float32 keep their type, the
// others become float32. Object, string, complex, datetime and structured
// dtypes, and arrays that are not 3-D, are refused with vri::Error naming the
// file, as are data shorter or longer than the shape needs; sizes are checked
// (GridVolume::checked_sample_count, the memory budget) before allocating.
GridVolume read_npy_volume(const std::filesystem::path& path);
// The same from the file's bytes; `source` names it in errors.
GridVolume parse_npy_volume(std::span<const std::byte> bytes, const std::string& source);

}  // namespace vri
