#include "vri/tables/incremental_builder.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <vector>

#include "incremental_diagonals.hpp"
#include "vri/tables/slab_integral.hpp"

namespace vri {

namespace {

using Entry = std::array<float, 4>;
using V2 = double __attribute__((vector_size(16)));

Entry to_entry(const SlabRgba& v) {
  return {static_cast<float>(v.r), static_cast<float>(v.g), static_cast<float>(v.b), static_cast<float>(v.a)};
}

// Diagonals are built kGroup at a time and stored row by row: entries
// (i, i+m0 .. i+m0+kGroup-1) are adjacent in memory, one diagonal is not.
constexpr int kGroup = 32;

struct Scratch {
  DiagonalSweep sweep;
  std::vector<Entry> upper, lower;  // kGroup diagonals, n entries each
  explicit Scratch(int n) : sweep(n), upper(std::size_t(kGroup) * n), lower(std::size_t(kGroup) * n) {}
};

void build_group(const DiscreteTf& tf, const Pieces& pieces, double length, int m0, Scratch& s,
                 PreintegrationTable& table) {
  const int n = tf.size(), m1 = std::min(m0 + kGroup, n);
  const auto at = [n](int m_offset, int i) { return std::size_t(m_offset) * n + i; };
  for (int m = m0; m < m1; ++m) {
    s.sweep.weights(pieces, length, m);
    Entry* upper = &s.upper[at(m - m0, 0)];
    Entry* lower = &s.lower[at(m - m0, 0)];
    s.sweep.composite(&tf[0], m, [&](int i, const SlabRgba& u, const SlabRgba& l) {
      upper[i] = to_entry(u);
      lower[i] = to_entry(l);
    });
  }
  for (int r = 0; r < n; ++r)
    for (int m = m0; m < m1; ++m) {
      if (r + m < n) std::copy_n(s.upper[at(m - m0, r)].data(), 4, table.entry(r, r + m));
      if (r - m >= 0) std::copy_n(s.lower[at(m - m0, r - m)].data(), 4, table.entry(r, r - m));
    }
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
