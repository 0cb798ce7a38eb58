// Weighted second-order tables (second_order_weighted.hpp): the three Lagrange
// weights sum to the unweighted slab, the entries match an independent
// quadrature of the weighted integrals, fast matches its chord model, and the
// bytes do not depend on the thread count.
#include "tables/second_order_weighted.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <utility>

#include "tables/random_tf.hpp"
#include "tables/second_order_chord_model.hpp"
#include "vri/error.hpp"

namespace vri {
namespace {

double fast_tolerance(int iterations) { return 1e-6 + 3e-8 * iterations; }  // float sums over K chords


double channel(const SlabRgba& v, int c) { return c == 0 ? v.r : c == 1 ? v.g : c == 2 ? v.b : v.a; }

// D_f + D_m + D_b = C and S_f + S_m + S_b = alpha: in the definition against
// second_order_entry, and in the packed plain tables (D_f from the definition).
TEST(SecondOrderWeighted, WeightsSumToTheUnweightedTable) {
  const DiscreteTf tf(test::random_spiky_tf(3, 30.0), 13);
  const auto plain = make_second_order_builder("plain");
  const SecondOrderWeightedTables t = plain->build_weighted(tf, 1.5, 40);
  const SecondOrderTable unweighted = plain->build(tf, 1.5, 40);
  EXPECT_EQ(std::memcmp(t.full.data(), unweighted.data(), unweighted.bytes()), 0);
  double worst = 0, largest = 0;
  for (int f = 0; f < 13; ++f)
    for (int m = 0; m < 13; ++m)
      for (int b = 0; b < 13; ++b) {
        const SecondOrderWeights w = second_order_weighted_entry(tf, f, m, b, 1.5, 40);
        const SlabRgba one = second_order_entry(tf, f, m, b, 1.5, 40);
        for (int c = 0; c < 4; ++c) {
          const double sum = channel(w.front, c) + channel(w.middle, c) + channel(w.back, c);
          const double packed = channel(w.front, c) + t.middle.entry(f, m, b)[c] + t.back.entry(f, m, b)[c];
          worst = std::max({worst, std::abs(sum - channel(one, c)), std::abs(packed - t.full.entry(f, m, b)[c])});
          largest = std::max(largest, std::abs(channel(w.back, c)));
        }
      }
  EXPECT_LT(worst, 1e-5);
  EXPECT_GT(largest, 0.1);  // the weights are not all zero
}

// The weighted integrals along the continuous parabola, written independently:
// trapezoid rule in u on M intervals for both the optical depth and the
// weighted emission, int L_k(u) c tau e^{-D(u)} L du (white for k's specular).
SecondOrderWeights quadrature(const DiscreteTf& tf, double s_f, double s_m, double s_b, double length) {
  const int M = 40000;
  const auto scalar = [&](double u) {  // Lagrange interpolation through the three samples
    const double v = s_f * lagrange_front(u) + s_m * lagrange_middle(u) + s_b * lagrange_back(u);
    return std::clamp(v, 0.0, tf.size() - 1.0);
  };
  SecondOrderWeights out;
  double depth = 0, prev_tau = 0;
  for (int i = 0; i <= M; ++i) {
    const double u = double(i) / M;
    const TfSample v = tf.at_index(scalar(u));
    if (i > 0) depth += 0.5 * (prev_tau + v.tau) * length / M;
    prev_tau = v.tau;
    const double g = v.tau * std::exp(-depth) * length / M * (i == 0 || i == M ? 0.5 : 1.0);
    const auto add = [&](SlabRgba& to, double w) {
      to.r += w * g * v.r, to.g += w * g * v.g, to.b += w * g * v.b, to.a += w * g;
    };
    add(out.front, lagrange_front(u));
    add(out.middle, lagrange_middle(u));
    add(out.back, lagrange_back(u));
  }
  return out;
}

TEST(SecondOrderWeighted, EntriesMatchQuadratureOfTheWeightedIntegrals) {
  // A smooth transfer function: the chords depart from the parabola by
  // O(1/K^2), so K = 1024 leaves ~1e-7 of model error.
  const TransferFunction smooth({{0, 0.2, 0.4, 1, 0.5}, {100, 1, 0.5, 0.2, 3}, {255, 0.5, 1, 0.5, 1}});
  const DiscreteTf tf(smooth, 9);
  double worst = 0;
  for (int f = 0; f < 9; f += 2)
    for (int m = 0; m < 9; m += 3)
      for (int b = 0; b < 9; b += 2) {
        const SecondOrderWeights q = quadrature(tf, f, m, b, 0.7);
        const SecondOrderWeights d = second_order_weighted_entry(tf, f, m, b, 0.7, 1024);
        for (int c = 0; c < 4; ++c)
          worst = std::max({worst, std::abs(channel(d.front, c) - channel(q.front, c)),
                            std::abs(channel(d.middle, c) - channel(q.middle, c)),
                            std::abs(channel(d.back, c) - channel(q.back, c))});
      }
  std::printf("definition %.3g\n", worst);
  EXPECT_LT(worst, 2e-6);
}

// fast against its model written out (second_order_chord_model.hpp): the
// lanes, the weighted layout and the Lagrange weights at the chord ends; its
// full table has the bytes of build().
TEST(SecondOrderWeighted, FastEqualsItsChordModelInEveryEntry) {
  const auto fast = make_second_order_builder("fast");
  const DiscreteTf tf(test::random_spiky_tf(5, 20.0), 19);
  for (int iterations : {1, 16, 64}) {
    const SecondOrderWeightedTables q = fast->build_weighted(tf, 2.0, iterations);
    EXPECT_EQ(std::memcmp(q.full.data(), fast->build(tf, 2.0, iterations).data(), q.full.bytes()), 0);
    const test::ChordModel model(tf, 2.0, iterations);
    double worst = 0;
    for (int f = 0; f < 19; ++f)
      for (int m = 0; m < 19; ++m)
        for (int b = 0; b < 19; ++b) {
          if (2 * m == f + b) continue;  // straight: the definition (StraightEntriesAreTheFirstOrderSlab)
          const SecondOrderWeights w = model.entry(f, m, b);
          for (int c = 0; c < 4; ++c)
            worst = std::max({worst, std::abs(q.full.entry(f, m, b)[c] - channel(w.full, c)),
                              std::abs(q.middle.entry(f, m, b)[c] - channel(w.middle, c)),
                              std::abs(q.back.entry(f, m, b)[c] - channel(w.back, c))});
        }
    EXPECT_LE(worst, fast_tolerance(iterations)) << "K " << iterations;
  }
}

TEST(SecondOrderWeighted, SameBytesForAnyThreadCount) {
  const DiscreteTf tf(test::random_spiky_tf(8, 5.0), 26);
  for (const char* name : {"plain", "fast"}) {
    const auto builder = make_second_order_builder(name);
    auto build = [&](int threads) {
      tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
      return builder->build_weighted(tf, 1.3, 16);
    };
    const SecondOrderWeightedTables one = build(1), two = build(2);
    for (auto table : {&SecondOrderWeightedTables::full, &SecondOrderWeightedTables::middle,
                       &SecondOrderWeightedTables::back})
      EXPECT_EQ(std::memcmp((one.*table).data(), (two.*table).data(), (one.*table).bytes()), 0) << name;
  }
}

// preint2-dual's weighted tables: slice m of each is build_weighted at length
// L_max m / (M - 1) (slice 0 empty), and the three count against the 1 GiB cap.
TEST(SecondOrderWeighted, LengthTablesHoldTheWeightedSlices) {
  const DiscreteTf tf(test::random_spiky_tf(2, 5.0), 9);
  const auto fast = make_second_order_builder("fast");
  const SecondOrderWeightedLengthTables t = build_second_order_weighted_length_tables(*fast, tf, 3, 2.0, 16);
  const SecondOrderWeightedTables one = fast->build_weighted(tf, 1.0, 16), two = fast->build_weighted(tf, 2.0, 16);
  for (auto [lengths, slice] : {std::pair{&t.full, &one.full}, std::pair{&t.middle, &one.middle},
                                std::pair{&t.back, &one.back}}) {
    ASSERT_EQ(lengths->slices().size(), 3u);
    EXPECT_EQ(std::memcmp(lengths->slices()[1].data(), slice->data(), slice->bytes()), 0);
    const float* empty = lengths->slices()[0].data();
    EXPECT_TRUE(std::all_of(empty, empty + slice->bytes() / sizeof(float), [](float v) { return v == 0; }));
  }
  EXPECT_EQ(std::memcmp(t.back.slices()[2].data(), two.back.data(), two.back.bytes()), 0);
  // 3 x 2 x 256^3 entries: 1.5 GiB.
  EXPECT_THROW(build_second_order_weighted_length_tables(*fast, DiscreteTf(test::random_spiky_tf(1, 1.0), 256), 2,
                                                         1.0, 8),
               Error);
}

}  // namespace
}  // namespace vri
