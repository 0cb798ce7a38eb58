#include "vri/io.hpp"

#include <string>

#include "vri/error.hpp"
#include "io/grid_region.hpp"

namespace vri {

GridVolume read_raw_volume(const std::filesystem::path& path, std::array<std::int64_t, 3> dims,
                           ScalarType type, Endian endian, const RegionChooser& region) {
  const std::uint64_t n = GridVolume::checked_sample_count(dims);
  const std::uint64_t need = n * scalar_type_size(type);
  const std::uint64_t size = checked_file_size(path);
  if (size != need)  // check before reading: an oversized file is refused cheaply
    throw Error("'" + path.string() + "' is " + std::to_string(size) + " bytes, but " +
                std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
                std::to_string(dims[2]) + " " + scalar_type_name(type) + " needs " +
                std::to_string(need));
  const std::array<int, 3> d{int(dims[0]), int(dims[1]), int(dims[2])};
  if (region) {  // one part: its rows alone
    const GridRegion r = region(d);
    return make_part(read_region_from_file(path, 0, type, endian, d, r), d, r);
  }
  return GridVolume(d, GridVolume::decode(type, endian, n, [&](std::span<std::byte> out) { read_file_range(path, 0, out); }));
}

}  // namespace vri
