#include "piece_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "cubic.hpp"
#include "gauss_kronrod.hpp"
#include "tf_pieces.hpp"
#include "vri/error.hpp"

namespace vri {

namespace {

// One piece on which the transfer function is a single linear segment:
// tau(t) is then the cubic `tau`.
struct Piece {
  const Cubic& s;
  const TfSegment& seg;
  Cubic tau;
  Piece(const Cubic& s_, const TfSegment& seg_) : s(s_), seg(seg_) {
    tau.c[0] = seg.ref.tau + seg.slope.tau * (s.c[0] - seg.s_ref);
    for (int k = 1; k < 4; ++k) tau.c[k] = seg.slope.tau * s.c[k];
  }
};

// tau and the optical depth from a0, D(u) = integral of tau over
// [a0, a0 + u], as polynomials in u taken about a0, so that their rounding
// is relative to what they are near a0: the difference P(t) - P(a0) of one
// quartic about the cell's start cancelled, and so did tau's terms of 1e11
// where a spike rises from 0; at extinctions of thousands their noise
// outgrew the error budget and the ray the panel cap (issue 46).
struct DepthFrom {
  Cubic d;  // tau(a0 + u)
  DepthFrom(const Cubic& tau, double a0) : d(shifted(tau, a0)) {}
  double tau(double u) const { return d(u); }
  double operator()(double u) const {
    return (((0.25 * d.c[3] * u + d.c[2] / 3) * u + 0.5 * d.c[1]) * u + d.c[0]) * u;
  }
  // The u in [0, len] where the depth first reaches `depth` (bisection; D
  // grows, tau >= 0), given that it does by len. Up to 2200 halvings: at
  // extinction 1e300 the layer is 1e-299 thick, a thousand halvings of len.
  double reach(double depth, double len) const {
    double lo = 0, hi = len;
    for (int k = 0; k < 2200; ++k) {
      const double m = 0.5 * (lo + hi);
      if (!(m > lo && m < hi)) break;
      ((*this)(m) < depth ? lo : hi) = m;
    }
    return hi;
  }
};

// Past this optical depth from a piece's start what is left of its light
// weighs under e^-50 (2e-22): the colour integral stops there. Without it, at
// extinction 1e15 every Gauss-Kronrod node lay past the thin layer the light
// comes from, both rules agreed on 0, and the ray came out black and opaque.
constexpr double kDepthCut = 50;

}  // namespace

long PieceIntegrator::default_max_panels() {
  const char* v = std::getenv(kMaxPanelsVariable);
  if (!v || !*v) return kDefaultMaxPanels;
  char* end = nullptr;
  const long n = std::strtol(v, &end, 10);
  if (*end != 0 || n <= 0)
    throw Error(std::string(kMaxPanelsVariable) + " must be a positive integer, got '" + v + "'");
  return n;
}

PieceIntegrator::PieceIntegrator(const TransferFunction& tf, long max_panels)
    : splitter_(std::make_unique<TfPieceSplitter>(tf)), max_panels_(max_panels) {}

PieceIntegrator::~PieceIntegrator() = default;

void PieceIntegrator::integrate_linear(double s_front, double s_back, double len, double error_per_length,
                                       Accumulator& acc, const Lit* lit) const {
  integrate(Cubic::linear(s_front, s_back, len), len, error_per_length, acc, lit);
}

void PieceIntegrator::integrate(const Cubic& s, double len, double error_per_length, Accumulator& acc,
                                const Lit* lit) const {
  if (!(len > 0)) return;
  splitter_->split(s, len, [&](double x, double y, const TfSegment& seg) {
    const Piece pc(s, seg);
    auto integrate_smooth = [&](double a0, double b0) {
      if (!(b0 > a0) || acc.T == 0) return;  // nothing behind an opaque front shows
      const DepthFrom depth(pc.tau, a0);
      const double full = depth(b0 - a0);
      // The quadrature runs in u = t - a0: in t, a layer 1e-9 wide at t ~ 0.3
      // holds its nodes to 2e-8 of its width, the depth to 1e-6 of itself, and
      // the error estimate never fell under its floor (350 000 panels a piece
      // at extinction 1e10).
      const double u_end = full > kDepthCut ? depth.reach(kDepthCut, b0 - a0) : b0 - a0;
      // The scalar about a0 as well: s(a0) - s_ref once, then its change over
      // u without cancellation. Two points 5e-11 apart make a colour slope of
      // 1e10 per scalar unit, and s(t) at t ~ 0.3 carried noise of 1e-6 into
      // the colour: the panel cap again (seed 227).
      const Cubic s_a = shifted(s, a0);
      const double ds0 = s_a.c[0] - seg.s_ref;
      // The segment's values lie between its ends' (tau >= 0, colour in
      // [0, 1]); clamping keeps rounding in s(t) - s_ref, times a steep slope,
      // from leaving that range. exp(...) <= 1: optical depth only grows.
      auto f = [&](double u, double (&out)[3]) {
        const double t = a0 + u, ds = ds0 + ((s_a.c[3] * u + s_a.c[2]) * u + s_a.c[1]) * u;
        const double w = std::max(depth.tau(u), 0.0) * std::exp(-std::max(depth(u), 0.0));
        const auto terms = lit ? lit->shader->terms({lit->grad[0](t), lit->grad[1](t), lit->grad[2](t)}, lit->dir)
                               : HeadlightShader::Terms{1, 0};
        out[0] = (std::clamp(seg.ref.r + seg.slope.r * ds, 0.0, 1.0) * terms.a + terms.b) * w;
        out[1] = (std::clamp(seg.ref.g + seg.slope.g * ds, 0.0, 1.0) * terms.a + terms.b) * w;
        out[2] = (std::clamp(seg.ref.b + seg.slope.b * ds, 0.0, 1.0) * terms.a + terms.b) * w;
      };
      // Adaptive Gauss-Kronrod, iterative, depth first. The error allowed on
      // the unattenuated integral is the piece's share of the budget (not
      // over T, which would be enough: the panels would then depend on the
      // transmittance in front, which a brick of a distributed render does
      // not know, and its image leave one process's by up to the tolerance,
      // SPEC §11), and never below what rounding leaves of the panel's own
      // value (kRelative of it): an absolute target alone is out of reach
      // when the integrand is huge (specular 1e10) and would subdivide to the
      // depth cap.
      const double T_in = acc.T;
      constexpr double kRelative = 1e-12;
      struct Item {
        double a, b;
        int depth;
      };
      Item stack[64];
      int top = 0;
      stack[top++] = {0, u_end, 0};
      double sum[3] = {0, 0, 0};
      while (top > 0) {
        const Item it = stack[--top];
        double k[3];
        if (++acc.panels > max_panels_)
          throw Error("exact: a ray needed more than " + std::to_string(max_panels_) +
                      " Gauss-Kronrod panels (the cap on work per ray); loosen the tolerance, or raise the cap "
                      "with the environment variable " + std::string(kMaxPanelsVariable));
        const double err = gk15::apply<3>(f, it.a, it.b, k);
        const double size = std::max({std::abs(k[0]), std::abs(k[1]), std::abs(k[2])});
        if (err <= std::max(error_per_length * (it.b - it.a), kRelative * size) || it.depth >= 40) {
          for (int c = 0; c < 3; ++c) sum[c] += k[c];
        } else {
          const double m = 0.5 * (it.a + it.b);
          stack[top++] = {m, it.b, it.depth + 1};  // right half popped second
          stack[top++] = {it.a, m, it.depth + 1};
        }
      }
      for (int c = 0; c < 3; ++c) acc.C[c] += T_in * sum[c];
      acc.T = T_in * std::exp(-std::max(full, 0.0));
    };
    double prev = x;
    for (int k = 0; lit && k < lit->nkinks; ++k)
      if (lit->kinks[k] > prev && lit->kinks[k] < y) {
        integrate_smooth(prev, lit->kinks[k]);
        prev = lit->kinks[k];
      }
    integrate_smooth(prev, y);
  });
}

}  // namespace vri
