#include "vri/tables/second_order_weighted.hpp"

#include <utility>
#include <vector>

#include "tables/second_order_substeps.hpp"

namespace vri {

SecondOrderWeights second_order_weighted_entry(const DiscreteTf& tf, double u_f, double u_m, double u_b,
                                               double length, int iterations) {
  SecondOrderWeights out;
  double T = 1;
  detail::for_each_second_order_substep(tf, u_f, u_m, u_b, length, iterations, [&](double t, const SlabRgba& v) {
    const auto add = [&](SlabRgba& to, double w) {
      to.r += w * T * v.r, to.g += w * T * v.g, to.b += w * T * v.b, to.a += w * T * v.a;
    };
    add(out.front, lagrange_front(t));
    add(out.middle, lagrange_middle(t));
    add(out.back, lagrange_back(t));
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
