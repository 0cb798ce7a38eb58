// See vtk_grid.hpp.
#include "vtk_grid.hpp"

#include <bit>

namespace vri::vtk {

FileSampleType file_sample_type(Num type) {
  switch (type) {
    case Num::Int8: return FileSampleType::Int8;
    case Num::UInt8: return FileSampleType::UInt8;
    case Num::Int16: return FileSampleType::Int16;
    case Num::UInt16: return FileSampleType::UInt16;
    case Num::Int32: return FileSampleType::Int32;
    case Num::UInt32: return FileSampleType::UInt32;
    case Num::Int64: return FileSampleType::Int64;
    case Num::UInt64: return FileSampleType::UInt64;
    case Num::Float32: return FileSampleType::Float32;
    case Num::Float64: break;
  }
  return FileSampleType::Float64;
}

GridVolume::Samples grid_samples(Num type, bool big_endian, std::uint64_t count,
                                 const std::function<void(std::span<std::byte>)>& fill) {
  return decode_file_samples(file_sample_type(type), big_endian ? Endian::Big : Endian::Little, count, fill);
}

GridVolume::Samples grid_samples_from_text(Num type, std::uint64_t count, std::string_view text,
                                           std::size_t& consumed) {
  check_ascii_count(count, text.size());
  return grid_samples(type, std::endian::native == std::endian::big, count,
                      [&](std::span<std::byte> out) { consumed = parse_ascii(type, text, out); });
}

}  // namespace vri::vtk
