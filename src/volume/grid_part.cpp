#include "vri/volume.hpp"

#include <string>
#include <vector>

#include "vri/error.hpp"

namespace vri {

void check_region(const GridRegion& r, std::array<int, 3> dims) {
  for (int a = 0; a < 3; ++a)
    if (!(r.lo[a] >= 0 && r.hi[a] < dims[a] && r.hi[a] - r.lo[a] >= 1))
      throw Error("the region " + std::to_string(r.lo[a]) + ".." + std::to_string(r.hi[a]) + " on axis " +
                  std::to_string(a) + " does not lie in the grid's " + std::to_string(dims[a]) + " points");
}

GridVolume make_part(GridVolume::Samples samples, std::array<int, 3> whole_dims, const GridRegion& region,
                     Vec3 spacing, Vec3 whole_origin) {
  check_region(region, whole_dims);
  GridVolume part(region.dims(), std::move(samples), spacing);
  part.set_brick({.whole_dims = whole_dims,
                  .offset = region.lo,
                  .whole_origin = whole_origin,
                  .own_lo = {0, 0, 0},
                  .own_hi = {whole_dims[0] - 1, whole_dims[1] - 1, whole_dims[2] - 1},
                  .whole_min = part.min_value(),
                  .whole_max = part.max_value()});
  return part;
}

GridVolume cut_region(const GridVolume& volume, const GridRegion& region) {
  check_region(region, volume.dims());
  const auto d = region.dims();
  GridVolume::Samples samples = volume.visit([&](auto v) -> GridVolume::Samples {
    using T = typename decltype(v)::value_type;
    std::vector<T> out;
    out.reserve(region.points());
    for (int k = region.lo[2]; k <= region.hi[2]; ++k)
      for (int j = region.lo[1]; j <= region.hi[1]; ++j) {
        const auto row = v.begin() + static_cast<std::ptrdiff_t>(volume.index(region.lo[0], j, k));
        out.insert(out.end(), row, row + d[0]);
      }
    return out;
  });
  return make_part(std::move(samples), volume.dims(), region, volume.spacing(), volume.origin());
}

}  // namespace vri
