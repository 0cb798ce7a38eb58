#include "vri/volume/macro_cells.hpp"

#include <algorithm>

namespace vri {

namespace {

// Macro cells along an axis of n points (n - 1 grid cells).
int macro_count(int n) { return (n - 2) / MacroCells::kCells + 1; }

// Reduces `in` (extent a x b x c, x fastest) along its first axis in windows of
// kCells + 1 points that overlap by one, and writes the result transposed so
// the next pass reduces the next axis: out has extent b x c x macro_count(a).
void reduce_axis(const std::vector<float>& lo_in, const std::vector<float>& hi_in, std::array<int, 3> extent,
                 std::vector<float>& lo_out, std::vector<float>& hi_out) {
  const int a = extent[0], b = extent[1], c = extent[2], m = macro_count(a);
  lo_out.assign(static_cast<std::size_t>(m) * b * c, 0);
  hi_out.assign(lo_out.size(), 0);
  for (int z = 0; z < c; ++z)
    for (int y = 0; y < b; ++y) {
      const std::size_t row = (static_cast<std::size_t>(z) * b + y) * a;
      for (int i = 0; i < m; ++i) {
        const int x0 = i * MacroCells::kCells, x1 = std::min(a - 1, x0 + MacroCells::kCells);
        float lo = lo_in[row + x0], hi = hi_in[row + x0];
        for (int x = x0 + 1; x <= x1; ++x) {
          lo = std::min(lo, lo_in[row + x]);
          hi = std::max(hi, hi_in[row + x]);
        }
        const std::size_t o = static_cast<std::size_t>(y) + static_cast<std::size_t>(b) * (z + static_cast<std::size_t>(c) * i);
        lo_out[o] = lo;
        hi_out[o] = hi;
      }
    }
}

}  // namespace

MacroCells::MacroCells(const GridVolume& volume)
    : volume_(volume),
      dims_{macro_count(volume.dims()[0]), macro_count(volume.dims()[1]), macro_count(volume.dims()[2])} {
  // Three separable passes, x then y then z; each transposes (x, y, z) -> (y, z, x),
  // so after three the layout is x fastest again.
  std::array<int, 3> extent = volume.dims();
  std::vector<float> lo, hi;
  reduce_axis(volume.values(), volume.values(), extent, lo, hi);
  extent = {extent[1], extent[2], dims_[0]};
  reduce_axis(lo, hi, extent, lo_, hi_);
  extent = {extent[1], extent[2], dims_[1]};
  reduce_axis(lo_, hi_, extent, lo, hi);
  lo_ = std::move(lo);
  hi_ = std::move(hi);
}

}  // namespace vri
