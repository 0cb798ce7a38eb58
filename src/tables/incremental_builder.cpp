#include "vri/tables/incremental_builder.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

#include "incremental_diagonals.hpp"
#include "vri/tables/slab_integral.hpp"

namespace vri {

namespace {

using V2 = double __attribute__((vector_size(16)));

struct Scratch {
  DiagonalSweep sweep;
  GroupBuffer buffer;
  explicit Scratch(int n) : sweep(n), buffer(n) {}
};

void build_group(const DiscreteTf& tf, const Pieces& pieces, double length, int m0, Scratch& s,
                 PreintegrationTable& table) {
  const int n = tf.size(), m1 = std::min(m0 + kGroup, n);
  for (int m = m0; m < m1; ++m) {
    s.sweep.weights(pieces, length, m);
    Entry* upper = s.buffer.upper_of(n, m - m0);
    Entry* lower = s.buffer.lower_of(n, m - m0);
    s.sweep.composite(&tf[0], m, [&](int i, const SlabRgba& u, const SlabRgba& l) {
      upper[i] = to_entry(u);
      lower[i] = to_entry(l);
    });
  }
  s.buffer.store(m0, m1, table);
}

}  // namespace

DiagonalSweep::DiagonalSweep(int n)
    : fp_(n - 1), fq_(n - 1), bq_(n - 1), bp_(n - 1), alpha_(n - 1),
      head_f_(n - 1), tail_f_(n - 1), head_b_(n - 1), tail_b_(n - 1) {}

void DiagonalSweep::weights(const Pieces& pieces, double length, int m) {
  const int count = pieces.size() - 1;
  const double d = length / m;
  // The series for every piece (a branch-free loop), then the thick ones again.
  const auto set = [this](int k, const PieceWeights& w) {
    fp_[k] = w.fp, fq_[k] = w.fq, bq_[k] = w.bq, bp_[k] = w.bp, alpha_[k] = w.alpha;
  };
  const double* tau = pieces.tau.data();
  const auto thin = [d](double t) { return std::min(t * d, piece_series::kThin); };
  int k = 0;
  for (; k + 1 < count; k += 2) {  // two pieces per SSE2 register
    const auto w = thin_piece_weights(V2{thin(tau[k]), thin(tau[k + 1])}, V2{thin(tau[k + 1]), thin(tau[k + 2])});
    for (int lane = 0; lane < 2; ++lane) set(k + lane, {w.fp[lane], w.fq[lane], w.bq[lane], w.bp[lane], w.alpha[lane]});
  }
  if (k < count) set(k, thin_piece_weights(thin(tau[k]), thin(tau[k + 1])));
  for (int k : pieces.by_thickness) {
    if (pieces.thickest(k) * d <= piece_series::kThin) break;
    set(k, thick_piece_weights(tau[k] * d, tau[k + 1] * d));
  }
}

PreintegrationTable IncrementalBuilder::build(const DiscreteTf& tf, double length) const {
  check_slab_length(length);
  PreintegrationTable table(tf.axis(), length);
  const int n = tf.size();
  for (int i = 0; i < n; ++i) std::copy_n(to_entry(homogeneous_slab(tf[i], length)).data(), 4, table.entry(i, i));
  const Pieces pieces(tf);
  // Scratch is reused by whichever thread runs a group and fully overwritten
  // before it is read, so the bytes do not depend on the thread count.
  tbb::enumerable_thread_specific<Scratch> scratch([n] { return Scratch(n); });
  const int groups = (n - 1 + kGroup - 1) / kGroup;
  tbb::parallel_for(0, groups, [&](int g) { build_group(tf, pieces, length, 1 + g * kGroup, scratch.local(), table); });
  return table;
}

}  // namespace vri
