#pragma once
// ZeroSpots: which spots of a second-order table's (s_f, s_m, s_b) grid read
// only zero entries, so that a lookup there can skip its loads. A trilinear
// blend at spot (f, m, b) reads the eight entries (f..f+1, m..m+1, b..b+1);
// when all of them are zero in every table given (every length slice of
// preint2-dual's (l, s_f, s_m, s_b) table and, lit, its weighted tables), the
// blend is +0 in every channel whatever its weights, which is what a skipped
// lookup returns: the same bytes, without the lines of a table that lives in
// memory. Inside the non-empty macro cells that empty-space skipping keeps,
// many segments still fall on such spots (a sample pair in the transparent
// range beside the data); their entries are the table's zeros, read for
// nothing. Found from the tables' own floats, so it holds for any builder.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace vri {

class ZeroSpots {
 public:
  // `tables`: each n^3 entries of 4 floats in (f, m, b) order, b fastest.
  ZeroSpots(int n, const std::vector<const float*>& tables);
  // Whether the blend at entry (f, m, b), index (f n + m) n + b, reads only zeros.
  bool zero(std::size_t entry) const { return (bits_[entry / 64] >> (entry % 64)) & 1; }

 private:
  std::vector<std::uint64_t> bits_;
};

}  // namespace vri
