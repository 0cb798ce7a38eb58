#include "vri/integrators/piece_integrator.hpp"

#include <algorithm>
#include <cmath>

#include "cubic.hpp"
#include "gauss_kronrod.hpp"

namespace vri {

namespace {

// One piece of a cell on which the transfer function is a single linear
// segment: tau(t) is then the cubic `tau`, and its integral the quartic P.
struct Piece {
  const Cubic& s;
  const TfSegment& seg;
  Cubic tau;
  Piece(const Cubic& s_, const TfSegment& seg_) : s(s_), seg(seg_) {
    tau.c[0] = seg.ref.tau + seg.slope.tau * (s.c[0] - seg.s_ref);
    for (int k = 1; k < 4; ++k) tau.c[k] = seg.slope.tau * s.c[k];
  }
  double P(double t) const {
    return (((0.25 * tau.c[3] * t + tau.c[2] / 3) * t + 0.5 * tau.c[1]) * t + tau.c[0]) * t;
  }
};

}  // namespace

PieceIntegrator::PieceIntegrator(const TransferFunction& tf) : tf_(tf) {
  opaque_prefix_.assign(tf.segments().size() + 1, 0);
  for (std::size_t i = 0; i < tf.segments().size(); ++i)
    opaque_prefix_[i + 1] = opaque_prefix_[i] + (tf.segments()[i].transparent() ? 0 : 1);
}

void PieceIntegrator::integrate_linear(double s_front, double s_back, double len,
                                       double error_per_length, Accumulator& acc) const {
  Cubic s;
  s.c[0] = s_front;
  s.c[1] = len > 0 ? (s_back - s_front) / len : 0;
  integrate(s, len, error_per_length, acc);
}

void PieceIntegrator::integrate(const Cubic& s, double len, double error_per_length,
                                Accumulator& acc) const {
  if (!(len > 0)) return;

  // Knots: the ends and the critical points, between which s is monotone.
  double knots[4], vals[4];
  double crit[2];
  const int nc = s.critical_points(len, crit);
  int nk = 0;
  knots[nk++] = 0;
  for (int i = 0; i < nc; ++i) knots[nk++] = crit[i];
  knots[nk++] = len;
  double smin = INFINITY, smax = -INFINITY;
  for (int i = 0; i < nk; ++i) {
    vals[i] = s(knots[i]);
    smin = std::min(smin, vals[i]);
    smax = std::max(smax, vals[i]);
  }
  // Empty space: every transfer-function segment the piece's values touch is transparent.
  const int i0 = tf_.segment_index(smin), i1 = tf_.segment_index(smax);
  if (opaque_prefix_[i1 + 1] == opaque_prefix_[i0]) return;

  const auto& bp = tf_.breakpoints();
  auto integrate_piece = [&](double x, double y) {
    if (!(y > x)) return;
    const TfSegment& seg = tf_.segments()[tf_.segment_index(s(0.5 * (x + y)))];
    if (seg.transparent()) return;
    const Piece pc(s, seg);
    const double px = pc.P(x);
    auto f = [&](double t, double (&out)[3]) {
      const double ds = s(t) - seg.s_ref;
      const double w = pc.tau(t) * std::exp(px - pc.P(t));
      out[0] = (seg.ref.r + seg.slope.r * ds) * w;
      out[1] = (seg.ref.g + seg.slope.g * ds) * w;
      out[2] = (seg.ref.b + seg.slope.b * ds) * w;
    };
    // Adaptive Gauss-Kronrod, iterative, depth first. The error allowed on the
    // unattenuated integral is the piece's share of the budget divided by T.
    const double T_in = acc.T;
    const double density = error_per_length / T_in;
    struct Item {
      double a, b;
      int depth;
    };
    Item stack[64];
    int top = 0;
    stack[top++] = {x, y, 0};
    double sum[3] = {0, 0, 0};
    while (top > 0) {
      const Item it = stack[--top];
      double k[3];
      const double err = gk15::apply<3>(f, it.a, it.b, k);
      if (err <= density * (it.b - it.a) || it.depth >= 40) {
        for (int c = 0; c < 3; ++c) sum[c] += k[c];
      } else {
        const double m = 0.5 * (it.a + it.b);
        stack[top++] = {m, it.b, it.depth + 1};  // right half popped second
        stack[top++] = {it.a, m, it.depth + 1};
      }
    }
    for (int c = 0; c < 3; ++c) acc.C[c] += T_in * sum[c];
    acc.T = T_in * std::exp(px - pc.P(y));
  };

  // Split each monotone run where s crosses a control point, front to back.
  for (int m = 0; m + 1 < nk; ++m) {
    const double ka = knots[m], kb = knots[m + 1], fa = vals[m], fb = vals[m + 1];
    double prev = ka;
    auto cut_at = [&](double value) {
      const double r = std::clamp(s.solve_monotone(value, ka, kb), prev, kb);
      integrate_piece(prev, r);
      prev = r;
    };
    if (fa < fb) {
      for (auto it = std::upper_bound(bp.begin(), bp.end(), fa); it != bp.end() && *it < fb; ++it)
        cut_at(*it);
    } else if (fa > fb) {
      for (auto it = std::lower_bound(bp.begin(), bp.end(), fa); it != bp.begin() && *(it - 1) > fb;)
        cut_at(*--it);
    }
    integrate_piece(prev, kb);
  }
}

}  // namespace vri
