#pragma once
// A part of a grid (distributed rendering: one rank's brick, docs/
// DISTRIBUTED.md): the points lo..hi (inclusive) on each axis, and the
// volume that holds them as a part of the whole grid (GridVolume::Brick).
// Readers take a RegionChooser and read the part alone (io/grid_region.hpp).
#include <array>
#include <cstdint>
#include <functional>

#include "vri/volume/grid_volume.hpp"

namespace vri {

struct GridRegion {
  std::array<int, 3> lo, hi;  // grid points, inclusive
  std::array<int, 3> dims() const { return {hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1}; }
  std::uint64_t points() const {
    const auto d = dims();
    return std::uint64_t(d[0]) * d[1] * d[2];
  }
};

// Chooses the region of a grid of `dims` points, once a reader knows them.
using RegionChooser = std::function<GridRegion(std::array<int, 3> dims)>;

// Throws vri::Error unless `region` lies in a grid of `dims` with 2 points a side at least.
void check_region(const GridRegion& region, std::array<int, 3> dims);

// The region's samples as a part of a grid of `whole_dims` points
// (GridVolume::Brick) owning all its cells until told otherwise, with the
// whole grid's spacing and origin; min and max its own until the whole
// grid's are known.
GridVolume make_part(GridVolume::Samples samples, std::array<int, 3> whole_dims, const GridRegion& region,
                     Vec3 spacing = {1, 1, 1}, Vec3 whole_origin = {0, 0, 0});

// The region of a volume in memory, as a part of it (make_part).
GridVolume cut_region(const GridVolume& volume, const GridRegion& region);

}  // namespace vri
