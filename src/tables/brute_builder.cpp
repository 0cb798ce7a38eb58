#include "tables/brute_builder.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "tables/slab_integral.hpp"

namespace vri {

namespace {

// 8-point Gauss-Legendre on [-1, 1], nodes +-kX[g], weights kW[g].
constexpr double kX[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr double kW[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

}  // namespace

SlabRgba quadrature_piece(const TfSample& p, const TfSample& q, double d) {
  const double A = p.tau * d, B = q.tau * d, k = 0.5 * (B - A);
  if (A == 0 && B == 0) return {};
  // In x = t/d: tau d = A + 2k x, depth D(x) = A x + k x^2, c linear;
  // C = int_0^1 c(x) (A + 2k x) exp(-D(x)) dx.
  const double x_max = reach_of_depth(A, k, 50);
  const int panels = panel_count(A, k, x_max, 0.5);
  const double w = x_max / panels;
  double C[3] = {0, 0, 0};
  for (int i = 0; i < panels; ++i) {
    const double mid = (i + 0.5) * w;
    for (int g = 0; g < 8; ++g) {
      const double x = mid + (g < 4 ? -kX[g] : kX[g - 4]) * 0.5 * w;
      const double f = kW[g % 4] * (A + 2 * k * x) * std::exp(-x * (A + k * x));
      C[0] += f * ((1 - x) * p.r + x * q.r);
      C[1] += f * ((1 - x) * p.g + x * q.g);
      C[2] += f * ((1 - x) * p.b + x * q.b);
    }
  }
  const double h = 0.5 * w;
  return {C[0] * h, C[1] * h, C[2] * h, -std::expm1(-(A + B) / 2)};
}

double BruteBuilder::length_table_work(const DiscreteTf& tf, int lengths, double max_length) const {
  const int n = tf.size();
  // Prefix sums over the bins of the largest tau in each and of its pieces.
  std::vector<double> tau_sum(n, 0.0), pieces_sum(n, 0.0);
  for (int k = 0; k + 1 < n; ++k) {
    double tau = std::max(tf[k].tau, tf[k + 1].tau);
    for (const SubPiece& s : tf.sub_pieces(k)) tau = std::max({tau, s.p.tau, s.q.tau});
    const double pieces = std::max<double>(1, double(tf.sub_pieces(k).size()));
    tau_sum[k + 1] = tau_sum[k] + (std::isfinite(tau) ? tau : 1e300);
    pieces_sum[k + 1] = pieces_sum[k] + pieces;
  }
  // Entry (f, b) of the slice of length l = m c crosses g = |b - f| bins in p
  // pieces of total depth at most m c T / g (T: the bins' tau); piece i takes
  // min(4 d_i + 1, 201) panels, so the entry at most min(4 D + p, 201 p);
  // summed over m = 1 .. M - 1 in closed form. The diagonal is closed form.
  const double M1 = lengths - 1, c = max_length / M1;
  double work = 0;
  for (int f = 0; f < n; ++f)
    for (int b = 0; b < n; ++b) {
      if (f == b) continue;
      const int lo = std::min(f, b), hi = std::max(f, b);
      const double p = pieces_sum[hi] - pieces_sum[lo];
      const double depth_per_m = c * (tau_sum[hi] - tau_sum[lo]) / (hi - lo);  // D at m = 1
      const double k = depth_per_m > 0 ? std::min(M1, std::floor(50 * p / depth_per_m)) : M1;
      work += p * k + 2 * depth_per_m * k * (k + 1) + (M1 - k) * 201 * p;
    }
  return 8 * work + M1 * n;
}

PreintegrationTable BruteBuilder::build(const DiscreteTf& tf, double length) const {
  check_slab_length(length);
  PreintegrationTable table(tf.axis(), length);
  const int n = tf.size();
  tbb::parallel_for(0, n, [&](int f) {
    for (int b = 0; b < n; ++b) store(table.entry(f, b), integrate_slab(tf, f, b, length, quadrature_piece));
  });
  return table;
}

}  // namespace vri
