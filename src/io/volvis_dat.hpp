#pragma once
// The volvis.org ".dat" format: three little-endian uint16 dims, then uint16 samples.
#include <filesystem>

#include "vri/volume.hpp"

namespace vri {

GridVolume read_volvis_dat(const std::filesystem::path& path);
// Samples are rounded and clamped to [0, 65535].
void write_volvis_dat(const std::filesystem::path& path, const GridVolume& volume);

}  // namespace vri
