#pragma once
// MacroCells: the min/max grid of empty-space skipping (Levoy 1990, "Efficient
// ray tracing of volume data", §3: a pyramid of occupancy; here its one coarse
// level, as in Parker et al. 1998 and VTK's FixedPoint space leaping). Macro
// cell (I, J, K) covers the grid cells [8I, 8I + 8) x [8J, 8J + 8) x [8K, 8K + 8)
// (fewer at the far faces) and holds the min and max of the samples on its
// corner points 8I .. 8I + 8, ..., so the trilinear field anywhere in it lies
// in [min, max] (a convex combination of its cells' corners). Computed once per
// volume, O(samples), and kept by it (GridVolume::macro_ranges); the transfer
// function is applied later (EmptySpace).
#include <array>
#include <cstddef>
#include <vector>

#include "vri/volume.hpp"

namespace vri {

// The ranges themselves: dims macro cells, x fastest.
struct MacroRanges {
  std::array<int, 3> dims;
  std::vector<float> lo, hi;
};
// O(samples); GridVolume::macro_ranges() calls it once per volume.
MacroRanges compute_macro_ranges(const GridVolume& volume);

class MacroCells {
 public:
  static constexpr int kCells = 8;  // grid cells per macro cell a side

  // The volume's ranges (computed on the first call for a volume).
  explicit MacroCells(const GridVolume& volume) : volume_(volume), ranges_(volume.macro_ranges()) {}

  const GridVolume& volume() const { return volume_; }
  const std::array<int, 3>& dims() const { return ranges_.dims; }
  std::size_t count() const { return ranges_.lo.size(); }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) + static_cast<std::size_t>(ranges_.dims[0]) *
                                             (static_cast<std::size_t>(j) + static_cast<std::size_t>(ranges_.dims[1]) * k);
  }
  // The range of the field over macro cell `index`.
  float min(std::size_t index) const { return ranges_.lo[index]; }
  float max(std::size_t index) const { return ranges_.hi[index]; }

 private:
  const GridVolume& volume_;
  const MacroRanges& ranges_;
};

}  // namespace vri
