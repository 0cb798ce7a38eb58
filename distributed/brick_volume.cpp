#include "brick_volume.hpp"

#include <algorithm>
#include <cmath>

#include "vri/error.hpp"
#include "vri/methods.hpp"
#include "vri/volume.hpp"

namespace vri::distributed {

int ghost_points(const MethodSpec& method) {
  const bool sampled = known_method(method.name).step_parameter == "step";
  const double piece = sampled ? 2 * method.step : 0;  // voxel units; the cell walks own whole cells
  return static_cast<int>(std::ceil(std::min(piece, 1e6))) + 3;
}

GridRegion brick_region(const BrickCells& cells, std::array<int, 3> whole_dims, int ghost) {
  GridRegion r;
  for (int a = 0; a < 3; ++a) {
    r.lo[a] = std::max(0, cells.lo[a] - ghost);
    r.hi[a] = std::min(whole_dims[a] - 1, cells.hi[a] + ghost);
  }
  return r;
}

void own_cells(GridVolume& part, const BrickCells& cells) {
  const auto& b = part.brick();
  if (!b) throw Error("own_cells: the volume is not a part of a grid");
  GridVolume::Brick owned = *b;
  owned.own_lo = cells.lo;
  owned.own_hi = cells.hi;
  for (int a = 0; a < 3; ++a)
    if (cells.lo[a] < b->offset[a] || cells.hi[a] > b->offset[a] + part.dims()[a] - 1)
      throw Error("own_cells: the brick's cells are not all in this part of the grid");
  part.set_brick(owned);
}

GridVolume cut_brick(const GridVolume& whole, const BrickCells& cells, int ghost) {
  GridVolume part = cut_region(whole, brick_region(cells, whole.dims(), ghost));
  GridVolume::Brick b = *part.brick();
  b.own_lo = cells.lo;
  b.own_hi = cells.hi;
  b.whole_min = whole.min_value();
  b.whole_max = whole.max_value();
  part.set_brick(b);
  return part;
}

}  // namespace vri::distributed
