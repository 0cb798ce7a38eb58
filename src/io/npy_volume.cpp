// Volumes from NumPy .npy files (npy.hpp): a 3-D array indexed [z, y, x]
// (SPEC §11: x fastest, as a raw file), any numeric dtype in either byte
// order, C or Fortran order. The format: NumPy NEP 1 and numpy.lib.format
// (https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html);
// the preamble is parsed by npy_header.hpp, shared with the image reader.
#include <algorithm>
#include <bit>
#include <functional>
#include <map>
#include <type_traits>
#include <vector>

#include "grid_samples.hpp"
#include "npy_header.hpp"
#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "vri/io.hpp"

namespace vri {

namespace {

struct Dtype {
  FileSampleType type;
  Endian endian;
};

// "<f4", ">i2", "|u1", "|b1", ...: the numeric dtypes; others are refused
// naming what they hold.
Dtype parse_dtype(const std::string& descr, const std::string& where) {
  static const std::map<std::string, FileSampleType> numeric = {
      {"b1", FileSampleType::Bool},    {"i1", FileSampleType::Int8},    {"u1", FileSampleType::UInt8},
      {"i2", FileSampleType::Int16},   {"u2", FileSampleType::UInt16},  {"i4", FileSampleType::Int32},
      {"u4", FileSampleType::UInt32},  {"i8", FileSampleType::Int64},   {"u8", FileSampleType::UInt64},
      {"f2", FileSampleType::Float16}, {"f4", FileSampleType::Float32}, {"f8", FileSampleType::Float64}};
  const char order = descr.empty() ? '?' : descr[0];
  const bool known_order = order == '<' || order == '>' || order == '|' || order == '=';
  const auto it = known_order ? numeric.find(descr.substr(1)) : numeric.end();
  if (it == numeric.end()) {
    const char kind = descr.size() > 1 ? descr[1] : '?';
    const char* what = kind == 'c'                  ? "complex numbers"
                       : kind == 'O'                ? "Python objects"
                       : kind == 'U' || kind == 'S' ? "strings"
                       : kind == 'V'                ? "raw records"
                       : kind == 'M' || kind == 'm' ? "dates or times"
                                                    : "an unknown type";
    throw Error(where + ": dtype '" + descr + "' (" + what + ") is not supported; a volume needs bool, "
                "int8..int64, uint8..uint64, float16, float32 or float64");
  }
  // '|' (byte order not applicable) and '=' (native) read as this machine's order.
  const Endian native = std::endian::native == std::endian::big ? Endian::Big : Endian::Little;
  return {it->second, order == '<' ? Endian::Little : order == '>' ? Endian::Big : native};
}

// Fortran order stores the first index fastest: [z, y, x] with z fastest.
// Copied into x-fastest storage (a second buffer, under the memory budget).
GridVolume::Samples from_fortran_order(GridVolume::Samples samples, std::array<int, 3> dims) {
  return std::visit(
      [&](const auto& in) -> GridVolume::Samples {
        using T = typename std::decay_t<decltype(in)>::value_type;
        check_allocation(in.size(), sizeof(T), "a Fortran-ordered array's x-fastest copy");
        std::vector<T> out(in.size());
        const std::size_t nx = dims[0], ny = dims[1], nz = dims[2];
        std::size_t from = 0;
        for (std::size_t x = 0; x < nx; ++x)
          for (std::size_t y = 0; y < ny; ++y)
            for (std::size_t z = 0; z < nz; ++z) out[x + nx * (y + ny * z)] = in[from++];
        return out;
      },
      samples);
}

std::string shape_text(const std::vector<std::uint64_t>& shape) {
  std::string s = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
  return s + (shape.size() == 1 ? ",)" : ")");
}

// The volume whose preamble is `preamble` (file_size bytes in all); `read`
// copies bytes from an offset of the file.
GridVolume npy_volume(std::span<const std::byte> preamble, std::uint64_t file_size,
                      const std::function<void(std::uint64_t, std::span<std::byte>)>& read, const std::string& where) {
  const NpyHeader h = parse_npy_header(preamble, file_size, where);
  const Dtype dtype = parse_dtype(h.descr, where);
  if (h.shape.size() != 3)
    throw Error(where + ": the array's shape " + shape_text(h.shape) + " is " + std::to_string(h.shape.size()) +
                "-D; a volume needs a 3-D array indexed [z, y, x]");
  const auto dim = [&](int i) { return std::int64_t(std::min<std::uint64_t>(h.shape[i], std::uint64_t{1} << 40)); };
  const std::array<std::int64_t, 3> dims{dim(2), dim(1), dim(0)};
  const auto in_file = [&](auto&& f) { return naming_file(where, f); };
  const std::uint64_t n = in_file([&] { return GridVolume::checked_sample_count(dims); });
  const std::uint64_t need = n * file_sample_size(dtype.type), have = file_size - h.data_offset;
  if (have != need)
    throw Error(where + " holds " + std::to_string(have) + " data bytes; its shape " + shape_text(h.shape) +
                " and dtype '" + h.descr + "' need " + std::to_string(need));
  const std::array<int, 3> idims{int(dims[0]), int(dims[1]), int(dims[2])};
  return in_file([&] {
    GridVolume::Samples samples = decode_file_samples(dtype.type, dtype.endian, n, [&](std::span<std::byte> out) {
      read(h.data_offset, out);
    });
    if (h.fortran_order) samples = from_fortran_order(std::move(samples), idims);
    return GridVolume(idims, std::move(samples));
  });
}

std::string where_of(const std::string& source) { return "NumPy '" + source + "'"; }

}  // namespace

GridVolume read_npy_volume(const std::filesystem::path& path) {
  const std::string where = where_of(path.string());
  const std::uint64_t size = checked_file_size(path);
  // The magic and header length, then the whole preamble; the data go
  // straight from the file into the volume.
  std::vector<std::byte> preamble(std::min<std::uint64_t>(size, 12));
  read_file_range(path, 0, preamble);
  preamble.resize(npy_preamble_size(preamble, size, where));
  read_file_range(path, 0, preamble);
  return npy_volume(preamble, size, [&](std::uint64_t offset, std::span<std::byte> out) {
    read_file_range(path, offset, out);
  }, where);
}

GridVolume parse_npy_volume(std::span<const std::byte> bytes, const std::string& source) {
  return npy_volume(bytes, bytes.size(), [&](std::uint64_t offset, std::span<std::byte> out) {
    copy_range(bytes, offset, out);
  }, where_of(source));
}

}  // namespace vri
