// NumPy .npy files: the header (NEP 1, numpy.lib.format), float arrays for images.
#include "vri/io.hpp"

#include <charconv>
#include <cstring>
#include <string>

#include "npy_header.hpp"
#include "vri/error.hpp"
#include "vri/volume.hpp"

namespace vri {

namespace {

// A small reader of the header's Python literal: a dict of quoted keys whose
// values are a quoted string, True/False, a tuple of integers, or a list (a
// structured dtype, refused by the caller).
class DictReader {
 public:
  DictReader(const std::string& text, const std::string& where) : t_(text), where_(where) {}

  void expect(char c) {
    skip_space();
    if (i_ >= t_.size() || t_[i_] != c) fail(std::string("expected '") + c + "'");
    ++i_;
  }
  bool next_is(char c) {
    skip_space();
    return i_ < t_.size() && t_[i_] == c;
  }
  std::string quoted() {
    skip_space();
    if (i_ >= t_.size() || (t_[i_] != '\'' && t_[i_] != '"')) fail("expected a quoted string");
    const auto end = t_.find(t_[i_], i_ + 1);
    if (end == std::string::npos) fail("unterminated string");
    std::string out = t_.substr(i_ + 1, end - i_ - 1);
    i_ = end + 1;
    return out;
  }
  // The value's text as written: up to the matching bracket for ( and [,
  // the closing quote for a string, else the next ',' or '}'.
  std::string value() {
    skip_space();
    if (i_ < t_.size() && (t_[i_] == '\'' || t_[i_] == '"')) {
      // Appended, not "'" + quoted() + "'": GCC 12 warns falsely (-Wrestrict) on that form.
      std::string out(1, '\'');
      out += quoted();
      out += '\'';
      return out;
    }
    const std::size_t begin = i_;
    int depth = 0;
    for (; i_ < t_.size(); ++i_) {
      const char c = t_[i_];
      if (c == '(' || c == '[') ++depth;
      else if ((c == ')' || c == ']') && --depth == 0) return t_.substr(begin, ++i_ - begin);
      else if (depth == 0 && (c == ',' || c == '}')) break;
    }
    if (depth != 0 || i_ == begin) fail("malformed value");
    return trim(t_.substr(begin, i_ - begin));
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw Error(where_ + ": malformed .npy header (" + what + " at byte " + std::to_string(i_) + ")");
  }

 private:
  static std::string trim(const std::string& s) {
    const auto e = s.find_last_not_of(' ');
    return s.substr(0, e == std::string::npos ? 0 : e + 1);
  }
  void skip_space() {
    while (i_ < t_.size() && t_[i_] == ' ') ++i_;
  }
  const std::string& t_;
  const std::string& where_;
  std::size_t i_ = 0;
};

// "(11, 7, 5)", "(5,)" or "()": the dims; "5L" (Python 2) is read as 5.
std::vector<std::uint64_t> parse_shape(const std::string& text, const std::string& where) {
  if (text.size() < 2 || text.front() != '(' || text.back() != ')')
    throw Error(where + ": the .npy shape " + text + " is not a tuple");
  std::vector<std::uint64_t> out;
  std::size_t i = 1;
  while (i + 1 < text.size()) {
    while (i + 1 < text.size() && (text[i] == ' ' || text[i] == ',')) ++i;
    if (i + 1 >= text.size()) break;
    std::uint64_t v = 0;
    const auto [p, ec] = std::from_chars(text.data() + i, text.data() + text.size() - 1, v);
    if (ec != std::errc() || p == text.data() + i) throw Error(where + ": bad dimension in the .npy shape " + text);
    i = std::size_t(p - text.data());
    if (text[i] == 'L') ++i;
    if (text[i] != ',' && text[i] != ' ' && text[i] != ')') throw Error(where + ": bad dimension in the .npy shape " + text);
    out.push_back(v);
  }
  return out;
}

}  // namespace

std::uint64_t npy_preamble_size(std::span<const std::byte> start, std::uint64_t file_size, const std::string& where) {
  if (start.size() < 10 || std::memcmp(start.data(), "\x93NUMPY", 6) != 0) throw Error(where + " is not a .npy file");
  const auto byte = [&](std::size_t i) { return std::to_integer<std::uint64_t>(start[i]); };
  const std::uint64_t major = byte(6);
  std::uint64_t header_len, offset;
  if (major == 1) {
    header_len = byte(8) | (byte(9) << 8);
    offset = 10;
  } else if (major == 2 || major == 3) {
    if (start.size() < 12) throw Error(where + " is truncated");
    header_len = byte(8) | (byte(9) << 8) | (byte(10) << 16) | (byte(11) << 24);
    offset = 12;
  } else {
    throw Error(where + ": unsupported .npy version " + std::to_string(major) + "." + std::to_string(byte(7)));
  }
  if (header_len > (std::uint64_t{1} << 20)) throw Error(where + ": .npy header of " + std::to_string(header_len) +
                                                         " bytes, over the 1 MiB vri reads");
  if (offset + header_len > file_size) throw Error(where + " is truncated inside its .npy header");
  return offset + header_len;
}

NpyHeader parse_npy_header(std::span<const std::byte> preamble, std::uint64_t file_size, const std::string& where) {
  NpyHeader h;
  h.data_offset = npy_preamble_size(preamble, file_size, where);
  if (preamble.size() < h.data_offset) throw Error(where + " is truncated inside its .npy header");
  const std::size_t begin = preamble[6] == std::byte{1} ? 10 : 12;
  std::string text(reinterpret_cast<const char*>(preamble.data()) + begin, h.data_offset - begin);
  // numpy pads the dict with spaces and ends it with '\n'; no other control
  // character belongs in it (and none reaches a one-line message).
  text.erase(text.find_last_not_of(" \n") + 1);
  for (std::size_t i = 0; i < text.size(); ++i)
    if (static_cast<unsigned char>(text[i]) < 0x20)
      throw Error(where + ": malformed .npy header (control character at byte " + std::to_string(i) + ")");
  DictReader dict(text, where);
  bool seen[3] = {false, false, false};
  dict.expect('{');
  while (!dict.next_is('}')) {
    const std::string key = dict.quoted();
    dict.expect(':');
    const std::string value = dict.value();
    if (key == "descr") {
      if (value.front() == '[') throw Error(where + ": structured dtype " + value + " is not supported");
      if (value.front() != '\'') throw Error(where + ": dtype " + value + " is not supported");
      h.descr = value.substr(1, value.size() - 2);
      seen[0] = true;
    } else if (key == "fortran_order") {
      if (value != "True" && value != "False") dict.fail("fortran_order is " + value);
      h.fortran_order = value == "True";
      seen[1] = true;
    } else if (key == "shape") {
      h.shape = parse_shape(value, where);
      seen[2] = true;
    }
    if (!dict.next_is('}')) dict.expect(',');
  }
  if (!seen[0] || !seen[1] || !seen[2]) throw Error(where + ": .npy header lacks " +
                                                    (!seen[0] ? "'descr'" : !seen[1] ? "'fortran_order'" : "'shape'"));
  h.count = 1;
  for (std::uint64_t d : h.shape)
    if (__builtin_mul_overflow(h.count, d, &h.count)) throw Error(where + ": the .npy shape is too large");
  return h;
}

NpyArray read_npy(const std::filesystem::path& path) {
  const auto bytes = read_file(path);
  // Appended, not "'" + ...: GCC 12 warns falsely (-Wrestrict) on that form here.
  std::string where(1, '\'');
  where += path.string();
  where += '\'';
  const NpyHeader h = parse_npy_header(bytes, bytes.size(), where);
  ScalarType type;
  if (h.descr == "<f4") type = ScalarType::Float32;
  else if (h.descr == "<f8") type = ScalarType::Float64;
  else throw Error(where + ": dtype '" + h.descr + "' is not supported (float32 or float64)");
  if (h.fortran_order) throw Error(where + ": Fortran-ordered arrays are not supported");
  const std::uint64_t size = scalar_type_size(type);
  if (h.count > (std::uint64_t{1} << 34)) throw Error(where + ": array is too large");
  if (bytes.size() - h.data_offset != h.count * size)
    throw Error(where + " holds " + std::to_string(bytes.size() - h.data_offset) + " data bytes, its shape needs " +
                std::to_string(h.count * size));
  NpyArray out;
  out.shape.assign(h.shape.begin(), h.shape.end());
  out.data = decode_samples(std::span(bytes).subspan(h.data_offset), type, Endian::Little, h.count);
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
  std::vector<std::byte> header(10 + dict.size());
  std::memcpy(header.data(), "\x93NUMPY\x01\x00", 8);
  header[8] = std::byte(dict.size() & 0xff);
  header[9] = std::byte(dict.size() >> 8);
  std::memcpy(header.data() + 10, dict.data(), dict.size());
  // The floats as they are (little-endian host), after the header: no copy
  // of an image beside it (4 MiB of fresh pages at 512 x 512).
  const std::span<const std::byte> parts[] = {header, std::as_bytes(data)};
  write_file_atomically(path, parts);
}

void write_npy(const std::filesystem::path& path, const Image& image) {
  write_npy(path, {std::size_t(image.height()), std::size_t(image.width()), 4}, image.data());
}

}  // namespace vri
