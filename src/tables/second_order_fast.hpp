#pragma once
// FastSecondOrderBuilder: the entries of second_order_table.hpp (El Hajjar et
// al. 2008, Eq. 2 and §6.2) computed many at a time, each chord looked up in a
// first-order table instead of integrated on its own.
//
// The chords: all chords have the length L/K, so the first-order table of
// that length (IncrementalBuilder, O(N^2), which integrates the control points
// inside a bin) holds every chord between two table scalars; a chord between
// any two scalars is its bilinear lookup (as preint1 looks up its slabs).
//
// Why it is fast: with m = f + d1 and b = f + d2 the parabola is
// P(t) = q(t) + f with q(t) = (A t + B) t, A = 2 d2 - 4 d1, B = 4 d1 - d2,
// independent of f. So along a diagonal (d1, d2) every entry's chord ends
// sit at the same offsets q(t_j) shifted by the integer f: the bilinear
// weights are shared, and with the first-order table laid out by diagonal
// (entry (x, x + e) at [e][x]) the entries f .. f+7 read 8 consecutive floats
// per corner. Eight entries go through their K chords together in one SIMD
// primitive (8 float lanes, GCC generic vectors; on x86-64 with VRI_SIMD also
// an AVX2 clone picked where the CPU has it, src/core/simd.hpp), with no exp
// at all. Clamping to the axis is a padding of the layout with the end
// entries. Each lane walks its row (f, m, .) in order, so stores stream.
//
// What it approximates: the bilinear lookup of a chord between table scalars
// (the definition integrates it exactly); measured against `plain` in
// docs/SECOND_ORDER.md and bounded in tests (about 1/N on a smooth transfer
// function). Against its own lookups written out in double it is exact to
// float rounding (1e-6 + 3e-8 K). Bytes are the same for any thread count.
#include "tables/second_order_weighted.hpp"

namespace vri {

class FastSecondOrderBuilder final : public SecondOrderBuilder {
 public:
  std::string_view name() const override { return "fast"; }
  SecondOrderTable build(const DiscreteTf& tf, double length, int iterations) const override;
  SecondOrderWeightedTables build_weighted(const DiscreteTf& tf, double length, int iterations) const override;
};

}  // namespace vri
