#pragma once
// ScalarType: the binary sample types vri reads, and their conversion to float.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace vri {

enum class ScalarType { UInt8, Int8, UInt16, Int16, UInt32, Int32, Float32, Float64 };
enum class Endian { Little, Big };

// SPEC names: uint8, uint16, int16, float32; also int8, uint32, int32, float64.
// Throws vri::Error for an unknown name.
ScalarType parse_scalar_type(const std::string& name);
std::string scalar_type_name(ScalarType type);
std::size_t scalar_type_size(ScalarType type);

// Converts `count` packed samples to float. Throws if `bytes` is too short.
std::vector<float> decode_samples(std::span<const std::byte> bytes, ScalarType type,
                                  Endian endian, std::uint64_t count);

}  // namespace vri
