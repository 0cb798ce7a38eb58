#pragma once
// The exact integral of SPEC §4 over one slab of a discretised transfer
// function (DiscreteTf), with the scalar linear along the slab. This is the
// definition every pre-integration table entry is held to:
//
//   entry(s_f, s_b, l) = (C, alpha) of a slab of length l whose scalar runs
//   linearly from s_f to s_b through the transfer function itself.
//
// The slab crosses the table scalars and the control points between s_f and
// s_b; between two of them (a "piece") tau and c are linear in the distance t
// along the ray, and the pieces composite front to back.
#include <algorithm>
#include <cmath>
#include <span>

#include "tables/discrete_tf.hpp"
#include "tables/slab_rgba.hpp"

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

// Sub-piece s between indices lo < hi inside it: its values there, exact at its ends.
inline TfSample sub_piece_at(const SubPiece& s, double u) {
  if (u <= s.u0) return s.p;
  if (u >= s.u1) return s.q;
  const double w = (u - s.u0) / (s.u1 - s.u0);
  return {(1 - w) * s.p.r + w * s.q.r, (1 - w) * s.p.g + w * s.q.g, (1 - w) * s.p.b + w * s.q.b,
          (1 - w) * s.p.tau + w * s.q.tau};
}

// The part [lo, hi] of a split bin's sub-pieces, composited in the direction
// of travel (dir > 0: lo at the front) with piece(front, back, d), d =
// per_index times the index span. Steps inside the bin are crossed exactly.
template <class PieceFn>
SlabRgba integrate_sub_pieces(std::span<const SubPiece> subs, double lo, double hi, double dir, double per_index,
                              PieceFn& piece) {
  SlabRgba acc;
  const auto one = [&](const SubPiece& s) {
    const double a = std::max(s.u0, lo), b = std::min(s.u1, hi);
    if (!(b > a)) return;
    const TfSample p = sub_piece_at(s, a), q = sub_piece_at(s, b);
    acc = over(acc, dir > 0 ? piece(p, q, (b - a) * per_index) : piece(q, p, (b - a) * per_index));
  };
  if (dir > 0)
    for (const SubPiece& s : subs) one(s);
  else
    for (auto it = subs.rbegin(); it != subs.rend(); ++it) one(*it);
  return acc;
}

// How a slab's plain bins become pieces: one a bin, or one a straight run
// of bins (DiscreteTf::linear_end: tau and c one line along it, so its
// integral is one piece's, and the bins one by one differ from it only by
// roundings). Runs only where the piece function is exact for linear tau
// and c (linear_piece, a quadrature); weighted_slab's weight times colour
// is quadratic along a piece and is approximated bin by bin.
enum class SlabPieces { Bins, Runs };

// The pieces of the slab from continuous index u_f != u_b to u_b
// (DiscreteTf::at_index) of length l, front to back: plain(front, back, d)
// for each plain bin or straight run (or part of one), d its length, and
// split(subs, lo, hi, dir, per_index) for the part [lo, hi] of a split bin
// (integrate_sub_pieces).
template <class Plain, class Split>
void for_each_slab_bin(const DiscreteTf& tf, double u_f, double u_b, double length, Plain&& plain, Split&& split,
                       SlabPieces pieces = SlabPieces::Bins) {
  const double dir = u_b > u_f ? 1 : -1;
  const double per_index = length / std::abs(u_b - u_f);
  double u = u_f;
  TfSample front = tf.at_index(u);
  // at_index at a table scalar short of u_b: that scalar's sample (a table
  // scalar before the last one, where at_index reads it with weight 1 and
  // its neighbour's with weight 0: the same bits), without its search.
  const auto at = [&](double next) { return next == u_b ? tf.at_index(next) : tf[static_cast<int>(next)]; };
  while (u != u_b) {
    // The next table scalar in the direction of travel, or u_b.
    double next = dir > 0 ? std::floor(u) + 1 : std::ceil(u) - 1;
    if (dir * (next - u_b) > 0) next = u_b;
    const int bin = static_cast<int>(std::min(u, next));
    const auto subs = tf.sub_pieces(bin);
    if (subs.empty()) {
      if (pieces == SlabPieces::Runs)  // on to the end of the bin's straight run (or u_b)
        next = dir > 0 ? std::min(double(tf.linear_end(bin)), u_b) : std::max(double(tf.linear_begin(bin)), u_b);
      const TfSample back = at(next);
      plain(front, back, std::abs(next - u) * per_index);
      front = back;
    } else {
      split(subs, std::min(u, next), std::max(u, next), dir, per_index);
      front = at(next);
    }
    u = next;
  }
}

// The slab from continuous index u_f to u_b (DiscreteTf::at_index) of length
// l, composited piece by piece with `piece(front, back, d)` -> SlabRgba: one
// piece per plain bin or straight run (`pieces`; or part of one), one per
// sub-piece of a split bin. u_f == u_b is the homogeneous slab.
// O(bins or runs crossed + sub-pieces crossed + 1).
template <class PieceFn>
SlabRgba integrate_slab(const DiscreteTf& tf, double u_f, double u_b, double length, PieceFn piece,
                        SlabPieces pieces = SlabPieces::Bins) {
  if (u_f == u_b) return homogeneous_slab(tf.at_index(u_f), length);
  SlabRgba acc;
  for_each_slab_bin(
      tf, u_f, u_b, length,
      [&](const TfSample& front, const TfSample& back, double d) { acc = over(acc, piece(front, back, d)); },
      [&](std::span<const SubPiece> subs, double lo, double hi, double dir, double per_index) {
        acc = over(acc, integrate_sub_pieces(subs, lo, hi, dir, per_index, piece));
      },
      pieces);
  return acc;
}

// integrate_slab with linear_piece over straight runs (SlabPieces::Runs):
// the exact slab integral at any scalars, and the same at continuous indices
// u_f, u_b (DiscreteTf::at_index). The runs' weights are found four at a
// time (the series of piece_weights.hpp on GCC vectors: the same operations
// lane by lane, so the same bits as linear_piece): the partial last slab of
// a ray that leaves the volume through its data crosses a dozen bins or
// more, most of them on a few straight runs.
SlabRgba exact_slab(const DiscreteTf& tf, double s_f, double s_b, double length);
SlabRgba exact_index_slab(const DiscreteTf& tf, double u_f, double u_b, double length);

}  // namespace vri
