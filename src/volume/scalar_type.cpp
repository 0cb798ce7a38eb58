#include "vri/volume.hpp"

#include <bit>
#include <cstring>

#include "vri/error.hpp"

namespace vri {

ScalarType parse_scalar_type(const std::string& name) {
  if (name == "uint8") return ScalarType::UInt8;
  if (name == "int8") return ScalarType::Int8;
  if (name == "uint16") return ScalarType::UInt16;
  if (name == "int16") return ScalarType::Int16;
  if (name == "uint32") return ScalarType::UInt32;
  if (name == "int32") return ScalarType::Int32;
  if (name == "float32") return ScalarType::Float32;
  if (name == "float64") return ScalarType::Float64;
  throw Error("unknown sample type '" + name +
              "' (known: uint8, int8, uint16, int16, uint32, int32, float32, float64)");
}

std::string scalar_type_name(ScalarType type) {
  switch (type) {
    case ScalarType::UInt8: return "uint8";
    case ScalarType::Int8: return "int8";
    case ScalarType::UInt16: return "uint16";
    case ScalarType::Int16: return "int16";
    case ScalarType::UInt32: return "uint32";
    case ScalarType::Int32: return "int32";
    case ScalarType::Float32: return "float32";
    case ScalarType::Float64: return "float64";
  }
  return "?";
}

std::size_t scalar_type_size(ScalarType type) {
  switch (type) {
    case ScalarType::UInt8:
    case ScalarType::Int8: return 1;
    case ScalarType::UInt16:
    case ScalarType::Int16: return 2;
    case ScalarType::UInt32:
    case ScalarType::Int32:
    case ScalarType::Float32: return 4;
    case ScalarType::Float64: return 8;
  }
  return 0;
}

namespace {

template <class T>
void decode_as(const std::byte* src, bool swap, std::uint64_t count, float* out) {
  unsigned char buf[sizeof(T)];
  for (std::uint64_t i = 0; i < count; ++i) {
    std::memcpy(buf, src + i * sizeof(T), sizeof(T));
    if (swap)
      for (std::size_t b = 0; b < sizeof(T) / 2; ++b) std::swap(buf[b], buf[sizeof(T) - 1 - b]);
    T v;
    std::memcpy(&v, buf, sizeof(T));
    out[i] = static_cast<float>(v);
  }
}

}  // namespace

std::vector<float> decode_samples(std::span<const std::byte> bytes, ScalarType type,
                                  Endian endian, std::uint64_t count) {
  const std::uint64_t need = count * scalar_type_size(type);
  if (bytes.size() < need)
    throw Error("sample data is " + std::to_string(bytes.size()) + " bytes, expected " +
                std::to_string(need));
  const bool swap = (endian == Endian::Big) != (std::endian::native == std::endian::big);
  std::vector<float> out(count);
  const std::byte* p = bytes.data();
  switch (type) {
    case ScalarType::UInt8: decode_as<std::uint8_t>(p, false, count, out.data()); break;
    case ScalarType::Int8: decode_as<std::int8_t>(p, false, count, out.data()); break;
    case ScalarType::UInt16: decode_as<std::uint16_t>(p, swap, count, out.data()); break;
    case ScalarType::Int16: decode_as<std::int16_t>(p, swap, count, out.data()); break;
    case ScalarType::UInt32: decode_as<std::uint32_t>(p, swap, count, out.data()); break;
    case ScalarType::Int32: decode_as<std::int32_t>(p, swap, count, out.data()); break;
    case ScalarType::Float32: decode_as<float>(p, swap, count, out.data()); break;
    case ScalarType::Float64: decode_as<double>(p, swap, count, out.data()); break;
  }
  return out;
}

}  // namespace vri
