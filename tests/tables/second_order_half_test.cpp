// HalfSecondOrderTable (half_second_order_table.hpp) against the float32 table.
#include <gtest/gtest.h>

#include <cmath>

#include "tables/random_tf.hpp"
#include "tables/half_second_order_table.hpp"

namespace vri {
namespace {

TEST(HalfSecondOrderTable, EveryEntryIsTheNearestHalf) {
  const DiscreteTf tf(test::random_spiky_tf(4, 6.0), 20);
  const SecondOrderTable full = make_second_order_builder("fast")->build(tf, 1.0, 32);
  const HalfSecondOrderTable half(full);
  EXPECT_EQ(half.bytes() * 2, full.bytes());
  for (int f = 0; f < 20; ++f)
    for (int m = 0; m < 20; ++m)
      for (int b = 0; b < 20; ++b) {
        const Rgba h = half.entry(f, m, b);
        for (int c = 0; c < 4; ++c) {
          const double x = full.entry(f, m, b)[c];
          ASSERT_LE(std::abs(h[c] - x), std::ldexp(std::abs(x), -11) + std::ldexp(1.0, -25)) << x;
        }
      }
  const ScalarAxis& ax = tf.axis();
  const Rgba a = half.lookup(ax.scalar(3) + 0.4, ax.scalar(11) + 0.3, ax.scalar(7) + 0.9),
             b = full.lookup(ax.scalar(3) + 0.4, ax.scalar(11) + 0.3, ax.scalar(7) + 0.9);
  for (int c = 0; c < 4; ++c) EXPECT_NEAR(a[c], b[c], 2.5e-4);
}

}  // namespace
}  // namespace vri
