#pragma once
// Splits the piece of a ray inside one cell where the trilinear signal s(t)
// crosses a transfer-function control point, so that on each resulting piece
// the transfer function is a single linear segment and every integrand is
// smooth. Pieces on transparent segments are skipped, and a cell whose values
// touch only transparent segments yields nothing (empty-space skipping).
#include <algorithm>
#include <cmath>
#include <vector>

#include "cubic.hpp"
#include "vri/transfer_function.hpp"

namespace vri {

class TfPieceSplitter {
 public:
  // Pieces are also cut at s's critical points unless `monotone` is false,
  // where a piece need only be smooth: then a cell whose field lies in one
  // segment (as the convex hull of its Bernstein coefficients shows, without
  // the roots of s') is one piece.
  explicit TfPieceSplitter(const TransferFunction& tf, bool monotone = true) : tf_(tf), monotone_(monotone) {
    opaque_prefix_.assign(tf.segments().size() + 1, 0);
    for (std::size_t i = 0; i < tf.segments().size(); ++i)
      opaque_prefix_[i + 1] = opaque_prefix_[i] + (tf.segments()[i].transparent() ? 0 : 1);
  }

  // Calls piece(x, y, segment) for each non-transparent piece [x, y] of
  // [0, len] (t measured from the cell entry), front to back.
  template <class Piece>
  void split(const Cubic& s, double len, Piece&& piece) const {
    if (!monotone_ && len > 0) {
      // s on [0, len] in Bernstein form b0..b3 lies between their least and
      // greatest.
      const double b0 = s.c[0], b3 = s(len);
      const double b1 = b0 + s.c[1] * len / 3, b2 = b3 - s.derivative(len) * len / 3;
      const int i = tf_.segment_index(std::min(std::min(b0, b1), std::min(b2, b3)));
      if (i == tf_.segment_index(std::max(std::max(b0, b1), std::max(b2, b3)))) {
        if (!tf_.segments()[i].transparent()) piece(0.0, len, tf_.segments()[i]);
        return;
      }
    }
    // Knots: the ends and the critical points, between which s is monotone.
    double knots[4], vals[4], crit[2];
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
    const int i0 = tf_.segment_index(smin), i1 = tf_.segment_index(smax);
    if (opaque_prefix_[i1 + 1] == opaque_prefix_[i0]) return;
    if (i0 == i1) {  // one segment holds every value: the monotone pieces, with no search
      for (int m = 0; m + 1 < nk; ++m)
        if (knots[m + 1] > knots[m]) piece(knots[m], knots[m + 1], tf_.segments()[i0]);
      return;
    }

    auto emit = [&](double x, double y) {
      if (!(y > x)) return;
      const TfSegment& seg = tf_.segments()[tf_.segment_index(s(0.5 * (x + y)))];
      if (!seg.transparent()) piece(x, y, seg);
    };
    const auto& bp = tf_.breakpoints();
    for (int m = 0; m + 1 < nk; ++m) {
      const double ka = knots[m], kb = knots[m + 1], fa = vals[m], fb = vals[m + 1];
      double prev = ka;
      auto cut_at = [&](double value) {
        const double r = std::clamp(s.solve_monotone(value, ka, kb), prev, kb);
        emit(prev, r);
        prev = r;
      };
      if (fa < fb) {
        for (auto it = std::upper_bound(bp.begin(), bp.end(), fa); it != bp.end() && *it < fb; ++it)
          cut_at(*it);
      } else if (fa > fb) {
        for (auto it = std::lower_bound(bp.begin(), bp.end(), fa); it != bp.begin() && *(it - 1) > fb;)
          cut_at(*--it);
      }
      emit(prev, kb);
    }
  }

 private:
  const TransferFunction& tf_;
  bool monotone_;
  std::vector<int> opaque_prefix_;  // opaque_prefix_[i]: non-transparent segments before i
};

}  // namespace vri
