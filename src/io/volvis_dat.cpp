#include "io/volvis_dat.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "vri/error.hpp"
#include "vri/io.hpp"
#include "vri/volume.hpp"

namespace vri {

GridVolume read_volvis_dat(const std::filesystem::path& path) {
  const std::uint64_t size = checked_file_size(path);
  if (size < 6) throw Error("'" + path.string() + "' is too short for a .dat header (6 bytes)");
  std::array<std::byte, 6> header;
  read_file_range(path, 0, header);
  const auto dims16 = decode_samples(header, ScalarType::UInt16, Endian::Little, 3);
  const std::array<std::int64_t, 3> dims{std::int64_t(dims16[0]), std::int64_t(dims16[1]),
                                         std::int64_t(dims16[2])};
  const std::uint64_t n = GridVolume::checked_sample_count(dims);
  if (size != 6 + 2 * n)
    throw Error("'" + path.string() + "' is " + std::to_string(size) + " bytes, but a " +
                std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
                std::to_string(dims[2]) + " .dat volume needs " + std::to_string(6 + 2 * n));
  return GridVolume({int(dims[0]), int(dims[1]), int(dims[2])},
                    GridVolume::decode(ScalarType::UInt16, Endian::Little, n,
                                       [&](std::span<std::byte> out) { read_file_range(path, 6, out); }));
}

void write_volvis_dat(const std::filesystem::path& path, const GridVolume& volume) {
  const auto& d = volume.dims();
  for (int a = 0; a < 3; ++a)
    if (d[a] > 65535) throw Error(".dat dims must fit in uint16");
  std::vector<std::byte> out;
  out.reserve(6 + 2 * volume.size());
  auto put = [&](std::uint16_t v) {
    out.push_back(std::byte(v & 0xff));
    out.push_back(std::byte(v >> 8));
  };
  for (int a = 0; a < 3; ++a) put(static_cast<std::uint16_t>(d[a]));
  for (std::size_t i = 0; i < volume.size(); ++i)
    put(static_cast<std::uint16_t>(std::clamp(std::lround(volume.value(i)), 0L, 65535L)));
  write_file_atomically(path, out);
}

}  // namespace vri
