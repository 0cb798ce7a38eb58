#pragma once
// One rank's part of the volume in sort-last rendering: the points of its
// brick's cells and a ghost layer around them, as a GridVolume that knows it
// is a brick (GridVolume::Brick), so every method integrates exactly the
// pieces of each ray that start in the brick, on the whole ray's samples.
#include "kd_bricks.hpp"
#include "vri/methods.hpp"
#include "vri/volume.hpp"

namespace vri::distributed {

// Ghost points a method needs on each side of its brick: a piece it owns
// starts in the brick and reads samples up to one piece (two steps for
// preint2's slabs) further, trilinear reads the next point and lighting's
// central differences one more; one more for rounding.
int ghost_points(const MethodSpec& method);

// The points a brick's rank reads: its cells' points and `ghost` more on
// each side, clamped to the grid.
GridRegion brick_region(const BrickCells& cells, std::array<int, 3> whole_dims, int ghost);

// Makes `part` (a part of a grid read by brick_region) own `cells`.
void own_cells(GridVolume& part, const BrickCells& cells);

// The brick of `whole` owning `cells`, with `ghost` points around them.
GridVolume cut_brick(const GridVolume& whole, const BrickCells& cells, int ghost);

}  // namespace vri::distributed
