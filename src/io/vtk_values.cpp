// See vtk_values.hpp.
#include "vtk_values.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <type_traits>

#include "vri/error.hpp"
#include "vri/memory.hpp"

namespace vri::vtk {

std::optional<Num> parse_num(const std::string& name) {
  static const std::map<std::string, Num> names = {
      {"char", Num::Int8},           {"signed_char", Num::Int8},  {"unsigned_char", Num::UInt8},
      {"short", Num::Int16},         {"unsigned_short", Num::UInt16}, {"int", Num::Int32},
      {"unsigned_int", Num::UInt32}, {"long", Num::Int64},        {"unsigned_long", Num::UInt64},
      {"vtktypeint64", Num::Int64},  {"vtktypeuint64", Num::UInt64}, {"vtkIdType", Num::Int64},
      {"float", Num::Float32},       {"double", Num::Float64},    {"Int8", Num::Int8},
      {"UInt8", Num::UInt8},         {"Int16", Num::Int16},       {"UInt16", Num::UInt16},
      {"Int32", Num::Int32},         {"UInt32", Num::UInt32},     {"Int64", Num::Int64},
      {"UInt64", Num::UInt64},       {"Float32", Num::Float32},   {"Float64", Num::Float64}};
  const auto it = names.find(name);
  if (it == names.end()) return std::nullopt;
  return it->second;
}

std::size_t num_size(Num type) {
  switch (type) {
    case Num::Int8: case Num::UInt8: return 1;
    case Num::Int16: case Num::UInt16: return 2;
    case Num::Int32: case Num::UInt32: case Num::Float32: return 4;
    default: return 8;
  }
}

std::string num_name(Num type) {
  static const char* const names[] = {"Int8",  "UInt8",  "Int16", "UInt16",  "Int32",
                                      "UInt32", "Int64", "UInt64", "Float32", "Float64"};
  return names[static_cast<int>(type)];
}

namespace {

template <class T>
double load(const std::byte* p, bool swap) {
  unsigned char b[sizeof(T)];
  std::memcpy(b, p, sizeof(T));
  if (swap)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
  T v;
  std::memcpy(&v, b, sizeof(T));
  return static_cast<double>(v);
}

}  // namespace

ChargedVector<double> decode(std::span<const std::byte> bytes, Num type, std::size_t count, bool big_endian) {
  const std::size_t size = num_size(type);
  if (bytes.size() / size < count)
    throw Error("binary data ends early: " + std::to_string(count) + " values need " +
                std::to_string(count * size) + " bytes, " + std::to_string(bytes.size()) + " left");
  const bool swap = big_endian != (std::endian::native == std::endian::big);
  check_allocation(count, sizeof(double), "an array of " + std::to_string(count) + " values");
  ChargedVector<double> out(count);
  const std::byte* p = bytes.data();
  for (std::size_t i = 0; i < count; ++i, p += size) {
    switch (type) {
      case Num::Int8: out[i] = load<std::int8_t>(p, swap); break;
      case Num::UInt8: out[i] = load<std::uint8_t>(p, swap); break;
      case Num::Int16: out[i] = load<std::int16_t>(p, swap); break;
      case Num::UInt16: out[i] = load<std::uint16_t>(p, swap); break;
      case Num::Int32: out[i] = load<std::int32_t>(p, swap); break;
      case Num::UInt32: out[i] = load<std::uint32_t>(p, swap); break;
      case Num::Int64: out[i] = load<std::int64_t>(p, swap); break;
      case Num::UInt64: out[i] = load<std::uint64_t>(p, swap); break;
      case Num::Float32: out[i] = load<float>(p, swap); break;
      case Num::Float64: out[i] = load<double>(p, swap); break;
    }
  }
  return out;
}

namespace {

// Stores a parsed ASCII number as T, refusing fractions and values out of T's range.
template <class T>
void store(double v, std::byte* p, std::string_view token, Num type) {
  if constexpr (std::is_floating_point_v<T>) {
    const T t = static_cast<T>(v);
    std::memcpy(p, &t, sizeof(T));
  } else {
    const double hi = std::ldexp(1.0, std::numeric_limits<T>::digits);
    const double lo = std::is_signed_v<T> ? -hi : 0.0;
    if (!(v >= lo && v < hi) || v != std::floor(v))
      throw Error("value '" + std::string(token) + "' is not a valid " + num_name(type));
    const T t = static_cast<T>(v);
    std::memcpy(p, &t, sizeof(T));
  }
}

}  // namespace

void check_ascii_count(std::uint64_t count, std::uint64_t bytes_left) {
  if (count > bytes_left / 2 + 1)
    throw Error("data ends early: " + std::to_string(count) + " values declared, " + std::to_string(bytes_left) +
                " bytes left: fewer than " + std::to_string(count) + " values fit");
}

std::size_t parse_ascii(Num type, std::string_view text, std::span<std::byte> out) {
  const std::size_t size = num_size(type), count = out.size() / size;
  const char* const begin = text.data();
  const char* const end = begin + text.size();
  const char* p = begin;
  for (std::size_t i = 0; i < count; ++i) {
    while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
    if (p == end) throw Error("data ends early: fewer than " + std::to_string(count) + " values");
    const char* first = *p == '+' ? p + 1 : p;
    std::from_chars_result r{};
    double v = 0;
    float f = 0;
    if (type == Num::Float32) r = std::from_chars(first, end, f);  // parsed as float: no double rounding
    else r = std::from_chars(first, end, v);
    if (r.ec != std::errc() || (r.ptr < end && !std::isspace(static_cast<unsigned char>(*r.ptr))))
      throw Error("bad number '" + std::string(p, std::min<std::size_t>(20, end - p)) + "'");
    const std::string_view token(p, r.ptr - p);
    std::byte* at = out.data() + i * size;
    switch (type) {
      case Num::Int8: store<std::int8_t>(v, at, token, type); break;
      case Num::UInt8: store<std::uint8_t>(v, at, token, type); break;
      case Num::Int16: store<std::int16_t>(v, at, token, type); break;
      case Num::UInt16: store<std::uint16_t>(v, at, token, type); break;
      case Num::Int32: store<std::int32_t>(v, at, token, type); break;
      case Num::UInt32: store<std::uint32_t>(v, at, token, type); break;
      case Num::Int64: store<std::int64_t>(v, at, token, type); break;
      case Num::UInt64: store<std::uint64_t>(v, at, token, type); break;
      case Num::Float32: std::memcpy(at, &f, sizeof f); break;
      case Num::Float64: store<double>(v, at, token, type); break;
    }
    p = r.ptr;
  }
  return std::size_t(p - begin);
}

ChargedVector<std::int64_t> to_indices(std::span<const double> values, const std::string& what) {
  ChargedVector<std::int64_t> out(values.size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const double v = values[i];
    if (!(v >= 0 && v < 9.0e15) || v != std::floor(v))
      throw Error(what + " entry " + std::to_string(i) + " is not a valid index (" + std::to_string(v) + ")");
    out[i] = static_cast<std::int64_t>(v);
  }
  return out;
}

std::vector<TetMesh::Tet> tets_from_cells(std::span<const std::int64_t> connectivity,
                                          std::span<const std::int64_t> offsets,
                                          std::span<const std::int64_t> types) {
  if (offsets.size() != types.size() + 1) throw Error("cell offsets and cell types disagree in count");
  std::vector<TetMesh::Tet> tets(types.size());
  for (std::size_t c = 0; c < types.size(); ++c) {
    const std::int64_t a = offsets[c], b = offsets[c + 1];
    if (types[c] != 10)
      throw Error("cell " + std::to_string(c) + " has VTK type " + std::to_string(types[c]) +
                  "; only tetrahedra (type 10) are supported");
    if (b - a != 4 || a < 0 || std::size_t(b) > connectivity.size())
      throw Error("cell " + std::to_string(c) + " is a tetrahedron with " + std::to_string(b - a) + " points");
    for (int k = 0; k < 4; ++k) {
      if (connectivity[a + k] > INT32_MAX)
        throw Error("cell " + std::to_string(c) + " refers to point " + std::to_string(connectivity[a + k]));
      tets[c][k] = static_cast<std::int32_t>(connectivity[a + k]);
    }
  }
  return tets;
}

std::vector<Vec3> points_from(std::span<const double> xyz) {
  std::vector<Vec3> points(xyz.size() / 3);
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  return points;
}

std::size_t choose_point_array(const std::vector<NamedArray>& arrays, const std::string& wanted,
                               const std::string& active) {
  std::string names;
  std::optional<std::size_t> named, active_one, first_one;
  for (std::size_t i = 0; i < arrays.size(); ++i) {
    const NamedArray& a = arrays[i];
    names += (names.empty() ? "" : ", ") + a.name;
    if (a.components != 1) names += " [" + std::to_string(a.components) + " components]";
    if (!named && a.name == wanted) named = i;
    if (!active_one && a.components == 1 && !active.empty() && a.name == active) active_one = i;
    if (!first_one && a.components == 1) first_one = i;
  }
  if (!wanted.empty()) {
    if (!named) throw Error("no point scalars named '" + wanted + "' (the file has: " + (names.empty() ? "none" : names) + ")");
    if (arrays[*named].components != 1)
      throw Error("point array '" + wanted + "' has " + std::to_string(arrays[*named].components) +
                  " components; vri renders one-component scalars");
    return *named;
  }
  if (active_one) return *active_one;
  if (!first_one)
    throw Error("no one-component point scalars" + (names.empty() ? std::string() : " (the file has: " + names + ")"));
  return *first_one;
}

}  // namespace vri::vtk
