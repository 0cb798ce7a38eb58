#pragma once
// The .npy preamble (NumPy NEP 1, numpy.lib.format): the magic "\x93NUMPY",
// format version 1.0, 2.0 or 3.0, the header length, and the header's Python
// dict literal {'descr': ..., 'fortran_order': ..., 'shape': (...)}. Shared by
// the float reader for images (npy.cpp) and the volume reader (npy_volume.cpp).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace vri {

struct NpyHeader {
  std::string descr;              // the dtype string without quotes: "<f4", "|u1", ...
  bool fortran_order = false;     // first index fastest
  std::vector<std::uint64_t> shape;
  std::uint64_t count = 0;        // the product of shape (checked against overflow)
  std::uint64_t data_offset = 0;  // where the data starts: the preamble's size
};

// The preamble's size (magic to the end of the header dict), from the file's
// first 12 bytes (`start`: fewer when the file is shorter). vri::Error,
// starting with `where`, for a file that is not .npy, an unknown version, or
// a header longer than the file (`file_size` bytes) or than 1 MiB.
std::uint64_t npy_preamble_size(std::span<const std::byte> start, std::uint64_t file_size, const std::string& where);

// Parses the preamble (`preamble` holds at least npy_preamble_size bytes).
// A structured dtype (a list as 'descr') is refused here, naming it.
NpyHeader parse_npy_header(std::span<const std::byte> preamble, std::uint64_t file_size, const std::string& where);

}  // namespace vri
