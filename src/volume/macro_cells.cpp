#include "volume/macro_cells.hpp"

#include <algorithm>
#include <limits>

namespace vri {

namespace {

// Macro cells along an axis of n points (n - 1 grid cells).
int macro_count(int n) { return (n - 2) / MacroCells::kCells + 1; }

// The window of macro cell `i` along an axis of n points: points
// [first, last], kCells + 1 of them (fewer at the far face); neighbours share one.
int first(int i) { return i * MacroCells::kCells; }
int last(int i, int n) { return std::min(n - 1, first(i) + MacroCells::kCells); }

// The min and max over each macro cell's window in x and y of z-plane `z`:
// lo/hi of mx * my entries; row_lo/row_hi (mx * ny) are scratch.
template <class T>
void reduce_plane(const T* plane, std::array<int, 3> dims, std::array<int, 3> m, std::vector<T>& row_lo,
                  std::vector<T>& row_hi, std::vector<T>& lo, std::vector<T>& hi) {
  const int nx = dims[0], ny = dims[1];
  for (int y = 0; y < ny; ++y) {
    const T* row = plane + static_cast<std::size_t>(y) * nx;
    for (int i = 0; i < m[0]; ++i) {
      const auto [l, h] = std::minmax_element(row + first(i), row + last(i, nx) + 1);
      row_lo[static_cast<std::size_t>(y) * m[0] + i] = *l;
      row_hi[static_cast<std::size_t>(y) * m[0] + i] = *h;
    }
  }
  for (int j = 0; j < m[1]; ++j)
    for (int i = 0; i < m[0]; ++i) {
      T l = row_lo[static_cast<std::size_t>(first(j)) * m[0] + i], h = row_hi[static_cast<std::size_t>(first(j)) * m[0] + i];
      for (int y = first(j) + 1; y <= last(j, ny); ++y) {
        l = std::min(l, row_lo[static_cast<std::size_t>(y) * m[0] + i]);
        h = std::max(h, row_hi[static_cast<std::size_t>(y) * m[0] + i]);
      }
      lo[static_cast<std::size_t>(j) * m[0] + i] = l;
      hi[static_cast<std::size_t>(j) * m[0] + i] = h;
    }
}

}  // namespace

MacroRanges compute_macro_ranges(const GridVolume& volume) {
  MacroRanges r{{macro_count(volume.dims()[0]), macro_count(volume.dims()[1]), macro_count(volume.dims()[2])}, {}, {}};
  const std::array<int, 3>& m = r.dims;
  // One z-plane at a time (the scratch is a few rows, not a copy of the
  // volume): reduce it in x and y, then fold it into the one or two layers of
  // macro cells whose z window holds it.
  const std::size_t layer = static_cast<std::size_t>(m[0]) * m[1];
  r.lo.assign(layer * m[2], std::numeric_limits<float>::infinity());
  r.hi.assign(r.lo.size(), -std::numeric_limits<float>::infinity());
  volume.visit([&](auto values) {
    using T = typename decltype(values)::value_type;
    const auto& n = volume.dims();
    const std::size_t plane = static_cast<std::size_t>(n[0]) * n[1];
    std::vector<T> row_lo(static_cast<std::size_t>(m[0]) * n[1]), row_hi(row_lo.size()), lo(layer), hi(layer);
    for (int z = 0; z < n[2]; ++z) {
      reduce_plane(values.data() + plane * z, n, m, row_lo, row_hi, lo, hi);
      for (int k = std::max(0, (z - 1) / MacroCells::kCells); k <= std::min(m[2] - 1, z / MacroCells::kCells); ++k) {
        for (std::size_t c = 0; c < layer; ++c) {
          r.lo[layer * k + c] = std::min(r.lo[layer * k + c], static_cast<float>(lo[c]));
          r.hi[layer * k + c] = std::max(r.hi[layer * k + c], static_cast<float>(hi[c]));
        }
      }
    }
  });
  return r;
}

}  // namespace vri
