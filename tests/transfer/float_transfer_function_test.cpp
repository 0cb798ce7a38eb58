// FloatTransferFunction (riemann's float path) against TransferFunction: the
// same segment for every float scalar, values within float rounding, zero
// opacity exactly where the function is zero, steps and end values as SPEC §3.
#include "transfer/float_transfer_function.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace vri {
namespace {

TEST(FloatTransferFunction, FindsTheSegmentOfEveryScalar) {
  std::mt19937 rng(3);
  // Uneven breakpoints: clusters narrower than a bin, a step, wide gaps.
  const TransferFunction tf({{-50, 0, 0, 0, 0},
                             {0, 0.1, 0.2, 0.3, 0},
                             {0.01, 0.5, 0.5, 0.5, 4},
                             {0.02, 0.2, 0.9, 0.1, 0},
                             {30, 0.3, 0.3, 0.3, 1},
                             {30, 0.9, 0.1, 0.4, 7},
                             {900, 1, 1, 1, 2}});
  const FloatTransferFunction ftf(tf);
  std::uniform_real_distribution<float> any(-100, 1000), near(-0.05f, 0.05f);
  int checked = 0;
  for (int i = 0; i < 200000; ++i) {
    const float s = i % 2 ? any(rng) : near(rng) + (i % 4 == 0 ? 0.0f : 30.0f);
    ASSERT_EQ(ftf.segment(s), tf.segment_index(s)) << s;
    const TfSample want = tf(s);
    const auto got = ftf(s);
    const double scale = 1 + std::abs(s) * 1e-2;  // slopes up to 400 per unit near 0.01
    EXPECT_NEAR(got.r, want.r, 2e-6 * scale) << s;
    EXPECT_NEAR(got.tau, want.tau, 2e-5 * scale) << s;
    ++checked;
  }
  EXPECT_EQ(checked, 200000);
  // At a step the later point holds; outside, the end values.
  EXPECT_FLOAT_EQ(ftf(30.0f).tau, 7);
  EXPECT_FLOAT_EQ(ftf(29.999f).tau, tf(29.999f).tau);
  EXPECT_FLOAT_EQ(ftf(-1e6f).r, 0);
  EXPECT_FLOAT_EQ(ftf(1e6f).tau, 2);
  // Zero opacity is exactly zero over a zero run, ends included.
  for (float s : {-50.0f, -20.0f, -1e-3f, 0.0f, 0.02f}) EXPECT_EQ(ftf(s).tau, 0.0f) << s;
}

TEST(FloatTransferFunction, OnePointIsConstant) {
  const FloatTransferFunction ftf(TransferFunction({{5, 0.25, 0.5, 0.75, 3}}));
  for (float s : {-1e9f, 4.0f, 5.0f, 6.0f, 1e9f}) {
    EXPECT_FLOAT_EQ(ftf(s).g, 0.5f);
    EXPECT_FLOAT_EQ(ftf(s).tau, 3);
  }
}

}  // namespace
}  // namespace vri
