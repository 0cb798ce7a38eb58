#include "volume/transparent_cells.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>

#include "vri/memory.hpp"

namespace vri {

TransparentCells::TransparentCells(const GridVolume& volume, const EmptySpace& space, const ZeroOpacityBins& zero,
                                   double margin) {
  const auto& n = volume.dims();
  row_ = static_cast<std::size_t>(n[0]);
  plane_bits_ = (row_ * n[1] + 63) / 64 * 64;
  const std::size_t words = plane_bits_ / 64 * n[2];
  check_allocation(words, sizeof(std::uint64_t), "the transparent-cell bits");
  bits_.assign(words, 0);
  const MacroCells& macro = space.cells();
  const auto& m = macro.dims();
  constexpr int K = MacroCells::kCells;
  // One layer of macro cells (K planes of cells) a task: no two share a word.
  tbb::parallel_for(0, m[2], [&](int mk) {
    volume.visit([&](auto values) {
      using T = typename decltype(values)::value_type;
      const std::size_t sy = n[0], sz = sy * n[1];
      // Along a row of cells: the least and greatest of the four samples
      // above each x (rows j, j + 1 of planes k, k + 1), so a cell's range is
      // that of two neighbours (in T: min and max commute with the exact or
      // monotone conversion to float the cell test makes).
      std::vector<T> lo(n[0]), hi(n[0]);
      std::vector<int> occupied;  // the non-empty macro cells of a row of them
      for (int mj = 0; mj < m[1]; ++mj) {
        occupied.clear();
        for (int mi = 0; mi < m[0]; ++mi)
          if (!space.empty(macro.index(mi, mj, mk))) occupied.push_back(mi);
        if (occupied.empty()) continue;
        for (int k = mk * K; k < std::min((mk + 1) * K, n[2] - 1); ++k)
          for (int j = mj * K; j < std::min((mj + 1) * K, n[1] - 1); ++j) {
            const T* __restrict r0 = values.data() + volume.index(0, j, k);
            const T* __restrict r1 = r0 + sy;
            const T* __restrict r2 = r0 + sz;
            const T* __restrict r3 = r2 + sy;
            T* __restrict l = lo.data();
            T* __restrict h = hi.data();
            for (int i = 0; i < n[0]; ++i) {  // (restrict: vectorized)
              const T a = r0[i], b = r1[i], c = r2[i], d = r3[i];
              l[i] = std::min(std::min(a, b), std::min(c, d));
              h[i] = std::max(std::max(a, b), std::max(c, d));
            }
            const std::size_t row = bit(0, j, k);
            for (const int mi : occupied)
              for (int i = mi * K; i < std::min((mi + 1) * K, n[0] - 1); ++i) {
                const double a = static_cast<float>(std::min(lo[i], lo[i + 1]));
                const double b = static_cast<float>(std::max(hi[i], hi[i + 1]));
                // (Without a branch: in the cells at a surface it is a coin toss.)
                bits_[(row + i) >> 6] |= std::uint64_t{zero.over(a - margin, b + margin)} << ((row + i) & 63);
              }
          }
      }
    });
  });
}

std::size_t TransparentCells::count() const {
  std::size_t c = 0;
  for (const std::uint64_t w : bits_) c += static_cast<std::size_t>(std::popcount(w));
  return c;
}

}  // namespace vri
