#pragma once
// FastSecondOrderBuilder: the entries of second_order_table.hpp (El Hajjar et
// al. 2008, Eq. 2 and §6.2) computed many at a time.
//
// Why it is fast: with m = f + d1 and b = f + d2 the parabola is
// P(t) = q(t) + f with q(t) = (A t + B) t, A = 2 d2 - 4 d1, B = 4 d1 - d2,
// independent of f. So along a diagonal (d1, d2) every entry samples the
// transfer function at the same sub-step offsets q(t_k), shifted by the
// integer f: the interpolation weights frac(q(t_k)) are shared, and the
// entries f, f+1, ..., f+7 read 8 consecutive table scalars. Eight entries go
// through the K sub-steps together in one SIMD primitive (8 float lanes, GCC
// generic vectors; on x86-64 with VRI_SIMD also an AVX2 clone picked where the
// CPU has it, src/core/simd.hpp), with exp evaluated by a
// polynomial. Clamping to the axis is a padding of the per-scalar arrays
// with their end values (a parabola through three values in [0, N-1] stays
// within [-(N-1)/8, 9(N-1)/8]).
//
// It works in float32 with a polynomial exp (relative error ~1e-7) where
// `plain` works in double: |fast - plain| <= 1e-6 + 3e-8 K per channel
// (measured in docs/SECOND_ORDER.md). Bytes are the same for any thread count.
#include "vri/tables/second_order_weighted.hpp"

namespace vri {

class FastSecondOrderBuilder final : public SecondOrderBuilder {
 public:
  std::string_view name() const override { return "fast"; }
  SecondOrderTable build(const DiscreteTf& tf, double length, int iterations) const override;
  SecondOrderWeightedTables build_weighted(const DiscreteTf& tf, double length, int iterations) const override;
};

}  // namespace vri
