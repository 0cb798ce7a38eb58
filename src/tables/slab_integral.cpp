#include "vri/tables/slab_integral.hpp"

#include <algorithm>
#include <cmath>

#include "vri/tables/piece_weights.hpp"

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

PiecePair linear_piece(const TfSample& p, const TfSample& q, double d) {
  const PieceWeights w = piece_weights(p.tau * d, q.tau * d);
  return {{p.r * w.fp + q.r * w.fq, p.g * w.fp + q.g * w.fq, p.b * w.fp + q.b * w.fq, w.alpha},
          {q.r * w.bq + p.r * w.bp, q.g * w.bq + p.g * w.bp, q.b * w.bq + p.b * w.bp, w.alpha}};
}

SlabRgba exact_slab(const DiscreteTf& tf, double s_f, double s_b, double length) {
  return exact_index_slab(tf, tf.axis().index(s_f), tf.axis().index(s_b), length);
}

SlabRgba exact_index_slab(const DiscreteTf& tf, double u_f, double u_b, double length) {
  return integrate_slab(tf, u_f, u_b, length,
                        [](const TfSample& p, const TfSample& q, double d) { return linear_piece(p, q, d).forward; });
}

}  // namespace vri
