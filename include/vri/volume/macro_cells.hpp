#pragma once
// MacroCells: the min/max grid of empty-space skipping (Levoy 1990, "Efficient
// ray tracing of volume data", §3: a pyramid of occupancy; here its one coarse
// level, as in Parker et al. 1998 and VTK's FixedPoint space leaping). Macro
// cell (I, J, K) covers the grid cells [8I, 8I + 8) x [8J, 8J + 8) x [8K, 8K + 8)
// (fewer at the far faces) and holds the min and max of the samples on its
// corner points 8I .. 8I + 8, ..., so the trilinear field anywhere in it lies
// in [min, max] (a convex combination of its cells' corners). Built once per
// volume, O(samples); the transfer function is applied later (EmptySpace).
#include <array>
#include <cstddef>
#include <vector>

#include "vri/volume/grid_volume.hpp"

namespace vri {

class MacroCells {
 public:
  static constexpr int kCells = 8;  // grid cells per macro cell a side

  explicit MacroCells(const GridVolume& volume);

  const GridVolume& volume() const { return volume_; }
  const std::array<int, 3>& dims() const { return dims_; }
  std::size_t count() const { return lo_.size(); }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(dims_[0]) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims_[1]) * k);
  }
  // The range of the field over macro cell `index`.
  float min(std::size_t index) const { return lo_[index]; }
  float max(std::size_t index) const { return hi_[index]; }

 private:
  const GridVolume& volume_;
  std::array<int, 3> dims_;
  std::vector<float> lo_, hi_;
};

}  // namespace vri
