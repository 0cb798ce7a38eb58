#include "tables/engel_builder.hpp"

#include <tbb/parallel_for.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace vri {

PreintegrationTable EngelBuilder::build(const DiscreteTf& tf, double length) const {
  check_slab_length(length);
  PreintegrationTable table(tf.axis(), length);
  const int n = tf.size();
  // Prefix integrals over the index u (one unit per bin): depth[k] of tau,
  // emit[k][c] of tau * c; per linear piece (a plain bin, or each sub-piece of
  // a split one) tau is linear and tau * c quadratic, so the trapezoid and
  // Simpson rules are exact.
  std::vector<double> depth(n, 0.0);
  std::vector<std::array<double, 3>> emit(n, {0, 0, 0});
  const auto add = [](double& dep, std::array<double, 3>& em, const TfSample& p, const TfSample& q, double w) {
    dep += 0.5 * (p.tau + q.tau) * w;
    const double pm[3] = {0.5 * (p.r + q.r), 0.5 * (p.g + q.g), 0.5 * (p.b + q.b)};
    const double pc[3] = {p.r, p.g, p.b}, qc[3] = {q.r, q.g, q.b};
    const double tm = 0.5 * (p.tau + q.tau);
    for (int c = 0; c < 3; ++c) em[c] += (pc[c] * p.tau + 4 * pm[c] * tm + qc[c] * q.tau) / 6 * w;
  };
  for (int k = 0; k + 1 < n; ++k) {
    depth[k + 1] = depth[k];
    emit[k + 1] = emit[k];
    const auto subs = tf.sub_pieces(k);
    if (subs.empty()) add(depth[k + 1], emit[k + 1], tf[k], tf[k + 1], 1);
    for (const SubPiece& sp : subs) add(depth[k + 1], emit[k + 1], sp.p, sp.q, sp.u1 - sp.u0);
  }
  tbb::parallel_for(0, n, [&](int f) {
    for (int b = 0; b < n; ++b) {
      float* e = table.entry(f, b);
      if (f == b) {
        const TfSample& v = tf[f];
        e[0] = static_cast<float>(v.r * v.tau * length);
        e[1] = static_cast<float>(v.g * v.tau * length);
        e[2] = static_cast<float>(v.b * v.tau * length);
        e[3] = static_cast<float>(-std::expm1(-v.tau * length));
        continue;
      }
      const double d = length / std::abs(b - f);  // world length per index unit
      for (int c = 0; c < 3; ++c) e[c] = static_cast<float>(d * std::abs(emit[b][c] - emit[f][c]));
      e[3] = static_cast<float>(-std::expm1(-d * std::abs(depth[b] - depth[f])));
    }
  });
  return table;
}

}  // namespace vri
