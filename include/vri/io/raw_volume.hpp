#pragma once
// Headerless raw volumes (SPEC §1): nx*ny*nz samples, x fastest.
#include <array>
#include <filesystem>

#include "vri/volume/grid_part.hpp"
#include "vri/volume/grid_volume.hpp"
#include "vri/volume/scalar_type.hpp"

namespace vri {

// The file must hold exactly nx*ny*nz samples of `type`; a short or oversized
// file is refused, since either means the dims or the type are wrong.
// With `region`, only the region it picks is read (a part, grid_part.hpp).
GridVolume read_raw_volume(const std::filesystem::path& path, std::array<std::int64_t, 3> dims,
                           ScalarType type, Endian endian = Endian::Little, const RegionChooser& region = {});

}  // namespace vri
