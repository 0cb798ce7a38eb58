#pragma once
// Regular-grid samples from a VTK point array, shared by the .vti reader and
// the legacy STRUCTURED_POINTS reader: decoded straight into the volume's
// storage through grid_samples.hpp (uint8, uint16, int16 and float32 keep
// their own type; the others become float), from packed bytes or ASCII text.
#include <cstdint>
#include <functional>
#include <span>
#include <string_view>

#include "grid_samples.hpp"
#include "vri/volume.hpp"
#include "vtk_values.hpp"

namespace vri::vtk {

FileSampleType file_sample_type(Num type);

// `count` samples of `type`: `fill` writes exactly count * num_size(type)
// packed bytes (in the given byte order) into the span it is given. The
// memory budget is checked before anything is allocated.
GridVolume::Samples grid_samples(Num type, bool big_endian, std::uint64_t count,
                                 const std::function<void(std::span<std::byte>)>& fill);

// `count` samples parsed from ASCII text (parse_ascii); refuses a count the
// text cannot hold before allocating; `consumed` gets the characters read.
GridVolume::Samples grid_samples_from_text(Num type, std::uint64_t count, std::string_view text,
                                           std::size_t& consumed);

}  // namespace vri::vtk
