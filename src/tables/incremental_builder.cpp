#include "vri/tables/incremental_builder.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

#include "incremental_diagonals.hpp"
#include "vri/tables/slab_integral.hpp"

namespace vri {

namespace {

struct Scratch {
  DiagonalSweep sweep;
  GroupBuffer buffer;
  explicit Scratch(int n) : sweep(n), buffer(n) {}
};

void build_group(const DiscreteTf& tf, const Pieces& pieces, double length, int m0, Scratch& s,
                 PreintegrationTable& table) {
  const int n = tf.size(), m1 = std::min(m0 + kGroup, n);
  for (int m = m0; m < m1; ++m) {
    s.sweep.weights(pieces, length, m);
    s.sweep.composite(&tf[0], m, s.buffer.upper_of(n, m - m0), s.buffer.lower_of(n, m - m0));
  }
  s.buffer.store(m0, m1, table);
}

}  // namespace

PreintegrationTable IncrementalBuilder::build(const DiscreteTf& tf, double length) const {
  check_slab_length(length);
  PreintegrationTable table(tf.axis(), length);
  const int n = tf.size();
  for (int i = 0; i < n; ++i) std::copy_n(to_entry(homogeneous_slab(tf[i], length)).data(), 4, table.entry(i, i));
  const Pieces pieces(tf);
  // Scratch is reused by whichever thread runs a group and fully overwritten
  // before it is read, so the bytes do not depend on the thread count.
  tbb::enumerable_thread_specific<Scratch> scratch([n] { return Scratch(n); });
  const int groups = (n - 1 + kGroup - 1) / kGroup;
  tbb::parallel_for(0, groups, [&](int g) { build_group(tf, pieces, length, 1 + g * kGroup, scratch.local(), table); });
  return table;
}

}  // namespace vri
