#include "tables/slab_integral.hpp"

#include <algorithm>
#include <cmath>

#include "tables/piece_weights.hpp"

namespace vri {

double reach_of_depth(double a, double k, double depth) {
  if (a + k <= depth) return 1;
  // The root of a x + k x^2 = depth in (0, 1), in the form without cancellation.
  return 2 * depth / (a + std::sqrt(a * a + 4 * k * depth));
}

int panel_count(double a, double k, double x_max, double per_panel) {
  constexpr double kMaxPanels = 1 << 16;
  const double panels = std::ceil(std::max(a, a + 2 * k * x_max) * x_max / per_panel);
  // Written so that NaN saturates too.
  return panels >= 1 ? static_cast<int>(std::min(panels, kMaxPanels)) : 1;
}

namespace {

// A piece's colour with c_p, c_q weighted by wp, wq (piece_weights.hpp).
SlabRgba weighted(const TfSample& p, const TfSample& q, double wp, double wq, double alpha) {
  return {p.r * wp + q.r * wq, p.g * wp + q.g * wq, p.b * wp + q.b * wq, alpha};
}

// Up to four plain pieces waiting for their weights, composited in order by flush().
class PieceBatch {
 public:
  explicit PieceBatch(SlabRgba& acc) : acc_(acc) {}
  void add(const TfSample& p, const TfSample& q, double d) {
    p_[n_] = p, q_[n_] = q, a_[n_] = p.tau * d, b_[n_] = q.tau * d;
    if (++n_ == 4) flush();
  }
  void flush() {
    bool thin = n_ == 4;
    for (int k = 0; k < n_; ++k) thin = thin && std::max(a_[k], b_[k]) <= piece_series::kThin;
    if (thin) {
      using V4 = double __attribute__((vector_size(32)));
      const auto w = thin_piece_weights(V4{a_[0], a_[1], a_[2], a_[3]}, V4{b_[0], b_[1], b_[2], b_[3]});
      for (int k = 0; k < 4; ++k) acc_ = over(acc_, weighted(p_[k], q_[k], w.fp[k], w.fq[k], w.alpha[k]));
    } else {
      for (int k = 0; k < n_; ++k) {
        const PieceWeights w = piece_weights(a_[k], b_[k]);
        acc_ = over(acc_, weighted(p_[k], q_[k], w.fp, w.fq, w.alpha));
      }
    }
    n_ = 0;
  }

 private:
  SlabRgba& acc_;
  TfSample p_[4], q_[4];
  double a_[4], b_[4];  // optical thickness at each end, tau d
  int n_ = 0;
};

}  // namespace

PiecePair linear_piece(const TfSample& p, const TfSample& q, double d) {
  const PieceWeights w = piece_weights(p.tau * d, q.tau * d);
  return {weighted(p, q, w.fp, w.fq, w.alpha), weighted(q, p, w.bq, w.bp, w.alpha)};
}

SlabRgba exact_slab(const DiscreteTf& tf, double s_f, double s_b, double length) {
  return exact_index_slab(tf, tf.axis().index(s_f), tf.axis().index(s_b), length);
}

SlabRgba exact_index_slab(const DiscreteTf& tf, double u_f, double u_b, double length) {
  if (u_f == u_b) return homogeneous_slab(tf.at_index(u_f), length);
  const auto piece = [](const TfSample& p, const TfSample& q, double d) { return linear_piece(p, q, d).forward; };
  SlabRgba acc;
  PieceBatch batch(acc);
  for_each_slab_bin(
      tf, u_f, u_b, length, [&](const TfSample& front, const TfSample& back, double d) { batch.add(front, back, d); },
      [&](std::span<const SubPiece> subs, double lo, double hi, double dir, double per_index) {
        batch.flush();  // the pieces before it first
        acc = over(acc, integrate_sub_pieces(subs, lo, hi, dir, per_index, piece));
      },
      SlabPieces::Runs);
  batch.flush();
  return acc;
}

}  // namespace vri
