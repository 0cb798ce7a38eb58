#include "vri/tables/second_order_plain.hpp"

#include <tbb/parallel_for.h>

#include "vri/tables/table_builder.hpp"

namespace vri {

namespace {

void store(float* e, const SlabRgba& v) {
  e[0] = static_cast<float>(v.r);
  e[1] = static_cast<float>(v.g);
  e[2] = static_cast<float>(v.b);
  e[3] = static_cast<float>(v.a);
}

}  // namespace

SecondOrderTable PlainSecondOrderBuilder::build(const DiscreteTf& tf, double length, int iterations) const {
  check_slab_length(length);
  check_iterations(iterations);
  SecondOrderTable table(tf.axis(), length, iterations);
  const int n = tf.size();
  tbb::parallel_for(0, n, [&](int f) {
    for (int m = 0; m < n; ++m)
      for (int b = 0; b < n; ++b) store(table.entry(f, m, b), second_order_entry(tf, f, m, b, length, iterations));
  });
  return table;
}

SecondOrderWeightedTables PlainSecondOrderBuilder::build_weighted(const DiscreteTf& tf, double length,
                                                                  int iterations) const {
  check_slab_length(length);
  check_iterations(iterations);
  SecondOrderWeightedTables t{SecondOrderTable(tf.axis(), length, iterations),
                              SecondOrderTable(tf.axis(), length, iterations),
                              SecondOrderTable(tf.axis(), length, iterations)};
  const int n = tf.size();
  tbb::parallel_for(0, n, [&](int f) {
    for (int m = 0; m < n; ++m)
      for (int b = 0; b < n; ++b) {
        const SecondOrderWeights w = second_order_weighted_entry(tf, f, m, b, length, iterations);
        store(t.full.entry(f, m, b), w.full);
        store(t.middle.entry(f, m, b), w.middle);
        store(t.back.entry(f, m, b), w.back);
      }
  });
  return t;
}

}  // namespace vri
