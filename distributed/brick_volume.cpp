#include "brick_volume.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vri::distributed {

int ghost_points(const MethodSpec& method) {
  const bool sampled = method.name == "riemann" || method.name == "preint1" || method.name == "preint2";
  const double piece = sampled ? 2 * method.step : 0;  // voxel units; the cell walks own whole cells
  return static_cast<int>(std::ceil(std::min(piece, 1e6))) + 3;
}

GridVolume cut_brick(const GridVolume& whole, const BrickCells& cells, int ghost) {
  const auto& n = whole.dims();
  std::array<int, 3> p0, dims;
  for (int a = 0; a < 3; ++a) {
    p0[a] = std::max(0, cells.lo[a] - ghost);
    dims[a] = std::min(n[a] - 1, cells.hi[a] + ghost) - p0[a] + 1;
  }
  GridVolume::Samples samples = whole.visit([&](auto v) -> GridVolume::Samples {
    using T = typename decltype(v)::value_type;
    const std::size_t count = static_cast<std::size_t>(dims[0]) * dims[1] * dims[2];
    std::vector<std::remove_const_t<T>> out(count);
    std::size_t i = 0;
    for (int k = 0; k < dims[2]; ++k)
      for (int j = 0; j < dims[1]; ++j) {
        const T* row = v.data() + whole.index(p0[0], p0[1] + j, p0[2] + k);
        i = std::copy(row, row + dims[0], out.begin() + i) - out.begin();
      }
    return out;
  });
  const Vec3 o = whole.origin(), s = whole.spacing();
  const auto at = [&](int a, int point) { return o[a] + point * s[a]; };  // as GridVolume::box_hi
  GridVolume brick(dims, std::move(samples), s, {at(0, p0[0]), at(1, p0[1]), at(2, p0[2])});
  brick.set_brick({.whole_lo = whole.box_lo(),
                   .whole_hi = whole.box_hi(),
                   .own_lo = {at(0, cells.lo[0]), at(1, cells.lo[1]), at(2, cells.lo[2])},
                   .own_hi = {at(0, cells.hi[0]), at(1, cells.hi[1]), at(2, cells.hi[2])},
                   .whole_min = whole.min_value(),
                   .whole_max = whole.max_value()});
  return brick;
}

}  // namespace vri::distributed
