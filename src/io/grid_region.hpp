#pragma once
// Reading one part of a grid (volume/grid_part.hpp) from a file: readers
// that can seek (raw, NRRD raw) read the region's rows alone; a gzip stream
// is read through once, keeping the region; other formats are read whole
// and cut.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>

#include "vri/volume.hpp"

namespace vri {

// The region's samples from an x-fastest layout of `dims` samples of `type`:
// `read(byte offset, out)` fills `out` from the layout, one call per run of
// rows that lie end to end in the layout (a whole plane, or the whole
// region, when it spans the grid's width), so nothing outside it is read.
GridVolume::Samples read_region(ScalarType type, Endian endian, std::array<int, 3> dims, const GridRegion& region,
                                const std::function<void(std::uint64_t, std::span<std::byte>)>& read);

// The same from a file holding the layout from byte `start`: one pread a run,
// straight into the samples (issue 47: an ifstream's 8 KiB buffer, refilled
// after every seek, read 7.7 times a brick's bytes).
GridVolume::Samples read_region_from_file(const std::filesystem::path& path, std::uint64_t start, ScalarType type,
                                          Endian endian, std::array<int, 3> dims, const GridRegion& region);

// The same from a stream of the whole layout handed over in pieces (offset,
// bytes) in order: `feed` runs the stream and calls its argument with each
// piece (a gzip stream, gzip.hpp's gunzip_each).
GridVolume::Samples read_region_streamed(
    ScalarType type, Endian endian, std::array<int, 3> dims, const GridRegion& region,
    const std::function<void(const std::function<void(std::uint64_t, std::span<const std::byte>)>&)>& feed);

}  // namespace vri
