#include "test_support.hpp"
#include "vri/render.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "vri/error.hpp"

namespace vri {
namespace {

TEST(CompareImages, SharesRmsAndMaxPerChannel) {
  // two pixels, two channels: differences (0.1, 0) and (0.3, 0.02)
  const std::vector<float> a{0.1f, 0.f, 0.5f, 0.52f}, b{0.f, 0.f, 0.2f, 0.5f};
  const auto d = compare_images(a, b, 2, 0.05);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_DOUBLE_EQ(d[0].share_over, 1.0);
  EXPECT_NEAR(d[0].rms, std::sqrt((0.01 + 0.09) / 2), 1e-7);
  EXPECT_NEAR(d[0].max, 0.3, 1e-7);
  EXPECT_DOUBLE_EQ(d[1].share_over, 0.0);
  EXPECT_NEAR(d[1].max, 0.02, 1e-7);
}

TEST(CompareImages, NanCountsAsOverAndSizesMustMatch) {
  const std::vector<float> nan_zero{NAN, 0.f}, zeros{0.f, 0.f}, one_zero{0.f};
  const auto d = compare_images(nan_zero, zeros, 1, 0.1);
  EXPECT_DOUBLE_EQ(d[0].share_over, 0.5);
  EXPECT_THROW(compare_images(one_zero, zeros, 1, 0.1), Error);
}

// Issue 46, class 7: a NaN before a finite difference left a finite maximum.
TEST(CompareImages, ANanAnywhereStaysInTheMaximumAndIsCounted) {
  const std::vector<float> a{NAN, 0.f, 0.5f, 0.f, 0.f, NAN}, b{0.f, 0.f, 0.f, 0.f, 0.f, 0.f};
  const auto d = compare_images(a, b, 2, 0.1);
  EXPECT_TRUE(std::isnan(d[0].max));
  EXPECT_EQ(d[0].nan, 1u);
  EXPECT_TRUE(std::isnan(d[1].max));
  EXPECT_EQ(d[1].nan, 1u);
  const auto clean = compare_images(b, b, 2, 0.1);
  EXPECT_EQ(clean[0].nan, 0u);
  EXPECT_EQ(clean[0].max, 0);
}

}  // namespace
}  // namespace vri
