// Sample types beyond ScalarType, mirrored axes and detached data paths,
// shared by the NRRD, MetaImage and .npy readers (grid_samples.hpp).
#include "grid_samples.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <system_error>
#include <type_traits>
#include <vector>

#include "vri/error.hpp"
#include "vri/memory.hpp"

namespace vri {

namespace fs = std::filesystem;

std::size_t file_sample_size(FileSampleType type) {
  switch (type) {
    case FileSampleType::Bool:
    case FileSampleType::Int8:
    case FileSampleType::UInt8: return 1;
    case FileSampleType::Int16:
    case FileSampleType::UInt16:
    case FileSampleType::Float16: return 2;
    case FileSampleType::Int32:
    case FileSampleType::UInt32:
    case FileSampleType::Float32: return 4;
    case FileSampleType::Int64:
    case FileSampleType::UInt64:
    case FileSampleType::Float64: return 8;
  }
  return 0;
}

namespace {

// IEEE 754 binary16 to float (exact: every half is a float).
float half_to_float(std::uint16_t h) {
  const int exponent = (h >> 10) & 0x1f, mantissa = h & 0x3ff;
  float v;
  if (exponent == 0) v = std::ldexp(float(mantissa), -24);  // zero and subnormals
  else if (exponent == 31) v = mantissa ? std::numeric_limits<float>::quiet_NaN() : std::numeric_limits<float>::infinity();
  else v = std::ldexp(float(mantissa + 1024), exponent - 25);
  return (h & 0x8000) ? -v : v;
}

// Samples of a type vri does not store, converted to float.
template <class T>
std::vector<float> widen(const std::vector<std::byte>& bytes, bool swap) {
  std::vector<float> out(bytes.size() / sizeof(T));
  unsigned char buf[sizeof(T)];
  for (std::size_t i = 0; i < out.size(); ++i) {
    std::memcpy(buf, bytes.data() + i * sizeof(T), sizeof(T));
    if (swap) std::reverse(buf, buf + sizeof(T));
    T v;
    std::memcpy(&v, buf, sizeof(T));
    if constexpr (std::is_same_v<T, std::uint16_t>) out[i] = half_to_float(v);
    else out[i] = static_cast<float>(v);
  }
  return out;
}

}  // namespace

GridVolume::Samples decode_file_samples(FileSampleType type, Endian endian, std::uint64_t count,
                                        const std::function<void(std::span<std::byte>)>& fill) {
  switch (type) {
    case FileSampleType::Bool: {
      GridVolume::Samples out = GridVolume::decode(ScalarType::UInt8, endian, count, fill);
      for (auto& v : std::get<std::vector<std::uint8_t>>(out)) v = v != 0;
      return out;
    }
    case FileSampleType::Int8: return GridVolume::decode(ScalarType::Int8, endian, count, fill);
    case FileSampleType::UInt8: return GridVolume::decode(ScalarType::UInt8, endian, count, fill);
    case FileSampleType::Int16: return GridVolume::decode(ScalarType::Int16, endian, count, fill);
    case FileSampleType::UInt16: return GridVolume::decode(ScalarType::UInt16, endian, count, fill);
    case FileSampleType::Int32: return GridVolume::decode(ScalarType::Int32, endian, count, fill);
    case FileSampleType::UInt32: return GridVolume::decode(ScalarType::UInt32, endian, count, fill);
    case FileSampleType::Float32: return GridVolume::decode(ScalarType::Float32, endian, count, fill);
    case FileSampleType::Float64: return GridVolume::decode(ScalarType::Float64, endian, count, fill);
    default: break;
  }
  const std::size_t size = file_sample_size(type);
  // The file's bytes and the floats beside them.
  check_allocation(count, size + sizeof(float), "a volume of " + std::to_string(count) + " samples");
  std::vector<std::byte> bytes(count * size);
  fill(bytes);
  const bool swap = (endian == Endian::Big) != (std::endian::native == std::endian::big);
  if (type == FileSampleType::Int64) return widen<std::int64_t>(bytes, swap);
  if (type == FileSampleType::UInt64) return widen<std::uint64_t>(bytes, swap);
  return widen<std::uint16_t>(bytes, swap);  // Float16
}

void flip_samples(GridVolume::Samples& samples, std::array<int, 3> dims, std::array<bool, 3> flip) {
  const std::size_t nx = dims[0], ny = dims[1], nz = dims[2];
  std::visit(
      [&](auto& v) {
        if (v.size() != nx * ny * nz) throw Error("flip_samples: the samples do not match the dims");
        const auto row = [&](std::size_t j, std::size_t k) { return v.begin() + std::ptrdiff_t(nx * (j + ny * k)); };
        if (flip[0])
          for (std::size_t k = 0; k < nz; ++k)
            for (std::size_t j = 0; j < ny; ++j) std::reverse(row(j, k), row(j, k) + std::ptrdiff_t(nx));
        if (flip[1])
          for (std::size_t k = 0; k < nz; ++k)
            for (std::size_t j = 0; j < ny / 2; ++j)
              std::swap_ranges(row(j, k), row(j, k) + std::ptrdiff_t(nx), row(ny - 1 - j, k));
        if (flip[2])
          for (std::size_t k = 0; k < nz / 2; ++k)
            std::swap_ranges(row(0, k), row(0, k) + std::ptrdiff_t(nx * ny), row(0, nz - 1 - k));
      },
      samples);
}

std::string trim_blanks(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  const auto e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::string to_lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

void copy_range(std::span<const std::byte> bytes, std::uint64_t offset, std::span<std::byte> out) {
  if (offset > bytes.size() || out.size() > bytes.size() - offset) throw Error("the data are truncated");
  if (!out.empty()) std::memcpy(out.data(), bytes.data() + offset, out.size());
}

fs::path detached_data_path(const fs::path& header_dir, const std::string& name, bool allow_outside,
                            const std::string& where, const std::string& key) {
  const fs::path dir = header_dir.empty() ? fs::path(".") : header_dir;
  if (name.empty()) throw Error(where + ": '" + key + "' is empty");
  const fs::path named(name);
  if (allow_outside) return named.is_absolute() ? named : dir / named;
  const std::string refuse = where + ": " + key + " '" + name +
                             "' is outside the header's folder; set \"allow_outside_paths\": true in the "
                             "scene's volume to allow it";
  if (named.is_absolute() || *named.lexically_normal().begin() == "..") throw Error(refuse);
  std::error_code ec;
  const fs::path real_dir = fs::weakly_canonical(dir, ec), real = fs::weakly_canonical(dir / named, ec);
  if (ec) return dir / named;  // missing: reported when it is opened
  const fs::path rel = real.lexically_relative(real_dir);
  if (rel.empty() || *rel.begin() == "..") throw Error(refuse);
  return dir / named;
}

}  // namespace vri
