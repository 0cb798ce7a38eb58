#include "tables/sliced_builder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tables/random_tf.hpp"
#include "vri/error.hpp"
#include "tables/brute_builder.hpp"

namespace vri {
namespace {

TEST(Quantize, RoundsToEachFormat) {
  EXPECT_DOUBLE_EQ(quantize(0.5, Accumulation::Fixed8), 128.0 / 255);
  EXPECT_DOUBLE_EQ(quantize(0.5, Accumulation::Fixed12), 2048.0 / 4095);
  EXPECT_DOUBLE_EQ(quantize(1.0 / 3, Accumulation::Half), 0.333251953125);  // 0x3555
  EXPECT_DOUBLE_EQ(quantize(1e-6, Accumulation::Half), 17 * std::ldexp(1.0, -24));  // subnormal
  EXPECT_DOUBLE_EQ(quantize(1.0 / 3, Accumulation::Single), double(1.0f / 3));
  EXPECT_THROW(parse_accumulation("10bit"), Error);
}

double max_error(const PreintegrationTable& a, const PreintegrationTable& b) {
  double m = 0;
  for (std::size_t k = 0; k < a.data().size(); ++k) m = std::max(m, double(std::abs(a.data()[k] - b.data()[k])));
  return m;
}

// In single precision the slice-parallel sum converges to the exact table as
// the steps grow (midpoint samples: the error falls about 4x per doubling),
// and coarse frame buffers spoil it.
TEST(SlicedBuilder, ConvergesToBruteAndQuantisationCosts) {
  const DiscreteTf tf(test::random_spiky_tf(21, 1.5), 48);
  const PreintegrationTable ref = BruteBuilder().build(tf, 1.0);
  const double e96 = max_error(ref, SlicedBuilder(96).build(tf, 1.0));
  const double e384 = max_error(ref, SlicedBuilder(384).build(tf, 1.0));
  EXPECT_LT(e384, e96 / 8);
  EXPECT_LT(e384, 1e-3);
  const double e8 = max_error(ref, SlicedBuilder(384, Accumulation::Fixed8).build(tf, 1.0));
  const double e12 = max_error(ref, SlicedBuilder(384, Accumulation::Fixed12).build(tf, 1.0));
  EXPECT_GT(e8, e12);
  EXPECT_GT(e12, e384);
  EXPECT_THROW(SlicedBuilder(-1), Error);
}

}  // namespace
}  // namespace vri
