#include "tables/second_order_plain.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "vri/error.hpp"

#include "tables/table_builder.hpp"

namespace vri {

SecondOrderTable PlainSecondOrderBuilder::build(const DiscreteTf& tf, double length, int iterations) const {
  check_slab_length(length);
  check_iterations(iterations);
  SecondOrderTable table(tf.axis(), length, iterations);
  const int n = tf.size();
  tbb::parallel_for(0, n, [&](int f) {
    for (int m = 0; m < n && !tbb::is_current_task_group_canceling(); ++m)  // a cancelled build stops
      for (int b = 0; b < n; ++b) store(table.entry(f, m, b), second_order_entry(tf, f, m, b, length, iterations));
  });
  throw_if_build_cancelled();
  return table;
}

SecondOrderWeightedTables PlainSecondOrderBuilder::build_weighted(const DiscreteTf& tf, double length,
                                                                  int iterations) const {
  check_slab_length(length);
  check_iterations(iterations);
  SecondOrderWeightedTables t(tf.axis(), length, iterations);
  const int n = tf.size();
  tbb::parallel_for(0, n, [&](int f) {
    for (int m = 0; m < n && !tbb::is_current_task_group_canceling(); ++m)  // a cancelled build stops
      for (int b = 0; b < n; ++b) {
        const SecondOrderWeights w = second_order_weighted_entry(tf, f, m, b, length, iterations);
        store(t.full.entry(f, m, b), w.full);
        store(t.middle.entry(f, m, b), w.middle);
        store(t.back.entry(f, m, b), w.back);
      }
  });
  throw_if_build_cancelled();
  return t;
}

}  // namespace vri
