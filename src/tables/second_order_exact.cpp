#include "tables/second_order_exact.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_group.h>

#include "vri/error.hpp"

#include <algorithm>
#include <cmath>

#include "tables/table_builder.hpp"

namespace vri {

namespace {

double difference(const SlabRgba& a, const SlabRgba& b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
}

double difference(const SecondOrderWeights& a, const SecondOrderWeights& b) {
  return std::max({difference(a.full, b.full), difference(a.middle, b.middle), difference(a.back, b.back)});
}

// entry(K) for K = 64, 128, ... until two successive values differ by at
// most the tolerance (or K reaches the cap).
template <class Entry>
auto converged(Entry entry) {
  int k = 64;
  auto e = entry(k);
  while (k < kMaxSecondOrderIterations) {
    k *= 2;
    const auto next = entry(k);
    const double change = difference(next, e);
    e = next;
    if (change <= ExactSecondOrderBuilder::kTolerance) break;
  }
  return e;
}

void check_size(int n) {
  if (n > ExactSecondOrderBuilder::kMaxSize)
    throw Error("the exact second-order builder integrates every entry to 1e-7 and takes tables up to " +
                std::to_string(ExactSecondOrderBuilder::kMaxSize) + " a side, got " + std::to_string(n) +
                "; use plain or fast");
}

}  // namespace

SecondOrderWeights exact_second_order_entry(const DiscreteTf& tf, double u_f, double u_m, double u_b,
                                            double length) {
  return converged([&](int k) { return second_order_weighted_entry(tf, u_f, u_m, u_b, length, k); });
}

// The unweighted table alone: the same doubling on the unweighted entry, no
// weighted integrals computed for nothing.
SecondOrderTable ExactSecondOrderBuilder::build(const DiscreteTf& tf, double length, int) const {
  check_slab_length(length);
  const int n = tf.size();
  check_size(n);
  SecondOrderTable t(tf.axis(), length, kMaxSecondOrderIterations);
  tbb::parallel_for(0, n, [&](int f) {
    for (int m = 0; m < n && !tbb::is_current_task_group_canceling(); ++m)  // a cancelled build stops
      for (int b = 0; b < n; ++b)
        store(t.entry(f, m, b), converged([&](int k) { return second_order_entry(tf, f, m, b, length, k); }));
  });
  throw_if_build_cancelled();
  return t;
}

SecondOrderWeightedTables ExactSecondOrderBuilder::build_weighted(const DiscreteTf& tf, double length, int) const {
  check_slab_length(length);
  const int n = tf.size();
  check_size(n);
  SecondOrderWeightedTables t(tf.axis(), length, kMaxSecondOrderIterations);
  tbb::parallel_for(0, n, [&](int f) {
    for (int m = 0; m < n && !tbb::is_current_task_group_canceling(); ++m)  // a cancelled build stops
      for (int b = 0; b < n; ++b) {
        const SecondOrderWeights w = exact_second_order_entry(tf, f, m, b, length);
        store(t.full.entry(f, m, b), w.full);
        store(t.middle.entry(f, m, b), w.middle);
        store(t.back.entry(f, m, b), w.back);
      }
  });
  throw_if_build_cancelled();
  return t;
}

}  // namespace vri
