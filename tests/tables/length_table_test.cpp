#include "tables/length_table_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "vri/error.hpp"
#include "methods/exact/piece_integrator.hpp"

namespace vri {
namespace {

TEST(LengthTable, NodesHoldTheExactSegmentIntegral) {
  const TransferFunction tf({{0, 1, 0, 0, 0}, {1, 0, 1, 0, 2}, {2, 0, 0, 1, 0.5}});
  const LengthTable table = test::length_table(tf, 9, 5, 2.0);
  const PieceIntegrator exact(tf);
  // Node (m, i, j) = (3, 2, 7): l = 1.5, s_f = 0.5, s_b = 1.75.
  PieceIntegrator::Accumulator acc;
  exact.integrate_linear(0.5, 1.75, 1.5, 1e-12, acc);
  const Rgba v = table.lookup(1.5, 0.5, 1.75);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(v[c], acc.C[c], 2e-7);
  EXPECT_NEAR(v[3], 1 - acc.T, 2e-7);
  EXPECT_GT(v[3], 0.5);
  const Rgba zero = table.lookup(0, 0.3, 1.9);
  EXPECT_EQ(zero[3], 0);
}

TEST(LengthTable, InterpolatesAndClamps) {
  // Constant tau: alpha(l) = 1 - exp(-tau l), sampled at l = 0, 1, 2, 3.
  const TransferFunction tf({{0, 0.5, 0.5, 0.5, 0.3}, {1, 0.5, 0.5, 0.5, 0.3}});
  const LengthTable table = test::length_table(tf, 4, 4, 3.0);
  const double a1 = 1 - std::exp(-0.3), a2 = 1 - std::exp(-0.6);
  EXPECT_NEAR(table.lookup(1.5, 0.2, 0.9)[3], 0.5 * (a1 + a2), 1e-6);  // linear in l between nodes
  EXPECT_NEAR(table.lookup(1.0, -5, 7)[3], a1, 1e-6);                 // scalars clamped to [0, 1]
  EXPECT_NEAR(table.lookup(1.0, -5, 7)[0], 0.5 * a1, 1e-6);
}

TEST(LengthTable, RefusesBadSizes) {
  const TransferFunction tf({{0, 1, 1, 1, 1}});
  EXPECT_THROW(test::length_table(tf, 1, 4, 1), Error);
  EXPECT_THROW(test::length_table(tf, 4, 1, 1), Error);
  EXPECT_THROW(test::length_table(tf, 4, 4, 0), Error);
}

}  // namespace
}  // namespace vri
