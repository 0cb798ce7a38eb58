#include "tables/weighted_tables.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "incremental_diagonals.hpp"
#include "tables/brute_builder.hpp"
#include "tables/table_builder.hpp"

namespace vri {

namespace {

void store_packed(WeightedTables& t, int f, int b, const SlabWeights& w) {
  std::copy_n(to_entry(w.front).data(), 4, t.front.entry(f, b));
  std::copy_n(to_entry(w.back).data(), 4, t.back.entry(f, b));
}

// beta(A) = int_0^1 u A e^{-A u} du: the series sum_n (-1)^n A^(n+1) / (n! (n+2))
// while A is small (the closed form cancels there), else the closed form.
double beta(double A) {
  if (A < 0.5) {
    double term = A, sum = 0;  // term = (-1)^n A^(n+1) / n!
    for (int n = 0; n < 24; ++n, term *= -A / n) sum += term / (n + 2);
    return sum;
  }
  return (-std::expm1(-A) - A * std::exp(-A)) / A;
}

// The unweighted slab (C_1, alpha) split by the back-weighted (D, S).
SlabWeights split(const SlabRgba& c1, const SlabRgba& back) {
  return {{c1.r - back.r, c1.g - back.g, c1.b - back.b, c1.a}, back};
}

struct Scratch {
  DiagonalSweep sweep;
  // One diagonal of C_1, of the ramped colours and of the ramped white.
  std::vector<SlabRgba> c1_up, c1_lo, g_up, g_lo, gs_up, gs_lo;
  explicit Scratch(int n) : sweep(n), c1_up(n), c1_lo(n), g_up(n), g_lo(n), gs_up(n), gs_lo(n) {}
};

// Diagonal m of both tables.
// The ramped colours at the table scalars and at the split bins' sub-piece
// ends (the weight applied where the colour is given, linear between).
struct Ramped {
  std::vector<TfSample> at;
  std::vector<SubPiece> subs;
};

void build_diagonal(const DiscreteTf& tf, const Pieces& pieces, const Ramped& ramped, const Ramped& white_ramped,
                    double length, int m, Scratch& s, WeightedTables& t) {
  const int n = tf.size();
  s.sweep.weights(pieces, length, m);
  s.sweep.composite(&tf[0], tf.all_sub_pieces().data(), m, s.c1_up.data(), s.c1_lo.data());
  s.sweep.composite(ramped.at.data(), ramped.subs.data(), m, s.g_up.data(), s.g_lo.data());
  s.sweep.composite(white_ramped.at.data(), white_ramped.subs.data(), m, s.gs_up.data(), s.gs_lo.data());
  // C_W = (C_G - f C_1) / (j - f) for front index f, back index j: above
  // the diagonal f = i, j - f = m; below it f = i + m, j - f = -m.
  const auto back = [m](const SlabRgba& g, double gs, const SlabRgba& c1, double f, double sign) {
    const double w = sign / m;
    return SlabRgba{(g.r - f * c1.r) * w, (g.g - f * c1.g) * w, (g.b - f * c1.b) * w, (gs - f * c1.a) * w};
  };
  for (int i = 0; i + m < n; ++i) {
    store_packed(t, i, i + m, split(s.c1_up[i], back(s.g_up[i], s.gs_up[i].r, s.c1_up[i], i, 1)));
    store_packed(t, i + m, i, split(s.c1_lo[i], back(s.g_lo[i], s.gs_lo[i].r, s.c1_lo[i], i + m, -1)));
  }
}

}  // namespace

WeightedTables build_weighted_tables(const DiscreteTf& tf, double length) {
  check_slab_length(length);
  const int n = tf.size();
  WeightedTables t{PreintegrationTable(tf.axis(), length), PreintegrationTable(tf.axis(), length)};
  // The globally ramped colours (§4.3, Fig. 6b): colour times index, and white times index.
  const auto ramp = [](const TfSample& v, double u) { return TfSample{v.r * u, v.g * u, v.b * u, v.tau}; };
  const auto white = [](const TfSample& v, double u) { return TfSample{u, 0, 0, v.tau}; };
  Ramped ramped, white_ramped;
  for (int k = 0; k < n; ++k) {
    ramped.at.push_back(ramp(tf[k], k));
    white_ramped.at.push_back(white(tf[k], k));
  }
  for (const SubPiece& p : tf.all_sub_pieces()) {
    ramped.subs.push_back({p.u0, p.u1, ramp(p.p, p.u0), ramp(p.q, p.u1)});
    white_ramped.subs.push_back({p.u0, p.u1, white(p.p, p.u0), white(p.q, p.u1)});
  }
  tbb::parallel_for(0, n, [&](int i) {
    const double A = tf[i].tau * length, a = -std::expm1(-A), b = beta(A);
    const TfSample& c = tf[i];
    store_packed(t, i, i, split({c.r * a, c.g * a, c.b * a, a}, {c.r * b, c.g * b, c.b * b, b}));
  });
  const Pieces pieces(tf);
  // As IncrementalBuilder: per-thread scratch, fully overwritten before it is read.
  tbb::enumerable_thread_specific<Scratch> scratch([n] { return Scratch(n); });
  tbb::parallel_for(1, n, [&](int m) { build_diagonal(tf, pieces, ramped, white_ramped, length, m, scratch.local(), t); });
  return t;
}

WeightedTables brute_weighted_tables(const DiscreteTf& tf, double length) {
  check_slab_length(length);
  WeightedTables t{PreintegrationTable(tf.axis(), length), PreintegrationTable(tf.axis(), length)};
  tbb::parallel_for(0, tf.size(), [&](int f) {
    for (int b = 0; b < tf.size(); ++b) store_packed(t, f, b, pack(weighted_slab(tf, f, b, length, quadrature_piece)));
  });
  return t;
}

WeightedLengthTables build_weighted_length_tables(const DiscreteTf& tf, int lengths, double max_length) {
  check_length_tables(lengths, max_length, tf.size(), 2);
  std::vector<WeightedTables> slices = build_length_slices<WeightedTables>(
      lengths, max_length, [&](double l) { return build_weighted_tables(tf, l); },
      [&] { return WeightedTables{PreintegrationTable(tf.axis(), 0), PreintegrationTable(tf.axis(), 0)}; });
  std::vector<PreintegrationTable> front, back;
  for (WeightedTables& w : slices) {
    front.push_back(std::move(w.front));
    back.push_back(std::move(w.back));
  }
  return {LengthTable(std::move(front), max_length), LengthTable(std::move(back), max_length)};
}

SlabWeights exact_weighted_slab(const DiscreteTf& tf, double s_f, double s_b, double length) {
  return pack(weighted_slab(tf, tf.axis().index(s_f), tf.axis().index(s_b), length,
                            [](const TfSample& p, const TfSample& q, double d) { return linear_piece(p, q, d).forward; }));
}

}  // namespace vri
