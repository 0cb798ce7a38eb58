#include "vri/integrators/exact.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "cubic.hpp"
#include "gauss_kronrod.hpp"
#include "tf_pieces.hpp"
#include "vri/core/error.hpp"

namespace vri {

ExactIntegrator::ExactIntegrator(const GridVolume& volume, const TransferFunction& tf, double tolerance,
                                 const Lighting& lighting)
    : volume_(volume), tolerance_(tolerance), splitter_(std::make_unique<TfPieceSplitter>(tf)) {
  if (!(tolerance >= 1e-12 && tolerance <= 0.1))
    throw Error("exact: tolerance must be in [1e-12, 0.1], got " + std::to_string(tolerance));
  if (lighting.enabled) shader_.emplace(lighting, volume);
}

ExactIntegrator::~ExactIntegrator() = default;

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
  // Lit: the gradient components along the segment and the sign changes of
  // N.d, where |N.d| has a kink.
  Cubic grad[3];
  double kinks[3];
  int nkinks = 0;
  if (shader_) {
    for (int a = 0; a < 3; ++a) grad[a] = trilinear_along(shader_->gradients().cell_corners(a, cs.cell), cs);
    nkinks = sign_changes(combine(1.0, combine(dir.x, grad[0], dir.y, grad[1]), dir.z, grad[2]), len, kinks);
  }

  splitter_->split(s, len, [&](double x, double y, const TfSegment& seg) {
    const Piece pc(s, seg);
    auto integrate_smooth = [&](double a0, double b0) {
      if (!(b0 > a0)) return;
      const double pa = pc.P(a0);
      auto f = [&](double t, double (&out)[3]) {
        const double ds = s(t) - seg.s_ref;
        const double w = pc.tau(t) * std::exp(pa - pc.P(t));
        const auto lit = shader_ ? shader_->terms({grad[0](t), grad[1](t), grad[2](t)}, dir)
                                 : HeadlightShader::Terms{1, 0};
        out[0] = ((seg.ref.r + seg.slope.r * ds) * lit.a + lit.b) * w;
        out[1] = ((seg.ref.g + seg.slope.g * ds) * lit.a + lit.b) * w;
        out[2] = ((seg.ref.b + seg.slope.b * ds) * lit.a + lit.b) * w;
      };
      // Adaptive Gauss-Kronrod, iterative, depth first. The error allowed on
      // the unattenuated integral is the piece's share of the budget over T.
      const double T_in = acc.T;
      const double density = error_per_length / T_in;
      struct Item {
        double a, b;
        int depth;
      };
      Item stack[64];
      int top = 0;
      stack[top++] = {a0, b0, 0};
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
      acc.T = T_in * std::exp(pa - pc.P(b0));
    };
    double prev = x;
    for (int k = 0; k < nkinks; ++k)
      if (kinks[k] > prev && kinks[k] < y) {
        integrate_smooth(prev, kinks[k]);
        prev = kinks[k];
      }
    integrate_smooth(prev, y);
  });
}

}  // namespace vri
