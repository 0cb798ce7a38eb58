#include "methods/adaptive/simpson_colour_step.hpp"

#include "methods/adaptive/guaranteed_tries.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace vri {
namespace {

using simpson5::colour_step;

// The optical depths are the integrals of the quartic through the five tau
// samples: exact for a quartic tau(t), to rounding.
TEST(SimpsonColourStep, DepthsIntegrateAQuarticExactly) {
  const double a[5] = {0.3, -0.7, 1.1, 0.4, -0.2}, t0 = 0.25, h = 0.8;
  const auto tau = [&](double t) { return (((a[4] * t + a[3]) * t + a[2]) * t + a[1]) * t + a[0]; };
  const auto integral = [&](double t) {
    return ((((a[4] / 5 * t + a[3] / 4) * t + a[2] / 3) * t + a[1] / 2) * t + a[0]) * t;
  };
  TfSample f[5];
  for (int k = 0; k < 5; ++k) f[k] = {0.5, 0.5, 0.5, tau(t0 + h * k / 4)};
  const auto st = colour_step(f, h);
  EXPECT_EQ(st.depth[0], 0.0);
  for (int k = 1; k < 5; ++k) EXPECT_NEAR(st.depth[k], integral(t0 + h * k / 4) - integral(t0), 1e-15) << k;
  EXPECT_NEAR(st.attenuation, std::exp(-st.depth[4]), 1e-16);
}

// Issue 46, class 5: a sample of extinction 1e15 beside zeros made the
// quartic's depth negative between them, e^{+708} times tau infinite and the
// sums NaN (`adaptive --strategy coupled` at extinctions of 1e5 and more).
TEST(SimpsonColourStep, ADenseSampleBesideClearOnesStaysFinite) {
  for (double tau : {1e5, 1e10, 1e15, 1e300})
    for (int at = 0; at < 5; ++at) {
      TfSample f[5];
      for (int k = 0; k < 5; ++k) f[k] = {0.3, 0.6, 0.9, k == at ? tau : 0.0};
      const auto st = colour_step(f, 0.5);
      for (int c = 0; c < 4; ++c) {
        ASSERT_TRUE(std::isfinite(st.S[c]) && std::isfinite(st.D[c])) << tau << " at " << at;
        ASSERT_GE(st.D[c], 0) << tau << " at " << at;
      }
      for (int k = 0; k < 5; ++k) ASSERT_GE(st.depth[k], 0);
      ASSERT_LE(st.attenuation, 1);
    }
}

// Against the loop the method is written as (Algorithm 3's I_O, simpson5.hpp,
// at T = 1), with the C library's exp: the same sums to a few ulp, for
// random samples and steps.
TEST(SimpsonColourStep, MatchesTheScalarSums) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0, 1), opt(0, 40);
  for (int trial = 0; trial < 2000; ++trial) {
    TfSample f[5];
    for (auto& s : f) s = {unit(rng), unit(rng), unit(rng), trial % 3 ? opt(rng) : unit(rng) * 1e-3};
    const double h = 0.01 + unit(rng);
    const auto st = colour_step(f, h);
    const double W[4][5] = {{251, 646, -264, 106, -19}, {29, 124, 24, 4, -1}, {27, 102, 72, 42, -3},
                            {14, 64, 24, 64, 14}};
    const double den[4] = {720, 90, 80, 45};
    double g[4][5], err = 0;
    for (int k = 0; k < 5; ++k) {
      double depth = 0;
      if (k > 0) {
        for (int j = 0; j < 5; ++j) depth += W[k - 1][j] * f[j].tau;
        depth = std::max(depth * (h / 4 / den[k - 1]), 0.0);  // the quartic's dip below zero clamped
        ASSERT_NEAR(st.depth[k], depth, 1e-13 * (1 + std::abs(depth)));
      }
      const double w = f[k].tau * std::exp(-depth);
      g[0][k] = f[k].r * w, g[1][k] = f[k].g * w, g[2][k] = f[k].b * w, g[3][k] = w;
    }
    for (int c = 0; c < 4; ++c) {
      const double S = simpson5::whole(g[c], h), D = simpson5::halves(g[c], h);
      ASSERT_NEAR(st.S[c], S, 1e-13 * std::abs(S) + 1e-300) << trial << " " << c;
      ASSERT_NEAR(st.D[c], D, 1e-13 * std::abs(D) + 1e-300) << trial << " " << c;
      err = std::max(err, simpson5::error(D, S));
    }
    ASSERT_NEAR(st.err, err, 1e-12 * err + 1e-15 * std::abs(st.D[3]));
  }
}

// add_step at T: the opacity T (1 - e^{-depth}) exactly, and the colour the
// Boole estimate of the try at T = 1 rescaled to it.
TEST(SimpsonColourStep, AddStepScalesByTheTransmittance) {
  const TfSample f[5] = {{0.2, 0.4, 0.6, 0.5}, {0.3, 0.4, 0.5, 0.8}, {0.4, 0.4, 0.4, 1.2}, {0.5, 0.4, 0.3, 0.9},
                         {0.6, 0.4, 0.2, 0.4}};
  const double h = 0.7, T = 0.35;
  const auto st = colour_step(f, h);
  double C[3] = {0, 0, 0};
  const double T_after = simpson5::add_step(st, T, C);
  EXPECT_DOUBLE_EQ(T_after, T * std::exp(-st.depth[4]));
  const double boole_alpha = simpson5::corrected(st.D[3], st.S[3]);
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(C[c], (T - T_after) * simpson5::corrected(st.D[c], st.S[c]) / boole_alpha, 1e-15);
  // A greenish mean: the chromaticities' weighted mean stays between the samples'.
  EXPECT_NEAR(C[1] / (T - T_after), 0.4, 1e-12);
}

// The four-lane first tries of `guaranteed` give, lane by lane, the bytes of
// colour_step on the samples seg.at(s(u + h k / 4)): the integrator may add a
// piece from either.
TEST(PieceTries, LanesGiveTheBytesOfColourStep) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0, 1), coef(-40, 40);
  for (int trial = 0; trial < 500; ++trial) {
    simpson5::PieceTries tries;
    Cubic s[4];
    TfSegment seg[4];
    for (int l = 0; l < 4; ++l) {
      s[l] = {{100 * unit(rng), coef(rng), coef(rng) / 4, coef(rng) / 16}};
      seg[l].s_ref = 100 * unit(rng);
      seg[l].ref = {unit(rng), unit(rng), unit(rng), 2 * unit(rng)};
      seg[l].slope = {unit(rng) / 50, -unit(rng) / 50, unit(rng) / 50, unit(rng) / 20};
      tries.set(l, s[l], seg[l], unit(rng), 0.01 + unit(rng));
    }
    tries.run();
    for (int l = 0; l < 4; ++l) {
      TfSample f[5];
      for (int k = 0; k < 5; ++k) f[k] = seg[l].at(s[l](tries.u[l] + tries.h[l] * (0.25 * k)));
      const auto st = colour_step(f, tries.h[l]);
      ASSERT_EQ(tries.err[l], st.err) << trial << " " << l;
      ASSERT_EQ(tries.attenuation[l], st.attenuation);
      ASSERT_EQ(tries.depth_err[l], simpson5::error(simpson5::halves(st.tau, tries.h[l]), simpson5::whole(st.tau, tries.h[l])));
      for (int c = 0; c < 4; ++c) {
        ASSERT_EQ(tries.channel_err[c][l], simpson5::error(st.D[c], st.S[c]));
        ASSERT_EQ(tries.boole[c][l], simpson5::corrected(st.D[c], st.S[c]));
      }
    }
  }
}

}  // namespace
}  // namespace vri
