#pragma once
// SlicedBuilder: the slice-parallel pre-integration of Roettger & Ertl 2002,
// §3 ("hardware-accelerated pre-integration"), on the CPU. All (s_f, s_b) of
// one table are integrated together in n steps of length l/n: step k samples
// every entry at s = s_f + (s_b - s_f)(k + 1/2)/n (the texture coordinate
// interpolated across the rectangle of their Fig. 3) and blends, back to
// front, the Stein et al. 1994 slab of constant chromaticity (their eq. 8):
//   alpha = 1 - exp(-tau(s) l/n),  C <- c(s) alpha + (1 - alpha) C,  T <- (1 - alpha) T,
// with c and tau read from the DiscreteTf, each linear in s. (A texture of
// premultiplied c alpha interpolated linearly, as in their hardware, would
// make c tau linear instead of quadratic between table scalars: a bias that
// no number of steps removes, 0.06 on tests' spiky TFs; docs/PREINTEGRATION.md.)
// The graphics pipeline's two inner loops become one row of entries (a loop
// the compiler vectorises) with the n steps outside it, rows spread over
// threads. The frame buffer's precision is simulated: after every blend the
// accumulated values (and the fetched colour and alpha) are rounded to 8-bit or 12-bit
// fixed point, IEEE half or single precision. n defaults to o * N with the
// paper's oversampling o = 2. Its error against `brute` is tabulated in
// docs/PREINTEGRATION.md.
#include "tables/table_builder.hpp"

namespace vri {

enum class Accumulation { Fixed8, Fixed12, Half, Single };
// "8bit", "12bit", "fp16", "fp32"; throws vri::Error otherwise.
Accumulation parse_accumulation(const std::string& name);
// x rounded to the nearest value the format holds (x in [0, 1]).
double quantize(double x, Accumulation format);

class SlicedBuilder final : public TableBuilder {
 public:
  // steps = 0: 2 N steps. Throws vri::Error unless 0 <= steps <= 1 << 20.
  explicit SlicedBuilder(int steps = 0, Accumulation accumulation = Accumulation::Single);
  std::string_view name() const override { return "sliced"; }
  // n^2 entries, each stepped through its slices (steps, or 2n).
  double work(int n) const override { return double(steps_ > 0 ? steps_ : 2 * n) * n * n; }
  PreintegrationTable build(const DiscreteTf& tf, double length) const override;

 private:
  int steps_;
  Accumulation accumulation_;
};

}  // namespace vri
