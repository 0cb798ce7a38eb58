#include "tables/second_order_weighted.hpp"

#include <utility>
#include <vector>

#include "tables/second_order_chords.hpp"
#include "tables/weighted_tables.hpp"

namespace vri {

SecondOrderWeights second_order_weighted_entry(const DiscreteTf& tf, double u_f, double u_m, double u_b,
                                               double length, int iterations) {
  SecondOrderWeights out;
  double T = 1;
  const auto forward = [](const TfSample& p, const TfSample& q, double d) { return linear_piece(p, q, d).forward; };
  detail::for_each_second_order_chord(
      tf, u_f, u_m, u_b, length, iterations, [&](double t0, double t1, double u0, double u1, double step) {
        // The chord's integrals weighted by its own front and back weight
        // (rgb = D, a = S); a Lagrange weight, linear across the chord,
        // is L(t0) at its front and L(t1) at its back.
        const SlabWeights w = weighted_slab(tf, u0, u1, step, forward);
        const auto add = [&](SlabRgba& to, double (*L)(double)) {
          const double a = T * L(t0), b = T * L(t1);
          to.r += a * w.front.r + b * w.back.r, to.g += a * w.front.g + b * w.back.g;
          to.b += a * w.front.b + b * w.back.b, to.a += a * w.front.a + b * w.back.a;
        };
        add(out.front, lagrange_front);
        add(out.middle, lagrange_middle);
        add(out.back, lagrange_back);
        const SlabRgba v = exact_index_slab(tf, u0, u1, step);
        out.full = over(out.full, v);
        T *= 1 - v.a;
      });
  return out;
}

SecondOrderWeightedLengthTables build_second_order_weighted_length_tables(const SecondOrderBuilder& builder,
                                                                          const DiscreteTf& tf, int lengths,
                                                                          double max_length, int iterations) {
  check_length_table(lengths, max_length, tf.size(), 3);
  check_iterations(iterations);
  std::vector<SecondOrderTable> full, middle, back;
  // Length 0 is the empty slab (all weighted integrals 0).
  for (auto* slices : {&full, &middle, &back}) slices->emplace_back(tf.axis(), 0.0, iterations);
  for (int m = 1; m < lengths; ++m) {
    SecondOrderWeightedTables t = builder.build_weighted(tf, max_length * m / (lengths - 1), iterations);
    full.push_back(std::move(t.full));
    middle.push_back(std::move(t.middle));
    back.push_back(std::move(t.back));
  }
  return {SecondOrderLengthTable(std::move(full), max_length), SecondOrderLengthTable(std::move(middle), max_length),
          SecondOrderLengthTable(std::move(back), max_length)};
}

}  // namespace vri
