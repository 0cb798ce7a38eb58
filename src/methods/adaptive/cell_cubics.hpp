#pragma once
// The trilinear field along a ray in four cells at once, lanes over the
// cells: what trilinear_along (cubic.hpp) gives for each, to the bit, and the
// least and greatest of each cell's corners. `guaranteed` builds its cells'
// cubics four at a time (adaptive_guaranteed.cpp); every cell of one ray
// shares the ray's direction in cell coordinates.
#include <cstddef>

#include "volume/cell_traversal.hpp"
#include "vri/volume.hpp"

namespace vri {

struct CellCubics {
  static constexpr int kLanes = 4;
  // Input: the corners c000, c100, c010, c110, c001, c101, c011, c111 (as
  // corners_as_float reads them), the cell coordinates at the segment's
  // start, and d(local)/dt.
  double corner[8][kLanes], local0[3][kLanes], dir[3];
  // Output: the cubic's coefficients c[0..3] (t from the segment's start)
  // and the corners' range.
  double c[4][kLanes], lo[kLanes], hi[kLanes];

  // Fills lane l from the cell segment `cs` of a volume with samples `values`.
  template <class T>
  void set(int l, const T* values, const GridVolume& volume, const CellSegment& cs) {
    const std::size_t sy = volume.dims()[0], sz = sy * volume.dims()[1];
    const auto v = corners_as_float(values + volume.index(cs.cell[0], cs.cell[1], cs.cell[2]), sy, sz);
    for (int k = 0; k < 8; ++k) corner[k][l] = v[k];
    for (int a = 0; a < 3; ++a) local0[a][l] = cs.local0[a], dir[a] = cs.local_dir[a];
  }
  // Fills the output of every lane; lanes from `used` on (idle at a ray's
  // end) first repeat lane 0's input.
  void run(int used = kLanes) {
    for (int l = used; l < kLanes; ++l) {
      for (int k = 0; k < 8; ++k) corner[k][l] = corner[k][0];
      for (int a = 0; a < 3; ++a) local0[a][l] = local0[a][0];
    }
    run_lanes();
  }

 private:
  void run_lanes();
};

}  // namespace vri
