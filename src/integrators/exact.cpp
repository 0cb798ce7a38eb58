#include "vri/integrators/exact.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cubic.hpp"
#include "gauss_kronrod.hpp"
#include "vri/core/error.hpp"

namespace vri {

ExactIntegrator::ExactIntegrator(const GridVolume& volume, const TransferFunction& tf, double tolerance,
                                 const Lighting& lighting)
    : volume_(volume), tf_(tf), tolerance_(tolerance) {
  if (!(tolerance >= 1e-12 && tolerance <= 0.1))
    throw Error("exact: tolerance must be in [1e-12, 0.1], got " + std::to_string(tolerance));
  if (lighting.enabled) shader_.emplace(lighting, volume);
  opaque_prefix_.assign(tf.segments().size() + 1, 0);
  for (std::size_t i = 0; i < tf.segments().size(); ++i)
    opaque_prefix_[i + 1] = opaque_prefix_[i] + (tf.segments()[i].transparent() ? 0 : 1);
}

Rgba ExactIntegrator::integrate(const Ray& ray) const {
  const auto iv = clip_to_box(ray, volume_.box_lo(), volume_.box_hi());
  if (!iv) return {0, 0, 0, 0};
  Accumulator acc;
  const double error_per_length = tolerance_ / iv->length();
  // What is left after stopping is at most T * (brightest colour) per channel.
  const double cutoff = 0.1 * tolerance_ / std::max(1.0, shader_ ? shader_->max_brightness() : 1.0);
  for_each_cell_segment(volume_, ray, *iv, [&](const CellSegment& seg) {
    integrate_cell(seg, ray.dir, error_per_length, acc);
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

void ExactIntegrator::integrate_cell(const CellSegment& cs, Vec3 dir, double error_per_length,
                                     Accumulator& acc) const {
  const double len = cs.tb - cs.ta;
  const Cubic s = trilinear_along(volume_, cs);

  // Knots: the ends and the critical points, between which s is monotone.
  double knots[4], vals[4];
  int nk = 0;
  knots[nk++] = 0;
  nk += s.critical_points(len, knots + 1);
  knots[nk++] = len;
  double smin = INFINITY, smax = -INFINITY;
  for (int i = 0; i < nk; ++i) {
    vals[i] = s(knots[i]);
    smin = std::min(smin, vals[i]);
    smax = std::max(smax, vals[i]);
  }
  // Empty space: every transfer-function segment the cell's values touch is transparent.
  const int i0 = tf_.segment_index(smin), i1 = tf_.segment_index(smax);
  if (opaque_prefix_[i1 + 1] == opaque_prefix_[i0]) return;

  // Cuts: where s crosses a control point (each monotone run crosses each
  // control value between its end values once) and, when lit, where N.d = 0.
  thread_local std::vector<double> cuts;
  cuts.clear();
  const auto& bp = tf_.breakpoints();
  for (int m = 0; m + 1 < nk; ++m) {
    const double ka = knots[m], kb = knots[m + 1], lo = std::min(vals[m], vals[m + 1]),
                 hi = std::max(vals[m], vals[m + 1]);
    for (auto it = std::upper_bound(bp.begin(), bp.end(), lo); it != bp.end() && *it < hi; ++it)
      cuts.push_back(s.solve_monotone(*it, ka, kb));
  }
  Cubic grad[3];
  if (shader_) {
    for (int a = 0; a < 3; ++a) grad[a] = trilinear_along(shader_->gradients().cell_corners(a, cs.cell), cs);
    const Cubic nd = combine(1.0, combine(dir.x, grad[0], dir.y, grad[1]), dir.z, grad[2]);
    double roots[3];
    const int nr = sign_changes(nd, len, roots);
    cuts.insert(cuts.end(), roots, roots + nr);
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.push_back(len);

  auto integrate_piece = [&](double x, double y) {
    if (!(y > x)) return;
    const TfSegment& seg = tf_.segments()[tf_.segment_index(s(0.5 * (x + y)))];
    if (seg.transparent()) return;
    const Piece pc(s, seg);
    const double px = pc.P(x);
    auto f = [&](double t, double (&out)[3]) {
      const double ds = s(t) - seg.s_ref;
      const double w = pc.tau(t) * std::exp(px - pc.P(t));
      double a = 1, b = 0;  // unlit: c_lit = c
      if (shader_) {
        const auto terms = shader_->terms({grad[0](t), grad[1](t), grad[2](t)}, dir);
        a = terms.a;
        b = terms.b;
      }
      out[0] = ((seg.ref.r + seg.slope.r * ds) * a + b) * w;
      out[1] = ((seg.ref.g + seg.slope.g * ds) * a + b) * w;
      out[2] = ((seg.ref.b + seg.slope.b * ds) * a + b) * w;
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

  double prev = 0;
  for (double cut : cuts) {
    const double c = std::clamp(cut, prev, len);
    integrate_piece(prev, c);
    prev = c;
  }
}

}  // namespace vri
