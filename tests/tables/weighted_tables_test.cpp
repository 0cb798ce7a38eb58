// The weighted tables of interpolated lighting (tables/weighted_tables.hpp)
// against the unweighted table and against every entry integrated on its own.
#include "tables/weighted_tables.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>

#include "tables/random_tf.hpp"
#include "vri/error.hpp"
#include "tables/brute_builder.hpp"
#include "tables/incremental_builder.hpp"
#include "tables/table_builder.hpp"

namespace vri {
namespace {

struct Case {
  unsigned seed;
  int n;
  double length, max_tau;
};
constexpr Case kCases[] = {{1, 64, 1.0, 0.5}, {2, 64, 0.5, 4.0}, {3, 64, 3.0, 20.0}, {4, 33, 1.0, 300.0}};

// Worst |a - b| over entries and the four channels.
double max_difference(const PreintegrationTable& a, const PreintegrationTable& b) {
  double m = 0;
  for (std::size_t k = 0; k < a.data().size(); ++k) m = std::max(m, double(std::abs(a.data()[k] - b.data()[k])));
  return m;
}

// Front + back = the unweighted table (C, and S = alpha), for the fast tables
// and for the reference, whose front and back are integrated separately.
TEST(WeightedTables, FrontPlusBackIsTheUnweightedTable) {
  for (const Case c : kCases) {
    const DiscreteTf tf(test::random_spiky_tf(c.seed, c.max_tau), c.n);
    const PreintegrationTable c1 = IncrementalBuilder().build(tf, c.length);
    for (const WeightedTables& w : {build_weighted_tables(tf, c.length), brute_weighted_tables(tf, c.length)}) {
      double worst = 0;
      for (int f = 0; f < c.n; ++f)
        for (int b = 0; b < c.n; ++b) {
          const float *u = c1.entry(f, b), *front = w.front.entry(f, b), *back = w.back.entry(f, b);
          for (int ch = 0; ch < 3; ++ch) worst = std::max(worst, double(std::abs(front[ch] + back[ch] - u[ch])));
          worst = std::max(worst, double(std::abs(front[3] - u[3])));  // S_front + S_back = alpha
          // Each weighted part lies between 0 and the whole.
          EXPECT_GE(back[3], -1e-6f);
          EXPECT_LE(back[3], u[3] + 1e-6f);
        }
      EXPECT_LE(worst, 1e-5) << "seed " << c.seed;
    }
  }
}

// The paper's O(N^2) build (C_W = (C_G - i C_1) / (j - i)) against brute
// force. Measured worst: see docs/LIGHTING.md.
TEST(WeightedTables, EqualBruteWeightedInEveryEntry) {
  for (const Case c : kCases) {
    const DiscreteTf tf(test::random_spiky_tf(c.seed, c.max_tau), c.n);
    const WeightedTables fast = build_weighted_tables(tf, c.length), ref = brute_weighted_tables(tf, c.length);
    EXPECT_LE(max_difference(fast.front, ref.front), 1e-5) << "seed " << c.seed;
    EXPECT_LE(max_difference(fast.back, ref.back), 1e-5) << "seed " << c.seed;
    EXPECT_GT(*std::max_element(ref.back.data().begin(), ref.back.data().end()), 0.1f) << "seed " << c.seed;
  }
}

// A homogeneous slab in closed form: S_back = (1 - e^{-A}(1 + A)) / A.
TEST(WeightedTables, HomogeneousSlabIsClosedForm) {
  const DiscreteTf tf(TransferFunction({{0, 0.5, 0.25, 1, 0.01}, {1, 0.5, 0.25, 1, 3}}), 2);
  for (double l : {0.1, 1.0, 5.0}) {
    const WeightedTables w = build_weighted_tables(tf, l);
    for (int i : {0, 1}) {
      const double A = tf[i].tau * l, s = (1 - std::exp(-A) * (1 + A)) / A;
      EXPECT_NEAR(w.back.entry(i, i)[3], s, 1e-7 * std::max(1.0, s)) << l;
      EXPECT_NEAR(w.back.entry(i, i)[0], 0.5 * s, 1e-7) << l;
      EXPECT_NEAR(w.front.entry(i, i)[2], 1 - std::exp(-A) - s, 1e-7) << l;
    }
  }
}

TEST(WeightedTables, SameBytesForAnyThreadCount) {
  const DiscreteTf tf(test::random_spiky_tf(5, 3.0), 200);
  const auto build = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return build_weighted_tables(tf, 1.0);
  };
  const WeightedTables one = build(1), two = build(2);
  EXPECT_TRUE(std::ranges::equal(one.front.data(), two.front.data()));
  EXPECT_TRUE(std::ranges::equal(one.back.data(), two.back.data()));
}

TEST(WeightedTables, BadLengthIsAnError) {
  const DiscreteTf tf(test::random_spiky_tf(1, 1.0), 8);
  EXPECT_THROW(build_weighted_tables(tf, 0.0), Error);
}

// The mesh methods' weighted (l, s_f, s_b) tables: every slice is the
// weighted table of its length, and front + back is the unweighted
// LengthTable at the nodes and between them (both linear in l).
TEST(WeightedLengthTables, FrontPlusBackIsTheUnweightedLengthTable) {
  const DiscreteTf tf(test::random_spiky_tf(2, 4.0), 48);
  const WeightedLengthTables w = build_weighted_length_tables(tf, 5, 2.0);
  const LengthTable c1 = build_length_table(IncrementalBuilder(), tf, 5, 2.0);
  ASSERT_EQ(w.front.slices().size(), 5u);
  EXPECT_TRUE(std::ranges::all_of(w.front.slices()[0].data(), [](float v) { return v == 0; }));
  for (int m = 1; m < 5; ++m) {
    const WeightedTables slice = build_weighted_tables(tf, 2.0 * m / 4);
    EXPECT_TRUE(std::ranges::equal(w.front.slices()[m].data(), slice.front.data())) << m;
    EXPECT_TRUE(std::ranges::equal(w.back.slices()[m].data(), slice.back.data())) << m;
  }
  double worst = 0, largest = 0;
  for (double l : {0.0, 0.3, 0.5, 1.26, 2.0})
    for (double f = 0; f <= 255; f += 7.3)
      for (double b = 0; b <= 255; b += 5.9) {
        const Rgba u = c1.lookup(l, f, b), front = w.front.lookup(l, f, b), back = w.back.lookup(l, f, b);
        for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(front[c] + back[c] - u[c]));
        worst = std::max(worst, std::abs(front[3] - u[3]));
        largest = std::max(largest, back[3]);
      }
  EXPECT_LE(worst, 1e-5);
  EXPECT_GT(largest, 0.1);  // the weighted tables are not trivially zero
}

TEST(WeightedLengthTables, SameBytesForAnyThreadCount) {
  const DiscreteTf tf(test::random_spiky_tf(5, 3.0), 64);
  const auto build = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    return build_weighted_length_tables(tf, 6, 1.5);
  };
  const WeightedLengthTables one = build(1), two = build(2);
  EXPECT_EQ(one.front.data(), two.front.data());
  EXPECT_EQ(one.back.data(), two.back.data());
}

TEST(WeightedLengthTables, RefusesBadSizes) {
  const DiscreteTf tf(test::random_spiky_tf(1, 1.0), 8);
  EXPECT_THROW(build_weighted_length_tables(tf, 1, 1.0), Error);
  EXPECT_THROW(build_weighted_length_tables(tf, 4, 0.0), Error);
  // Two tables of 2^26 entries each would fit the limit alone, not together.
  const DiscreteTf big(test::random_spiky_tf(1, 1.0), 1024);
  EXPECT_THROW(build_weighted_length_tables(big, 64, 1.0), Error);
}

}  // namespace
}  // namespace vri
