#include "tables/zero_spots.hpp"

#include <tbb/parallel_for.h>

namespace vri {

ZeroSpots::ZeroSpots(int n, const std::vector<const float*>& tables) {
  const std::size_t s = static_cast<std::size_t>(n), entries = s * s * s;
  // Entry by entry: zero in every table (any non-zero float, -0 aside, clears it).
  std::vector<std::uint8_t> zero(entries, 1);
  tbb::parallel_for(std::size_t{0}, s, [&](std::size_t f) {
    for (const float* table : tables)
      for (std::size_t e = f * s * s; e < (f + 1) * s * s; ++e) {
        const float* v = table + 4 * e;
        if (v[0] != 0 || v[1] != 0 || v[2] != 0 || v[3] != 0) zero[e] = 0;
      }
  });
  // Spot by spot: its eight entries. Spots on the upper faces (an index n - 1)
  // are never looked up (FloatAxis::place stops at n - 2) and stay non-zero.
  bits_.assign((entries + 63) / 64, 0);
  const auto at = [&](std::size_t f, std::size_t m, std::size_t b) { return (f * s + m) * s + b; };
  for (std::size_t f = 0; f + 1 < s; ++f)
    for (std::size_t m = 0; m + 1 < s; ++m)
      for (std::size_t b = 0; b + 1 < s; ++b) {
        bool all = true;
        for (int c = 0; c < 8 && all; ++c) all = zero[at(f + (c & 1), m + (c >> 1 & 1), b + (c >> 2))];
        if (all) bits_[at(f, m, b) / 64] |= std::uint64_t{1} << (at(f, m, b) % 64);
      }
}

}  // namespace vri
