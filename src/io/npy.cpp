#include "vri/io/npy.hpp"

#include <cstring>
#include <string>

#include "vri/core/error.hpp"
#include "vri/io/file_io.hpp"
#include "vri/volume/scalar_type.hpp"

namespace vri {

namespace {

// The value text after 'key': in a numpy header dict.
std::string dict_value(const std::string& header, const std::string& key, const std::string& where) {
  const auto k = header.find("'" + key + "'");
  if (k == std::string::npos) throw Error(where + ": header lacks '" + key + "'");
  auto p = header.find(':', k);
  if (p == std::string::npos) throw Error(where + ": malformed header");
  ++p;
  while (p < header.size() && header[p] == ' ') ++p;
  std::size_t e = p;
  if (header[p] == '(') e = header.find(')', p) + 1;
  else if (header[p] == '\'') e = header.find('\'', p + 1) + 1;
  else while (e < header.size() && header[e] != ',' && header[e] != '}') ++e;
  if (e == std::string::npos || e <= p) throw Error(where + ": malformed header");
  return header.substr(p, e - p);
}

}  // namespace

NpyArray read_npy(const std::filesystem::path& path) {
  const auto bytes = read_file(path);
  // Appended, not "'" + ...: GCC 12 warns falsely (-Wrestrict) on that form here.
  std::string where(1, '\'');
  where += path.string();
  where += '\'';
  if (bytes.size() < 10 || std::memcmp(bytes.data(), "\x93NUMPY", 6) != 0)
    throw Error(where + " is not a .npy file");
  const int major = int(bytes[6]);
  std::size_t header_len, offset;
  if (major == 1) {
    header_len = std::size_t(bytes[8]) | (std::size_t(bytes[9]) << 8);
    offset = 10;
  } else if (major == 2 || major == 3) {
    if (bytes.size() < 12) throw Error(where + " is truncated");
    header_len = std::size_t(bytes[8]) | (std::size_t(bytes[9]) << 8) | (std::size_t(bytes[10]) << 16) |
                 (std::size_t(bytes[11]) << 24);
    offset = 12;
  } else {
    throw Error(where + ": unsupported .npy version " + std::to_string(major));
  }
  if (offset + header_len > bytes.size()) throw Error(where + " is truncated");
  const std::string header(reinterpret_cast<const char*>(bytes.data()) + offset, header_len);
  const std::string descr = dict_value(header, "descr", where);
  ScalarType type;
  if (descr == "'<f4'") type = ScalarType::Float32;
  else if (descr == "'<f8'") type = ScalarType::Float64;
  else throw Error(where + ": dtype " + descr + " is not supported (float32 or float64)");
  if (dict_value(header, "fortran_order", where) != "False")
    throw Error(where + ": Fortran-ordered arrays are not supported");
  NpyArray out;
  std::string shape = dict_value(header, "shape", where);
  std::size_t count = 1;
  for (std::size_t i = 1; i < shape.size();) {
    if (std::isdigit(static_cast<unsigned char>(shape[i]))) {
      std::size_t end;
      const unsigned long long v = std::stoull(shape.substr(i), &end);
      out.shape.push_back(v);
      if (v > 0 && count > (std::size_t(1) << 34) / v) throw Error(where + ": array is too large");
      count *= v;
      i += end;
    } else {
      ++i;
    }
  }
  const std::size_t data_off = offset + header_len;
  const std::size_t need = count * scalar_type_size(type);
  if (bytes.size() - data_off != need)
    throw Error(where + " holds " + std::to_string(bytes.size() - data_off) + " data bytes, its shape needs " +
                std::to_string(need));
  out.data = decode_samples(std::span(bytes).subspan(data_off), type, Endian::Little, count);
  return out;
}

void write_npy(const std::filesystem::path& path, const std::vector<std::size_t>& shape,
               std::span<const float> data) {
  std::string tuple;
  for (std::size_t i = 0; i < shape.size(); ++i) tuple += (i ? ", " : "") + std::to_string(shape[i]);
  if (shape.size() == 1) tuple += ",";  // a Python 1-tuple
  std::string dict = "{'descr': '<f4', 'fortran_order': False, 'shape': (" + tuple + "), }";
  // Pad with spaces so that the data starts on a 64-byte boundary (format v1.0).
  std::size_t total = 10 + dict.size() + 1;
  dict.append((64 - total % 64) % 64, ' ');
  dict += '\n';
  std::vector<std::byte> out(10 + dict.size() + data.size() * sizeof(float));
  std::memcpy(out.data(), "\x93NUMPY\x01\x00", 8);
  out[8] = std::byte(dict.size() & 0xff);
  out[9] = std::byte(dict.size() >> 8);
  std::memcpy(out.data() + 10, dict.data(), dict.size());
  std::memcpy(out.data() + 10 + dict.size(), data.data(), data.size() * sizeof(float));  // little-endian host
  write_file_atomically(path, out);
}

void write_npy(const std::filesystem::path& path, const Image& image) {
  write_npy(path, {std::size_t(image.height()), std::size_t(image.width()), 4}, image.data());
}

}  // namespace vri
