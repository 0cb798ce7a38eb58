#include "vri/integrators/exact.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "cubic.hpp"
#include "gauss_kronrod.hpp"
#include "tf_pieces.hpp"
#include "vri/core/error.hpp"

namespace vri {

ExactIntegrator::ExactIntegrator(const GridVolume& volume, const TransferFunction& tf,
                                 double tolerance)
    : volume_(volume), tolerance_(tolerance), splitter_(std::make_unique<TfPieceSplitter>(tf)) {
  if (!(tolerance >= 1e-12 && tolerance <= 0.1))
    throw Error("exact: tolerance must be in [1e-12, 0.1], got " + std::to_string(tolerance));
}

ExactIntegrator::~ExactIntegrator() = default;

Rgba ExactIntegrator::integrate(const Ray& ray) const {
  const auto iv = clip_to_box(ray, volume_.box_lo(), volume_.box_hi());
  if (!iv) return {0, 0, 0, 0};
  Accumulator acc;
  const double error_per_length = tolerance_ / iv->length();
  const double cutoff = 0.1 * tolerance_;
  for_each_cell_segment(volume_, ray, *iv, [&](const CellSegment& seg) {
    integrate_cell(seg, error_per_length, acc);
    return acc.T > cutoff;
  });
  return {acc.C[0], acc.C[1], acc.C[2], 1 - acc.T};
}

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

void ExactIntegrator::integrate_cell(const CellSegment& cs, double error_per_length,
                                     Accumulator& acc) const {
  const Cubic s = trilinear_along(volume_, cs);
  splitter_->split(s, cs.tb - cs.ta, [&](double x, double y, const TfSegment& seg) {
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
  });
}

}  // namespace vri
