#include "tables/incremental_builder.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

#include "incremental_diagonals.hpp"
#include "tables/slab_integral.hpp"

namespace vri {

PreintegrationTable IncrementalBuilder::build(const DiscreteTf& tf, double length) const {
  check_slab_length(length);
  PreintegrationTable table(tf.axis(), length);
  const int n = tf.size();
  for (int i = 0; i < n; ++i) std::copy_n(to_entry(homogeneous_slab(tf[i], length)).data(), 4, table.entry(i, i));
  const Pieces pieces(tf);
  // Scratch is reused by whichever thread runs a diagonal and fully
  // overwritten before it is read, so the bytes do not depend on the thread count.
  tbb::enumerable_thread_specific<DiagonalSweep> sweeps([n] { return DiagonalSweep(n); });
  tbb::parallel_for(1, n, [&](int m) {
    DiagonalSweep& sweep = sweeps.local();
    sweep.weights(pieces, length, m);
    sweep.composite(&tf[0], tf.all_sub_pieces().data(), m, table);
  });
  return table;
}

}  // namespace vri
