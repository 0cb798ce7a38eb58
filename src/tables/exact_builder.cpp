#include "tables/exact_builder.hpp"

#include <tbb/parallel_for.h>

#include "tables/slab_integral.hpp"

namespace vri {

PreintegrationTable ExactBuilder::build(const DiscreteTf& tf, double length) const {
  check_slab_length(length);
  PreintegrationTable table(tf.axis(), length);
  const int n = tf.size();
  const auto piece = [](const TfSample& p, const TfSample& q, double d) { return linear_piece(p, q, d).forward; };
  tbb::parallel_for(0, n, [&](int f) {
    for (int b = 0; b < n; ++b) store(table.entry(f, b), integrate_slab(tf, f, b, length, piece));
  });
  return table;
}

}  // namespace vri
