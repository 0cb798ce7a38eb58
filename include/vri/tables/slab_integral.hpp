#pragma once
// The exact integral of SPEC §4 over one slab of a discretised transfer
// function (DiscreteTf), with the scalar linear along the slab. This is the
// definition every pre-integration table entry is held to:
//
//   entry(s_f, s_b, l) = (C, alpha) of a slab of length l whose scalar runs
//   linearly from s_f to s_b, with r, g, b, tau linear between table scalars.
//
// The slab crosses the table scalars between s_f and s_b; between two of them
// (a "piece") tau and c are linear in the distance t along the ray, and the
// pieces composite front to back.
#include <cmath>

#include "vri/tables/discrete_tf.hpp"
#include "vri/tables/slab_rgba.hpp"

namespace vri {

// A homogeneous slab (s_f = s_b) in closed form: alpha = 1 - exp(-tau l), C = c alpha.
inline SlabRgba homogeneous_slab(const TfSample& v, double length) {
  const double a = -std::expm1(-v.tau * length);
  return {v.r * a, v.g * a, v.b * a, a};
}

// One piece of length d over which (r, g, b, tau) run linearly from `p` to
// `q`, integrated in both directions: forward (p at the front) and backward
// (q at the front), by piece_weights.hpp.
struct PiecePair {
  SlabRgba forward, backward;
};
PiecePair linear_piece(const TfSample& p, const TfSample& q, double d);

// Where the optical depth a x + k x^2 (a >= 0, a + 2k >= 0) reaches `depth`
// in [0, 1]; 1 if it does not. Quadratures stop there.
double reach_of_depth(double a, double k, double depth);

// Panels for a quadrature of exp(-(a x + k x^2)) over [0, x_max] such that no
// panel is optically deeper than `per_panel`: the extinction's maximum on
// [0, x_max] (at an end, since it is linear) times x_max. With x_max =
// reach_of_depth(a, k, D) that is at most 2 D / per_panel whatever tau is
// (an earlier max(a, a + 2k) x_max grew like sqrt(tau) and overflowed int near
// tau = 1e35); saturated in double before the cast all the same.
int panel_count(double a, double k, double x_max, double per_panel);

// The slab from continuous index u_f to u_b (DiscreteTf::at_index) of length
// l, composited piece by piece with `piece(front, back, d)` -> SlabRgba.
// u_f == u_b is the homogeneous slab. O(|u_b - u_f| + 1).
template <class PieceFn>
SlabRgba integrate_slab(const DiscreteTf& tf, double u_f, double u_b, double length, PieceFn piece) {
  if (u_f == u_b) return homogeneous_slab(tf.at_index(u_f), length);
  const double dir = u_b > u_f ? 1 : -1;
  const double per_index = length / std::abs(u_b - u_f);
  SlabRgba acc;
  double u = u_f;
  TfSample front = tf.at_index(u);
  while (u != u_b) {
    // The next table scalar in the direction of travel, or u_b.
    double next = dir > 0 ? std::floor(u) + 1 : std::ceil(u) - 1;
    if (dir * (next - u_b) > 0) next = u_b;
    const TfSample back = tf.at_index(next);
    acc = over(acc, piece(front, back, std::abs(next - u) * per_index));
    front = back;
    u = next;
  }
  return acc;
}

// integrate_slab with linear_piece: the exact slab integral at any scalars.
SlabRgba exact_slab(const DiscreteTf& tf, double s_f, double s_b, double length);

}  // namespace vri
