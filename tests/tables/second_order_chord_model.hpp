#pragma once
// What the `fast` second-order builder computes (second_order_fast.hpp),
// written independently in double for its tests: every chord of the parabola
// is a bilinear lookup of first-order tables of length L/K at its two ends
// (the unweighted table from the incremental builder, the weighted ones from
// build_weighted_tables), composited front to back; Lagrange weights are
// linear across a chord.
#include <algorithm>

#include "tables/incremental_builder.hpp"
#include "tables/second_order_weighted.hpp"
#include "tables/weighted_tables.hpp"

namespace vri::test {

class ChordModel {
 public:
  ChordModel(const DiscreteTf& tf, double length, int iterations)
      : tf_(tf),
        k_(iterations),
        full_(IncrementalBuilder().build(tf, length / iterations)),
        weighted_(build_weighted_tables(tf, length / iterations)) {}

  // Entry (f, m, b) at table indices; weights of it as second_order_weighted_entry.
  SecondOrderWeights entry(int f, int m, int b) const {
    const auto P = [&](int j) {  // the parabola in Lagrange form at t = j / K, clamped
      const double t = double(j) / k_;
      const double u = f * lagrange_front(t) + m * lagrange_middle(t) + b * lagrange_back(t);
      return std::clamp(u, 0.0, tf_.size() - 1.0);
    };
    const auto lookup = [&](const PreintegrationTable& t, double ua, double ub) {
      const ScalarAxis& ax = tf_.axis();
      const auto scalar = [&](double u) { return ax.s_lo + u * (ax.s_hi - ax.s_lo) / (ax.n - 1); };
      const Rgba v = t.lookup(scalar(ua), scalar(ub));
      return SlabRgba{v[0], v[1], v[2], v[3]};
    };
    SecondOrderWeights out;
    double T = 1;
    for (int k = 0; k < k_; ++k) {
      const double ua = P(k), ub = P(k + 1), t0 = double(k) / k_, t1 = double(k + 1) / k_;
      const SlabRgba chord = lookup(full_, ua, ub);
      SlabRgba front = lookup(weighted_.front, ua, ub), back = lookup(weighted_.back, ua, ub);
      front.a = chord.a - back.a;  // unpacked: S_front = alpha - S_back
      const auto add = [&](SlabRgba& to, double (*L)(double)) {
        const double a = T * L(t0), c = T * L(t1);
        to.r += a * front.r + c * back.r, to.g += a * front.g + c * back.g;
        to.b += a * front.b + c * back.b, to.a += a * front.a + c * back.a;
      };
      add(out.front, lagrange_front);
      add(out.middle, lagrange_middle);
      add(out.back, lagrange_back);
      out.full = over(out.full, chord);
      T *= 1 - chord.a;
    }
    return out;
  }

 private:
  const DiscreteTf& tf_;
  int k_;
  PreintegrationTable full_;
  WeightedTables weighted_;
};

}  // namespace vri::test
