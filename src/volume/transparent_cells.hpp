#pragma once
// TransparentCells: one bit per grid cell, set where the cell's corners'
// range (widened by the rounding margin) has zero extinction - the test the
// guaranteed adaptive integrator makes on every cell it walks, made once per
// transfer function instead. Only the cells of non-empty macro cells are
// classified (a walk over runs of them meets no others but at their faces);
// a clear bit means "not known transparent", so a cell left out is simply
// tested again. 1 bit a cell: an eighth of a byte volume's size; each
// z-plane of cells starts on a fresh 64-bit word, so the planes of
// different macro-cell layers are built in parallel.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "tables/zero_opacity.hpp"
#include "volume/empty_space.hpp"
#include "vri/volume.hpp"

namespace vri {

class TransparentCells {
 public:
  // The cells of `space`'s non-empty macro cells against `zero` over their
  // corners' range +- margin.
  TransparentCells(const GridVolume& volume, const EmptySpace& space, const ZeroOpacityBins& zero, double margin);

  bool transparent(int i, int j, int k) const {
    const std::size_t b = bit(i, j, k);
    return (bits_[b >> 6] >> (b & 63)) & 1;
  }
  std::size_t count() const;  // cells marked transparent

 private:
  std::size_t bit(int i, int j, int k) const {
    return static_cast<std::size_t>(k) * plane_bits_ + static_cast<std::size_t>(j) * row_ + static_cast<std::size_t>(i);
  }
  std::size_t row_, plane_bits_;  // bits a row of cells, a plane (a whole number of words)
  std::vector<std::uint64_t> bits_;
};

}  // namespace vri
