// `fast` against `plain` (second_order_fast.hpp) and both across thread counts.
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "tables/random_tf.hpp"
#include "vri/tables/second_order_table.hpp"

namespace vri {
namespace {

// The bound docs/SECOND_ORDER.md states for |fast - plain|: float32 and a
// polynomial exp against double, a few float roundings per sub-step.
double fast_tolerance(int iterations) { return 1e-6 + 3e-8 * iterations; }

double max_difference(const SecondOrderTable& a, const SecondOrderTable& b) {
  double m = 0;
  for (std::size_t k = 0; k < a.bytes() / sizeof(float); ++k)
    m = std::max(m, double(std::abs(a.data()[k] - b.data()[k])));
  return m;
}

struct Case {
  unsigned seed;
  int n;
  double length, max_tau;
  int iterations;
};

TEST(FastSecondOrderBuilder, EqualsPlainInEveryEntry) {
  const auto plain = make_second_order_builder("plain"), fast = make_second_order_builder("fast");
  for (const Case c : {Case{1, 24, 1.0, 0.5, 64}, Case{2, 31, 0.5, 4.0, 7}, Case{3, 17, 3.0, 20.0, 64},
                       Case{4, 9, 1.0, 300.0, 33}, Case{5, 2, 1.0, 1.0, 1}, Case{6, 20, 2.0, 1.0, 200}}) {
    const DiscreteTf tf(test::random_spiky_tf(c.seed, c.max_tau), c.n);
    EXPECT_LE(max_difference(plain->build(tf, c.length, c.iterations), fast->build(tf, c.length, c.iterations)),
              fast_tolerance(c.iterations))
        << "seed " << c.seed;
  }
}

TEST(SecondOrderBuilders, SameBytesForAnyThreadCount) {
  const DiscreteTf tf(test::random_spiky_tf(8, 5.0), 26);
  for (const char* name : {"plain", "fast"}) {
    const auto builder = make_second_order_builder(name);
    auto build = [&](int threads) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      return builder->build(tf, 1.3, 16);
    };
    const SecondOrderTable one = build(1), two = build(2), four = build(4);
    EXPECT_EQ(std::memcmp(one.data(), two.data(), one.bytes()), 0) << name;
    EXPECT_EQ(std::memcmp(one.data(), four.data(), one.bytes()), 0) << name;
  }
}

}  // namespace
}  // namespace vri
