#include "tables/slab_integral.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>

#include "random_tf.hpp"
#include "tables/brute_builder.hpp"
#include "tables/piece_weights.hpp"

namespace vri {
namespace {

TEST(HomogeneousSlab, ClosedForm) {
  const SlabRgba v = homogeneous_slab({0.2, 0.5, 1.0, 0.7}, 3.0);
  const double a = 1 - std::exp(-2.1);
  EXPECT_NEAR(v.a, a, 1e-15);
  EXPECT_NEAR(v.r, 0.2 * a, 1e-15);
  EXPECT_NEAR(v.b, a, 1e-15);
}

TEST(LinearPiece, EqualEndsIsTheHomogeneousSlab) {
  const TfSample v{0.3, 0.6, 0.9, 2.5};
  const PiecePair p = linear_piece(v, v, 0.8);
  const SlabRgba h = homogeneous_slab(v, 0.8);
  for (const SlabRgba& s : {p.forward, p.backward}) {
    EXPECT_NEAR(s.r, h.r, 1e-12);
    EXPECT_NEAR(s.g, h.g, 1e-12);
    EXPECT_NEAR(s.a, h.a, 1e-15);
  }
}

// tau rising from 0: J = int_0^1 exp(-k x^2) dx = sqrt(pi/k)/2 erf(sqrt k), k = B/2,
// and C = c_p (1 - J) + c_q (J - E) by parts (docs/PREINTEGRATION.md).
TEST(LinearPiece, RampFromZeroMatchesErfClosedForm) {
  for (double B : {0.01, 0.7, 3.0, 40.0, 900.0}) {
    const TfSample p{1, 0, 0, 0}, q{0, 1, 0, B};
    const double k = B / 2, E = std::exp(-k);
    const double J = 0.5 * std::sqrt(std::numbers::pi / k) * std::erf(std::sqrt(k));
    const PiecePair pp = linear_piece(p, q, 1.0);
    EXPECT_NEAR(pp.forward.r, 1 - J, 1e-12) << B;
    EXPECT_NEAR(pp.forward.g, J - E, 1e-12) << B;
    EXPECT_NEAR(pp.forward.a, 1 - E, 1e-15) << B;
    // Backward the same piece starts opaque-side first: swap the roles.
    const PiecePair rev = linear_piece(q, p, 1.0);
    EXPECT_NEAR(rev.backward.r, pp.forward.r, 1e-12) << B;
    EXPECT_NEAR(rev.backward.g, pp.forward.g, 1e-12) << B;
  }
}

TEST(LinearPiece, AgreesWithDirectQuadratureInBothDirections) {
  const double taus[] = {0, 1e-6, 0.05, 0.41, 0.42, 0.9, 1.7, 12, 250, 5000};  // d = 0.6: thin below 0.25/0.6
  for (double tp : taus)
    for (double tq : taus) {
      const TfSample p{0.9, 0.1, 0.4, tp}, q{0.2, 0.8, 0.5, tq};
      const PiecePair pp = linear_piece(p, q, 0.6);
      const SlabRgba f = quadrature_piece(p, q, 0.6), b = quadrature_piece(q, p, 0.6);
      EXPECT_NEAR(pp.forward.r, f.r, 1e-10) << tp << " " << tq;
      EXPECT_NEAR(pp.forward.g, f.g, 1e-10) << tp << " " << tq;
      EXPECT_NEAR(pp.backward.r, b.r, 1e-10) << tp << " " << tq;
      EXPECT_NEAR(pp.backward.b, b.b, 1e-10) << tp << " " << tq;
      EXPECT_EQ(pp.forward.a, pp.backward.a);
      EXPECT_NEAR(pp.forward.a, f.a, 1e-14);
    }
}

TransferFunction ramp_tf() {
  return TransferFunction({{0, 1, 0, 0, 0.0}, {4, 0, 1, 0, 2.0}, {8, 0, 0, 1, 0.5}});
}

// A slab cut at a point where the scalar is s_m is the front half over the back half.
TEST(ExactSlab, SplitsAtAnInteriorPoint) {
  const DiscreteTf tf(ramp_tf(), 9);
  const SlabRgba whole = exact_slab(tf, 1.3, 7.1, 2.0);
  const double s_m = 1.3 + (7.1 - 1.3) * 0.3;
  const SlabRgba parts = over(exact_slab(tf, 1.3, s_m, 0.6), exact_slab(tf, s_m, 7.1, 1.4));
  EXPECT_NEAR(whole.r, parts.r, 1e-13);
  EXPECT_NEAR(whole.g, parts.g, 1e-13);
  EXPECT_NEAR(whole.b, parts.b, 1e-13);
  EXPECT_NEAR(whole.a, parts.a, 1e-13);
  EXPECT_GT(whole.g, 0.1);
}

TEST(ExactSlab, EqualScalarsAreHomogeneousAtTheInterpolatedValue) {
  const DiscreteTf tf(ramp_tf(), 9);
  const SlabRgba v = exact_slab(tf, 2.5, 2.5, 0.7);
  const double tau = 0.625 * 2.0, a = 1 - std::exp(-tau * 0.7);
  EXPECT_NEAR(v.a, a, 1e-14);
  EXPECT_NEAR(v.r, 0.375 * a, 1e-14);
}

// A straight run of bins is one segment of the transfer function: on ramp_tf
// at the integers 0..8, the runs are [0, 4] and [4, 8] (the control point at
// 4 ends one and starts the next).
TEST(DiscreteTfRuns, EndAtControlPoints) {
  const DiscreteTf tf(ramp_tf(), 9);
  for (int k = 0; k < 8; ++k) {
    EXPECT_EQ(tf.linear_begin(k), k < 4 ? 0 : 4) << k;
    EXPECT_EQ(tf.linear_end(k), k < 4 ? 4 : 8) << k;
  }
  // A control point inside a bin splits it: its run is itself.
  const DiscreteTf off(ramp_tf(), 6);  // scalars 0, 1.6, ..., 8: the point at 4 inside bin 2
  EXPECT_FALSE(off.sub_pieces(2).empty());
  EXPECT_EQ(off.linear_begin(2), 2);
  EXPECT_EQ(off.linear_end(2), 3);
  EXPECT_EQ(off.linear_begin(1), 0);
  EXPECT_EQ(off.linear_end(1), 2);
  EXPECT_EQ(off.linear_begin(4), 3);
  EXPECT_EQ(off.linear_end(3), 5);
}

// On spiky transfer functions every bin of a run is plain, the run's bins
// share it, and the transfer function between its ends, at and between the
// table scalars, is the line between its end samples: a run is one linear
// piece. And runs longer than a bin are common.
TEST(DiscreteTfRuns, AreOneLineOfPlainBins) {
  for (unsigned seed = 0; seed < 8; ++seed)
    for (int n : {7, 64, 256}) {
      const TransferFunction f = test::random_spiky_tf(seed, 50.0);
      const DiscreteTf tf(f, n);
      int long_runs = 0;
      for (int k = 0; k + 1 < n; ++k) {
        const int b = tf.linear_begin(k), e = tf.linear_end(k);
        ASSERT_TRUE(b <= k && k < e && e <= n - 1) << seed << " " << n << " " << k;
        if (e - b == 1) continue;
        ++long_runs;
        const TfSample p = tf[b], q = tf[e];
        for (int j = b; j < e; ++j) {
          ASSERT_TRUE(tf.sub_pieces(j).empty());
          ASSERT_EQ(tf.linear_begin(j), b);
          ASSERT_EQ(tf.linear_end(j), e);
          for (double x : {0.0, 0.37}) {
            const double w = (j + x - b) / (e - b);
            const TfSample v = f(tf.axis().scalar(j) + x * (tf.axis().scalar(j + 1) - tf.axis().scalar(j)));
            const double scale = 1 + std::abs(p.tau) + std::abs(q.tau);
            ASSERT_NEAR(v.tau, (1 - w) * p.tau + w * q.tau, 1e-12 * scale) << seed << " " << n << " " << j;
            ASSERT_NEAR(v.g, (1 - w) * p.g + w * q.g, 1e-12) << seed << " " << n << " " << j;
          }
        }
      }
      if (n == 256) {
        EXPECT_GT(long_runs, n / 4) << seed;
      }
    }
}

// exact_index_slab integrates a straight run as one piece: the same
// integral as the run's bins one by one, up to roundings (which add up over
// the bins to about 1e-12; a run that were not one line would be off by
// orders of magnitude more).
TEST(ExactSlab, RunsAreTheirBinsUpToRoundings) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  const auto piece = [](const TfSample& p, const TfSample& q, double d) { return linear_piece(p, q, d).forward; };
  for (unsigned seed = 0; seed < 6; ++seed)
    for (double max_tau : {0.05, 2.0, 300.0}) {
      const DiscreteTf tf(test::random_spiky_tf(seed, max_tau), 256);
      for (int i = 0; i < 200; ++i) {
        const double u_f = 255 * u(rng), u_b = 255 * u(rng), length = std::pow(10.0, -2 + 2.5 * u(rng));
        const SlabRgba runs = exact_index_slab(tf, u_f, u_b, length);
        const SlabRgba bins = integrate_slab(tf, u_f, u_b, length, piece, SlabPieces::Bins);
        ASSERT_NEAR(runs.r, bins.r, 1e-10) << u_f << " " << u_b << " " << length;
        ASSERT_NEAR(runs.g, bins.g, 1e-10) << u_f << " " << u_b << " " << length;
        ASSERT_NEAR(runs.b, bins.b, 1e-10) << u_f << " " << u_b << " " << length;
        ASSERT_NEAR(runs.a, bins.a, 1e-10) << u_f << " " << u_b << " " << length;
      }
    }
}

// exact_index_slab finds the runs' weights four at a time: it must be
// bit for bit the slab composited piece by piece with linear_piece, on spiky
// transfer functions (split bins between plain ones, batches cut short by
// them), thin and thick pieces (mixed in one batch), both directions, spans
// from a fraction of a bin to the whole axis.
TEST(ExactSlab, BatchedWeightsAreBitForBitThePieceByPieceComposite) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  const auto piece = [](const TfSample& p, const TfSample& q, double d) { return linear_piece(p, q, d).forward; };
  int compared = 0;
  for (unsigned seed = 0; seed < 6; ++seed)
    for (double max_tau : {0.05, 2.0, 300.0}) {
      const DiscreteTf tf(test::random_spiky_tf(seed, max_tau), 256);
      for (int i = 0; i < 300; ++i) {
        const double u_f = 255 * u(rng);
        const double span = i % 3 == 0 ? 3 * u(rng) : 255 * u(rng);
        const double u_b = std::clamp(u(rng) < 0.5 ? u_f + span : u_f - span, 0.0, 255.0);
        const double length = std::pow(10.0, -2 + 2.5 * u(rng));
        const SlabRgba batched = exact_index_slab(tf, u_f, u_b, length);
        const SlabRgba one_by_one = integrate_slab(tf, u_f, u_b, length, piece, SlabPieces::Runs);
        ASSERT_EQ(batched.r, one_by_one.r) << u_f << " " << u_b << " " << length;
        ASSERT_EQ(batched.g, one_by_one.g) << u_f << " " << u_b << " " << length;
        ASSERT_EQ(batched.b, one_by_one.b) << u_f << " " << u_b << " " << length;
        ASSERT_EQ(batched.a, one_by_one.a) << u_f << " " << u_b << " " << length;
        compared += batched.a > 0;
      }
    }
  EXPECT_GT(compared, 3000);  // most slabs are not transparent
}

// for_each_slab_bin reads a table scalar short of the slab's end as its
// sample, tf[i], where it used to ask at_index(i): the two must be the same
// bits at every table scalar but the last (plain and split bins, steps on a
// table scalar, spikes inside a bin), or the slabs would change.
TEST(ExactSlab, TableScalarsAreTheirSamplesBitForBit) {
  for (unsigned seed = 0; seed < 8; ++seed)
    for (int n : {7, 64, 256}) {
      const DiscreteTf tf(test::random_spiky_tf(seed, 50.0), n);
      int split = 0;
      for (int i = 0; i + 1 < n; ++i) {
        const TfSample a = tf.at_index(i), b = tf[i];
        ASSERT_TRUE(a.r == b.r && a.g == b.g && a.b == b.b && a.tau == b.tau) << seed << " " << n << " " << i;
        split += !tf.sub_pieces(i).empty();
      }
      EXPECT_GT(split, 0) << seed << " " << n;  // split bins were among them
    }
  // A step exactly on a table scalar: the scalar holds the value after it.
  const DiscreteTf step(TransferFunction({{0, 0, 0, 0, 0}, {2, 0, 0, 0, 0}, {2, 1, 1, 1, 5}, {4, 1, 1, 1, 5}}), 5);
  EXPECT_EQ(step[2].tau, 5);
  EXPECT_EQ(step.at_index(2).tau, step[2].tau);
}

// Thick pieces (issue 46: extinctions of 1e9 built tables slowly): the
// graded panels and, where the piece is dense from its start, the closed
// form, against J integrated apart here (composite Simpson on 20 000 panels
// up to depth 60, where the rest is below e^-60).
TEST(ThickPieceWeights, MatchAnIntegralTakenApart) {
  auto J = [](double A, double B) {
    const double k = 0.5 * (B - A);
    double x_end = 1;
    if (A + k > 60) x_end = 2 * 60 / (A + std::sqrt(A * A + 4 * k * 60));
    const int n = 20000;
    const double h = x_end / n;
    double s = 0;
    for (int i = 0; i <= n; ++i) {
      const double x = i * h, f = std::exp(-x * (A + k * x));
      s += (i == 0 || i == n ? 1 : i % 2 ? 4 : 2) * f;
    }
    return s * h / 3;
  };
  for (const auto& ab : {std::array{2.0, 3.0}, {0.0, 40.0}, {60.0, 61.0}, {1e3, 1.2e3}, {1e3, 5e3}, {1e6, 1e6 + 1},
                         {1e9, 2e9}, {1e9, 1e9}, {4e3, 0.0}, {0.0, 4e3}, {1e12, 3e12}}) {
    const PieceWeights w = thick_piece_weights(ab[0], ab[1]);
    const double E = std::exp(-0.5 * (ab[0] + ab[1]));
    const double jf = J(ab[0], ab[1]), jb = J(ab[1], ab[0]);
    EXPECT_NEAR(w.fp, 1 - jf, 1e-12 * std::max(1.0, jf)) << ab[0] << " " << ab[1];
    EXPECT_NEAR(w.fq, jf - E, 1e-11 * jf + 1e-15) << ab[0] << " " << ab[1];
    EXPECT_NEAR(w.bq, 1 - jb, 1e-12 * std::max(1.0, jb)) << ab[0] << " " << ab[1];
    EXPECT_NEAR(w.bp, jb - E, 1e-11 * jb + 1e-15) << ab[0] << " " << ab[1];
  }
}

}  // namespace
}  // namespace vri
