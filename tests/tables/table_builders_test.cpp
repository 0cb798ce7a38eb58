// Every builder against `brute`, the reference (tables/brute_builder.hpp).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>

#include "tables/random_tf.hpp"
#include "vri/error.hpp"
#include "tables/brute_builder.hpp"
#include "tables/slab_integral.hpp"
#include "tables/table_builder.hpp"

namespace vri {
namespace {

double max_difference(const PreintegrationTable& a, const PreintegrationTable& b, int channel_lo = 0,
                      int channel_hi = 4) {
  double m = 0;
  for (std::size_t k = 0; k < a.data().size(); ++k)
    if (int(k % 4) >= channel_lo && int(k % 4) < channel_hi) {
      m = std::max(m, double(std::abs(a.data()[k] - b.data()[k])));
    }
  return m;
}

struct Case {
  unsigned seed;
  int n;
  double length, max_tau;
};

TEST(IncrementalBuilder, EqualsBruteInEveryEntry) {
  const auto incremental = make_table_builder("incremental");
  for (const Case c : {Case{1, 64, 1.0, 0.5}, Case{2, 97, 0.5, 4.0}, Case{3, 80, 3.0, 20.0},
                       Case{4, 33, 1.0, 300.0}, Case{5, 128, 1.0, 1.0}}) {
    const DiscreteTf tf(test::random_spiky_tf(c.seed, c.max_tau), c.n);
    const PreintegrationTable ref = BruteBuilder().build(tf, c.length);
    const PreintegrationTable fast = incremental->build(tf, c.length);
    EXPECT_LE(max_difference(ref, fast), 1e-5) << "seed " << c.seed;
    // The tables are not trivially zero: some entries are far from transparent.
    EXPECT_GT(*std::max_element(ref.data().begin(), ref.data().end()), 0.2f) << "seed " << c.seed;
  }
}

// Mirroring the transfer function (s -> 255 - s) swaps front and back.
TEST(TableBuilders, MirroredTransferFunctionTransposesTheTable) {
  const TransferFunction tf = test::random_spiky_tf(7, 10.0);
  std::vector<ControlPoint> mirrored(tf.points().rbegin(), tf.points().rend());
  for (auto& p : mirrored) p.s = 255 - p.s;
  const int n = 52;
  const DiscreteTf a(tf, n), b(TransferFunction(mirrored), n);
  for (const char* name : {"brute", "incremental"}) {
    const auto builder = make_table_builder(name);
    const PreintegrationTable ta = builder->build(a, 1.5), tb = builder->build(b, 1.5);
    double m = 0, asym = 0;
    for (int f = 0; f < n; ++f)
      for (int k = 0; k < n; ++k)
        for (int c = 0; c < 4; ++c) {
          m = std::max(m, double(std::abs(ta.entry(f, k)[c] - tb.entry(n - 1 - f, n - 1 - k)[c])));
          asym = std::max(asym, double(std::abs(ta.entry(f, k)[c] - ta.entry(k, f)[c])));
        }
    EXPECT_LE(m, 2e-6) << name;
    EXPECT_GT(asym, 0.05) << name;  // front and back really differ
  }
}

TEST(TableBuilders, ConstantTransferFunctionGivesTheHomogeneousSlabEverywhere) {
  const DiscreteTf tf(TransferFunction({{0, 0.2, 0.4, 0.8, 1.3}, {10, 0.2, 0.4, 0.8, 1.3}}), 40);
  const double a = 1 - std::exp(-1.3 * 0.9);
  for (const char* name : {"brute", "incremental", "engel"}) {
    const PreintegrationTable t = make_table_builder(name)->build(tf, 0.9);
    for (int f = 0; f < 40; f += 3) {
      for (int b = 0; b < 40; b += 5) {
        EXPECT_NEAR(t.entry(f, b)[3], a, 1e-6) << name;
        if (std::string(name) != "engel") {
          EXPECT_NEAR(t.entry(f, b)[2], 0.8 * a, 1e-6) << name;
        }
      }
    }
  }
}

// Engel et al.'s table gets the opacity exactly (the optical depth ignores
// ordering) and overestimates colour, since nothing inside a slab is attenuated.
TEST(EngelBuilder, ExactOpacityAndColourFromAbove) {
  const DiscreteTf tf(test::random_spiky_tf(11, 2.0), 64);
  const PreintegrationTable ref = BruteBuilder().build(tf, 1.0);
  const PreintegrationTable engel = make_table_builder("engel")->build(tf, 1.0);
  EXPECT_LE(max_difference(ref, engel, 3, 4), 1e-6);
  for (std::size_t k = 0; k < ref.data().size(); ++k)
    if (k % 4 != 3) {
      ASSERT_GE(engel.data()[k], ref.data()[k] - 1e-6f);
    }
  EXPECT_GT(max_difference(ref, engel, 0, 3), 0.05);  // and the error is real
}

TEST(LengthTable, EverySliceIsTheTableForItsLength) {
  const DiscreteTf tf(test::random_spiky_tf(13, 2.0), 24);
  const auto incremental = make_table_builder("incremental");
  const LengthTable lt = build_length_table(*incremental, tf, 5, 2.0);
  ASSERT_EQ(lt.slices().size(), 5u);
  ASSERT_EQ(lt.data().size(), 5u * 24 * 24 * 4);
  for (float v : lt.slices()[0].data()) ASSERT_EQ(v, 0.0f);
  for (int m = 1; m < 5; ++m) {
    const PreintegrationTable ref = BruteBuilder().build(tf, 2.0 * m / 4);
    EXPECT_LE(max_difference(ref, lt.slices()[m]), 1e-5) << m;
  }
  // Halfway between lengths 1.0 and 1.5, linear in l.
  const Rgba mid = lt.lookup(1.25, 100, 40), lo = lt.lookup(1.0, 100, 40), hi = lt.lookup(1.5, 100, 40);
  EXPECT_NEAR(mid[3], 0.5 * (lo[3] + hi[3]), 1e-7);
  EXPECT_NE(lo[3], hi[3]);
}

// An extinction of 1e35 or 1e38 per unit makes every slab opaque at its very
// front: alpha = 1 and the colour that of the front scalar (the limit of
// int c dalpha as the opacity gathers at t = 0). The panel counts of the
// quadratures grow like sqrt(tau l) there and once overflowed an int.
TEST(TableBuilders, HugeExtinctionGivesTheOpaqueSlabLimit) {
  for (const double tau : {1e35, 1e38}) {
    const DiscreteTf tf(TransferFunction({{0, 0.9, 0.2, 0.1, 0}, {10, 0.1, 0.5, 0.7, tau}}), 16);
    for (const char* name : {"brute", "incremental"}) {
      const PreintegrationTable t = make_table_builder(name)->build(tf, 1.0);
      for (int f = 0; f < 16; ++f)
        for (int b = 0; b < 16; ++b) {
          if (f == 0 && b == 0) continue;  // tau = 0 there: the empty slab
          const float* e = t.entry(f, b);
          ASSERT_EQ(e[3], 1.0f) << name << " tau " << tau << " entry " << f << ", " << b;
          ASSERT_NEAR(e[0], tf[f].r, 1e-6) << name << " tau " << tau << " entry " << f << ", " << b;
          ASSERT_NEAR(e[1], tf[f].g, 1e-6) << name << " tau " << tau << " entry " << f << ", " << b;
          ASSERT_NEAR(e[2], tf[f].b, 1e-6) << name << " tau " << tau << " entry " << f << ", " << b;
        }
      for (int c = 0; c < 4; ++c) EXPECT_EQ(t.entry(0, 0)[c], 0.0f) << name;
    }
  }
}

// brute's quadrature takes up to 201 panels a piece where a slab is deep
// (issue 47, item 8: one tetrahedron at coordinates 3e38 ran for minutes under
// a cap its estimate of 8 evaluations a bin passed); the other builders' work
// does not depend on the depth.
TEST(TableBuilders, BruteWorkCountsThePanelsOfDeepSlabs) {
  const DiscreteTf tf(TransferFunction({{0, 0.9, 0.2, 0.1, 0}, {10, 0.1, 0.5, 0.7, 1.0}}), 32);
  const BruteBuilder brute;
  const double plain = brute.work(32) * 8;  // 9 lengths: 8 non-empty slices
  const double shallow = brute.length_table_work(tf, 9, 1e-3), deep = brute.length_table_work(tf, 9, 3e38);
  EXPECT_GT(shallow, 0.9 * plain);
  EXPECT_LT(shallow, 1.1 * plain);
  EXPECT_GT(deep, 150 * plain);  // depth ~1e38 a piece: 201 panels of 8 points, where one did
  EXPECT_LT(deep, 210 * plain);
  for (const char* name : {"incremental", "sliced", "engel", "exact"}) {
    const auto builder = make_table_builder(name);
    EXPECT_EQ(builder->length_table_work(tf, 9, 3e38), builder->work(32) * 8) << name;
  }
}

TEST(TableBuilders, SameBytesForAnyThreadCount) {
  const DiscreteTf tf(test::random_spiky_tf(17, 2.0), 100);
  for (const char* name : {"brute", "incremental", "sliced", "engel"}) {
    const auto builder = make_table_builder(name);
    std::vector<float> one, many;
    {
      tbb::global_control only(tbb::global_control::max_allowed_parallelism, 1);
      const PreintegrationTable t = builder->build(tf, 1.0);
      one.assign(t.data().begin(), t.data().end());
    }
    const PreintegrationTable t = builder->build(tf, 1.0);
    many.assign(t.data().begin(), t.data().end());
    EXPECT_EQ(one, many) << name;
  }
}

TEST(TableBuilders, BadInputIsAnError) {
  const DiscreteTf tf(test::random_spiky_tf(1, 1.0), 8);
  EXPECT_THROW(make_table_builder("sliced-by-hand"), Error);
  EXPECT_THROW(make_table_builder("incremental")->build(tf, 0.0), Error);
  EXPECT_THROW(make_table_builder("brute")->build(tf, -1.0), Error);
  EXPECT_THROW(build_length_table(*make_table_builder("engel"), tf, 1, 1.0), Error);
  EXPECT_THROW(build_length_table(*make_table_builder("engel"), tf, 4, 0.0), Error);
  EXPECT_THROW(DiscreteTf(test::random_spiky_tf(1, 1.0), 1), Error);
}

}  // namespace
}  // namespace vri
