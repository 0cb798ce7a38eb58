// The second-order entry (El Hajjar et al. 2008; second_order_table.hpp)
// against closed forms, an independent evaluation of the same model, and the
// exact integral along the continuous parabola; the table's lookups.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "tables/random_tf.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"  // kDefaultSecondOrderIterations
#include "tables/second_order_exact.hpp"
#include "tables/second_order_table.hpp"
#include "tables/slab_integral.hpp"

namespace vri {
namespace {

// The discretised transfer function at continuous index u (control points
// inside a bin included), clamped to the axis.
TfSample tf_at(const DiscreteTf& tf, double u) { return tf.at_index(std::clamp(u, 0.0, tf.size() - 1.0)); }

// The parabola in Lagrange form through (0, f), (1/2, m), (1, b).
double parabola(double f, double m, double b, double t) {
  return f * (2 * t - 1) * (t - 1) - 4 * m * t * (t - 1) + b * t * (2 * t - 1);
}

// The integral of SPEC §4 along the continuous parabola (K -> infinity), by
// the trapezoid rule on 2^18 panels for both the depth and the colour.
SlabRgba continuous_integral(const DiscreteTf& tf, double f, double m, double b, double length) {
  const int panels = 1 << 18;
  const double h = 1.0 / panels;
  double depth = 0, c[3] = {0, 0, 0};
  auto at = [&](int i) { return tf_at(tf, parabola(f, m, b, i * h)); };
  TfSample prev = at(0);
  double prev_w = prev.tau * length;  // c tau e^-D at t = 0 without c
  for (int i = 1; i <= panels; ++i) {
    const TfSample s = at(i);
    depth += 0.5 * h * length * (prev.tau + s.tau);
    const double w = s.tau * length * std::exp(-depth);
    c[0] += 0.5 * h * (prev_w * prev.r + w * s.r);
    c[1] += 0.5 * h * (prev_w * prev.g + w * s.g);
    c[2] += 0.5 * h * (prev_w * prev.b + w * s.b);
    prev = s, prev_w = w;
  }
  return {c[0], c[1], c[2], -std::expm1(-depth)};
}

double max_abs(const SlabRgba& a, const SlabRgba& b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
}

TEST(SecondOrderEntry, ConstantParabolaIsTheHomogeneousSlab) {
  const DiscreteTf tf(test::random_spiky_tf(3, 8.0), 20);
  for (int i = 0; i < 20; ++i)
    for (const int k : {1, 7, 64}) {
      // K homogeneous sub-slabs of L/K composite to one of length L.
      const double a = -std::expm1(-tf[i].tau * 2.5);
      const SlabRgba e = second_order_entry(tf, i, i, i, 2.5, k);
      EXPECT_NEAR(e.a, a, 1e-14);
      EXPECT_NEAR(e.r, tf[i].r * a, 1e-14);
      EXPECT_NEAR(e.b, tf[i].b * a, 1e-14);
    }
}

// A straight parabola (m halfway) is one linear ramp: its K chords are
// consecutive pieces of one first-order slab, which "over" joins exactly.
TEST(SecondOrderEntry, StraightParabolaIsTheFirstOrderSlab) {
  const DiscreteTf tf(test::random_spiky_tf(5, 6.0), 32);
  for (const double length : {0.3, 1.0, 4.0})
    for (const int k : {1, 3, 64})
      for (const double f : {0.0, 3.5, 17.0, 31.0})
        for (const double b : {0.0, 2.25, 20.0, 31.0})
          ASSERT_LE(max_abs(second_order_entry(tf, f, (f + b) / 2, b, length, k), exact_index_slab(tf, f, b, length)),
                    1e-12)
              << f << " " << b << " K " << k;
}

// A spike narrower than a bin (the issue-16 case): every chord integrates the
// control points it crosses, so entries whose parabola crosses the spike see
// it whatever K, and agree with the integral along the continuous parabola.
TEST(SecondOrderEntry, SeesASpikeNarrowerThanABin) {
  const TransferFunction spike({{0, 0, 0, 0, 0},
                                {100.2, 1, 0.5, 0.2, 0},
                                {100.5, 1, 0.5, 0.2, 2},
                                {100.8, 1, 0.5, 0.2, 0},
                                {255, 0, 0, 0, 0}});
  const DiscreteTf tf(spike, 256);  // bins one scalar unit wide: the spike lies inside bin 100
  // Chords depart from the parabola by O(1/K^2); the old point samples of the
  // table scalars gave alpha 0 for all three.
  for (const auto& [k, bound] : {std::pair{4, 3e-2}, {16, 5e-3}, {64, 1e-4}}) {
    for (const auto& p : {std::array{90.0, 110.0, 120.0}, {100.0, 103.0, 99.0}, {98.0, 101.0, 101.0}}) {
      const SlabRgba e = second_order_entry(tf, p[0], p[1], p[2], 2.0, k);
      const SlabRgba exact = continuous_integral(tf, p[0], p[1], p[2], 2.0);
      EXPECT_GT(exact.a, 0.02);
      EXPECT_LE(max_abs(e, exact), bound) << p[0] << " " << p[1] << " " << p[2] << " K " << k;
    }
  }
}

TEST(SecondOrderEntry, ConvergesToTheContinuousParabolaIntegral) {
  const DiscreteTf tf(test::random_spiky_tf(7, 3.0), 24);
  const double fmb[][3] = {{0, 23, 5}, {3, 12, 20}, {20, 2, 18}, {10.5, 16.25, 1}, {23, 23, 0}};
  for (const auto& p : fmb) {
    const SlabRgba exact = continuous_integral(tf, p[0], p[1], p[2], 1.5);
    const double e64 = max_abs(second_order_entry(tf, p[0], p[1], p[2], 1.5, 64), exact);
    const double e256 = max_abs(second_order_entry(tf, p[0], p[1], p[2], 1.5, 256), exact);
    // Chords depart from the parabola by O(1/K^2) in the scalar.
    EXPECT_LE(e256, 2e-4) << p[0] << " " << p[1] << " " << p[2];
    EXPECT_LE(max_abs(second_order_entry(tf, p[0], p[1], p[2], 1.5, 4096), exact), 2e-6);
    if (e64 > 1e-4) {  // well above the trapezoid reference's own error at steps
      EXPECT_LE(e256, e64 / 6) << p[0] << " " << p[1] << " " << p[2];
    }
  }
}

// The `exact` builder (second_order_exact.hpp) against the closed form of a
// constant parabola and the independent trapezoid quadrature along the
// continuous parabola; `plain` at the default K and `fast` against it.
TEST(ExactSecondOrderBuilder, MatchesClosedFormsAndQuadrature) {
  const TransferFunction spike({{0, 0.2, 0.4, 1, 0.5}, {100.2, 1, 0.5, 0.2, 0.5}, {100.5, 1, 0.5, 0.2, 4},
                                {100.8, 1, 0.5, 0.2, 0.5}, {255, 0.5, 1, 0.5, 1}});
  const DiscreteTf tf(spike, 24);  // the spike inside bin 9
  for (int i : {0, 9, 23}) {
    const double a = -std::expm1(-tf[i].tau * 1.5);
    EXPECT_NEAR(exact_second_order_entry(tf, i, i, i, 1.5).full.a, a, 1e-12);
  }
  const double fmb[][3] = {{0, 23, 5}, {3, 12, 20}, {20, 2, 18}, {8, 10, 9}, {23, 23, 0}};
  for (const auto& p : fmb)
    EXPECT_LE(max_abs(exact_second_order_entry(tf, p[0], p[1], p[2], 1.5).full,
                      continuous_integral(tf, p[0], p[1], p[2], 1.5)),
              1e-5)
        << p[0] << " " << p[1] << " " << p[2];
  const DiscreteTf small(spike, 12);  // every entry to 1e-7 takes a while
  const auto exact = make_second_order_builder("exact")->build(small, 1.5, 1);
  double plain = 0, fast = 0;
  const SecondOrderTable p8 = make_second_order_builder("plain")->build(small, 1.5, kDefaultSecondOrderIterations),
                         f8 = make_second_order_builder("fast")->build(small, 1.5, kDefaultSecondOrderIterations);
  for (std::size_t k = 0; k < exact.bytes() / sizeof(float); ++k) {
    plain = std::max(plain, double(std::abs(p8.data()[k] - exact.data()[k])));
    fast = std::max(fast, double(std::abs(f8.data()[k] - exact.data()[k])));
  }
  std::printf("against exact at K = 8: plain %.3g, fast %.3g\n", plain, fast);
  EXPECT_LE(plain, 0.03);  // measured 0.018: the chord polyline at K = 8
  EXPECT_LE(fast, 0.1);    // measured 0.070: and the bilinear chord lookups inside the spike's bin
  EXPECT_THROW(make_second_order_builder("exact")->build(DiscreteTf(spike, 65), 1.0, 1), Error);
}

TEST(SecondOrderTable, LookupIsTrilinearBetweenEntries) {
  const DiscreteTf tf(test::random_spiky_tf(9, 2.0), 16);
  const SecondOrderTable t = make_second_order_builder("plain")->build(tf, 1.0, 8);
  const ScalarAxis& ax = tf.axis();
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(t.lookup(ax.scalar(3), ax.scalar(7), ax.scalar(11))[c], t.entry(3, 7, 11)[c]);
    double mean = 0;
    for (int corner = 0; corner < 8; ++corner)
      mean += t.entry(3 + (corner >> 2), 7 + ((corner >> 1) & 1), 11 + (corner & 1))[c] / 8.0;
    const double half = (ax.scalar(1) - ax.scalar(0)) / 2;
    EXPECT_NEAR(t.lookup(ax.scalar(3) + half, ax.scalar(7) + half, ax.scalar(11) + half)[c], mean, 1e-7);
  }
  EXPECT_EQ(t.bytes(), std::size_t{16} * 16 * 16 * 16);
}

TEST(SecondOrderLengthTable, IsLinearInLength) {
  const DiscreteTf tf(test::random_spiky_tf(11, 2.0), 12);
  const auto builder = make_second_order_builder("plain");
  const SecondOrderLengthTable t = build_second_order_length_table(*builder, tf, 3, 2.0, 16);
  const SecondOrderTable one = builder->build(tf, 1.0, 16), two = builder->build(tf, 2.0, 16);
  const double s[3] = {tf.axis().scalar(2), tf.axis().scalar(9), tf.axis().scalar(5)};
  const Rgba at1 = t.lookup(1.0, s[0], s[1], s[2]), at2 = t.lookup(5.0, s[0], s[1], s[2]),
             at_half = t.lookup(0.5, s[0], s[1], s[2]);
  for (int c = 0; c < 4; ++c) {
    EXPECT_EQ(at1[c], one.entry(2, 9, 5)[c]);
    EXPECT_EQ(at2[c], two.entry(2, 9, 5)[c]);  // clamped to max_length
    EXPECT_NEAR(at_half[c], 0.5 * one.entry(2, 9, 5)[c], 1e-7);
  }
  EXPECT_EQ(t.bytes(), 3 * one.bytes());
}

TEST(SecondOrderTable, RefusesBadInput) {
  const DiscreteTf tf(test::random_spiky_tf(1, 1.0), 8);
  const auto plain = make_second_order_builder("plain");
  EXPECT_THROW(make_second_order_builder("brute"), Error);
  EXPECT_THROW(plain->build(tf, 1.0, 0), Error);
  EXPECT_THROW(plain->build(tf, 1.0, kMaxSecondOrderIterations + 1), Error);
  EXPECT_THROW(plain->build(tf, 0.0, 8), Error);
  EXPECT_THROW(SecondOrderTable(ScalarAxis{0, 1, 407}, 1.0, 8), Error);  // 407^3 > 2^26
  EXPECT_THROW(build_second_order_length_table(*plain, tf, 1, 1.0, 8), Error);
  EXPECT_THROW(build_second_order_length_table(*plain, DiscreteTf(test::random_spiky_tf(1, 1.0), 256), 5, 1.0, 8),
               Error);  // 5 x 2^24 entries, refused before building
}

}  // namespace
}  // namespace vri
