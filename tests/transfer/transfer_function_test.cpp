#include "vri/transfer_function.hpp"

#include <gtest/gtest.h>

#include <string>

#include <cmath>

#include "vri/error.hpp"

namespace vri {
namespace {

TEST(TransferFunction, LinearBetweenPointsAndHeldOutside) {
  const TransferFunction tf({{10, 0, 0.5, 1, 2}, {20, 1, 0.5, 0, 4}});
  const auto mid = tf(12.5);
  EXPECT_DOUBLE_EQ(mid.r, 0.25);
  EXPECT_DOUBLE_EQ(mid.g, 0.5);
  EXPECT_DOUBLE_EQ(mid.b, 0.75);
  EXPECT_DOUBLE_EQ(mid.tau, 2.5);
  EXPECT_DOUBLE_EQ(tf(-100).tau, 2);
  EXPECT_DOUBLE_EQ(tf(10).tau, 2);
  EXPECT_DOUBLE_EQ(tf(20).tau, 4);
  EXPECT_DOUBLE_EQ(tf(1e9).tau, 4);
  EXPECT_DOUBLE_EQ(tf.s_lo(), 10);
  EXPECT_DOUBLE_EQ(tf.s_hi(), 20);
}

TEST(TransferFunction, AtAStepTheLaterPointHolds) {
  const TransferFunction tf({{0, 0, 0, 0, 0}, {5, 0, 0, 0, 1}, {5, 1, 1, 1, 3}, {10, 1, 1, 1, 3}});
  EXPECT_DOUBLE_EQ(tf(5).tau, 3);
  EXPECT_DOUBLE_EQ(tf(5).r, 1);
  EXPECT_NEAR(tf(std::nextafter(5.0, 0.0)).tau, 1, 1e-12);
  EXPECT_DOUBLE_EQ(tf(2.5).tau, 0.5);
  EXPECT_EQ(tf.breakpoints(), (std::vector<double>{0, 5, 10}));
  EXPECT_EQ(tf.segments().size(), 4u);  // below 0, [0,5), [5,10), above 10
}

TEST(TransferFunction, SegmentsAgreeWithEvaluation) {
  const TransferFunction tf({{0, 0, 0, 0, 0}, {3, 0.2, 0.4, 0.6, 0.5}, {3, 0.3, 0.1, 0.9, 2}, {8, 1, 1, 1, 0}});
  for (double s = -2; s <= 10; s += 0.37) {
    const auto& seg = tf.segments()[tf.segment_index(s)];
    EXPECT_GE(s, seg.s_lo);
    EXPECT_LT(s, seg.s_hi);
    EXPECT_NEAR(seg.at(s).tau, tf(s).tau, 1e-15);
    EXPECT_NEAR(seg.at(s).g, tf(s).g, 1e-15);
  }
  EXPECT_TRUE(tf.segments().front().transparent());
  EXPECT_FALSE(tf.segments()[1].transparent());
}

TEST(TransferFunction, OpacityFormConvertsPerPointBeforeInterpolation) {
  const auto tf = TransferFunction::from_opacity({{0, 1, 0, 0, 0.5}, {10, 0, 1, 0, 0.75}}, 2.0);
  EXPECT_NEAR(tf(0).tau, std::log(2.0) / 2, 1e-15);
  EXPECT_NEAR(tf(10).tau, std::log(4.0) / 2, 1e-15);
  EXPECT_NEAR(tf(5).tau, (std::log(2.0) + std::log(4.0)) / 4, 1e-15);  // linear in tau, not in a
}

TEST(TransferFunction, RejectsBadPoints) {
  EXPECT_THROW(TransferFunction({}), Error);
  EXPECT_THROW(TransferFunction({{5, 0, 0, 0, 1}, {4, 0, 0, 0, 1}}), Error);       // unsorted
  EXPECT_THROW(TransferFunction({{0, 0, 0, 0, -0.1}}), Error);                    // negative tau
  EXPECT_THROW(TransferFunction({{0, 1.5, 0, 0, 1}}), Error);                     // colour > 1
  EXPECT_THROW(TransferFunction({{NAN, 0, 0, 0, 1}}), Error);
  EXPECT_THROW(TransferFunction({{0, 0, 0, 0, INFINITY}}), Error);
  EXPECT_THROW(TransferFunction::from_opacity({{0, 0, 0, 0, 1.0}}, 1), Error);    // a = 1
  EXPECT_THROW(TransferFunction::from_opacity({{0, 0, 0, 0, -0.5}}, 1), Error);
  EXPECT_THROW(TransferFunction::from_opacity({{0, 0, 0, 0, 0.5}}, 0), Error);    // unit distance
}

// Issue 47, defect 12: numbers in messages as %g, not "0.000000" or 300 digits.
TEST(TransferFunction, MessagesShowTheNumbersGiven) {
  auto message = [](auto&& make) {
    try {
      make();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([] { TransferFunction({{2e-7, 0, 0, 0, 1}, {1e-7, 0, 0, 0, 1}}); })
                .find("s = 1e-07 is below the previous point's 2e-07"),
            std::string::npos);
  EXPECT_NE(message([] { TransferFunction({{0, 0, 0, 0, -1e300}}); }).find("got -1e+300"), std::string::npos);
  EXPECT_NE(message([] { TransferFunction::from_opacity({{0, 0, 0, 0, 1.5}}, 1); }).find("got 1.5"), std::string::npos);
}

}  // namespace
}  // namespace vri
