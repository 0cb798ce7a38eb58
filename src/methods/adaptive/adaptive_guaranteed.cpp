#include "adaptive_guaranteed.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "cell_cubics.hpp"
#include "methods/exact/cubic.hpp"
#include "methods/march/early_stop.hpp"
#include "guaranteed_tries.hpp"
#include "simpson_colour_step.hpp"
#include "methods/exact/tf_pieces.hpp"
#include "volume/cell_traversal.hpp"
#include "volume/empty_space.hpp"

namespace vri {

namespace {

// What a piece can change over a step bounds the step (issue 16). The error
// estimate |D - S|/15 only sees what five samples see: on a steep opaque ramp
// (tau 0 -> 500 within a voxel) tau T e^{-depth} is a spike that a whole-piece
// first try can put between its samples, all near zero, and accept. Capping
// tau_max h (the optical depth a step can hold) at kDepthPerStep and the
// colour's change over a step at kColourPerStep keeps every step in the range
// where Simpson's rule resolves the integrand and the estimate is its error.
constexpr double kDepthPerStep = 0.5, kColourPerStep = 0.25;

double step_cap(const Cubic& s, const TfSegment& seg, double x, double y) {
  // The piece lies on one segment: tau and colour are linear in s between the
  // segment's ends (constant on the end regions), so their largest values and
  // slopes are the segment's.
  // (The width in halves: it overflows for control points near -+1e308.)
  auto top = [&](double ref, double slope) {
    return slope == 0 ? ref : std::max(ref, ref + 2 * (slope * (0.5 * seg.s_hi - 0.5 * seg.s_lo)));
  };
  const double tau_max = top(seg.ref.tau, seg.slope.tau);
  const double dc_ds = std::max({std::abs(seg.slope.r), std::abs(seg.slope.g), std::abs(seg.slope.b)});
  // max |s'(t)| on [x, y]: s' is a quadratic, largest at an end or its vertex.
  double ds_dt = std::max(std::abs(s.derivative(x)), std::abs(s.derivative(y)));
  if (s.c[3] != 0) {
    const double v = -s.c[2] / (3 * s.c[3]);
    if (v > x && v < y) ds_dt = std::max(ds_dt, std::abs(s.derivative(v)));
  }
  double cap = INFINITY;
  if (tau_max > 0) cap = kDepthPerStep / tau_max;
  if (dc_ds * ds_dt > 0) cap = std::min(cap, kColourPerStep / (dc_ds * ds_dt));
  return cap;
}

}  // namespace

GuaranteedAdaptiveIntegrator::GuaranteedAdaptiveIntegrator(const GridVolume& volume,
                                                           const TransferFunction& tf,
                                                           const AdaptiveParams& params,
                                                           const Lighting& lighting)
    : volume_(volume),
      tolerance_(params.tolerance),
      zero_(tf),
      margin_(interpolation_margin(volume)),
      zero_bins_(zero_, volume.min_value() - margin_, volume.max_value() + margin_),
      skipping_(volume, zero_, FastPath{}, "adaptive"),
      dense_(tf) {
  params.validate();
  if (lighting.enabled) shader_.emplace(lighting, volume);
  hmax_ = params.hmax * volume.voxel_unit();
  // Lit: where the gradient nearly vanishes the normal swings and the
  // specular term |N.d|^p spikes over a fraction of a voxel; a first try
  // longer than that can put all five samples beside the spike, which the
  // estimate then cannot see. A quarter voxel restored the bound on
  // Marschner-Lobb (docs/ADAPTIVE.md, Lighting).
  if (shader_) hmax_ = std::min(hmax_, 0.25 * volume.voxel_unit());
  hfloor_ = 1e-4 * volume.voxel_unit();
  // Unlit, a cell whose field lies in one segment is one piece. Lit, pieces
  // stay cut at s's critical points too: near a vanishing gradient the
  // specular spike lies there, and a whole-cell first try can miss it
  // (marschner_lobb_lit at 1e-4 had 0.01 % of its pixels over).
  splitter_ = std::make_unique<TfPieceSplitter>(tf, /*monotone=*/lighting.enabled);
  if (const EmptySpace* space = skipping_.space()) transparent_.emplace(volume, *space, zero_bins_, margin_);
}

GuaranteedAdaptiveIntegrator::~GuaranteedAdaptiveIntegrator() = default;

Rgba GuaranteedAdaptiveIntegrator::integrate(const Ray& ray, RayStats& stats) const {
  return volume_.visit([&](auto values) { return integrate_typed(values.data(), ray, stats); });
}

template <class Value>
Rgba GuaranteedAdaptiveIntegrator::integrate_typed(const Value* values, const Ray& ray, RayStats& stats) const {
  const auto iv = volume_.clip(ray);
  if (!iv) return {0, 0, 0, 0};
  const double colour_density = 0.45 * tolerance_ / iv->length();
  // Lit colours reach max_brightness: what an optical-depth error or the
  // early stop can change behind T is T times that, not T.
  const double brightest = brightest_colour(shader_);
  const double depth_density = colour_density / brightest;
  const double cutoff = early_stop_transmittance(tolerance_, brightest);
  double T = 1;
  double C[3] = {0, 0, 0};

  const std::size_t sy = volume_.dims()[0], sz = sy * volume_.dims()[1];
  // Lit: the gradient along the current cell, three cubics in t from the cell entry.
  Cubic grad[3];
  // One smooth piece [x, y] (t from the cell entry) on transfer-function
  // segment `seg`, its steps at most hcap.
  auto integrate_piece = [&](const Cubic& s, const TfSegment& seg, double ta, double x, double y, double hcap) {
    // The samples of the current try and where they were taken: a half step
    // reuses 0, 1/4 and 1/2 of the failed one, the next step starts at the
    // last one's end (positions compare equal as halving is exact).
    TfSample f[5];
    double at[5] = {};
    bool known[5] = {false, false, false, false, false};
    simpson5::StepControl ctl{std::min(y - x, hcap)};
    // The early stop inside a piece too: a very opaque piece would otherwise
    // take y / hcap steps whatever T.
    for (double u = x; u < y && T > cutoff;) {
      const double h = std::min(ctl.h, y - u);
      for (int k = 0; k < 5; ++k) {
        const double p = u + h * (0.25 * k);
        if (known[k] && at[k] == p) continue;
        ++stats.evaluations;
        f[k] = seg.at(s(p));
        if (shader_) {
          const auto lt = shader_->terms({grad[0](p), grad[1](p), grad[2](p)}, ray.dir);
          f[k] = simpson5::lit(f[k], lt.a, lt.b);
        }
        at[k] = p;
        known[k] = true;
      }
      const auto st = simpson5::colour_step(f, h);
      const double depth_err =
          T * simpson5::error(simpson5::halves(st.tau, h), simpson5::whole(st.tau, h));
      const bool ok = (T * st.err <= colour_density * h && depth_err <= depth_density * h) || h <= hfloor_;
      if (!ok) {
        f[4] = f[2], at[4] = at[2];
        f[2] = f[1], at[2] = at[1];
        known[1] = known[3] = false;
        ctl.failed(h, hfloor_);
        continue;
      }
      for (int c = 0; c < 4; ++c) stats.error_estimate[c] += T * simpson5::error(st.D[c], st.S[c]) + depth_err;
      T = simpson5::add_step(st, T, C);
      if (stats.record_steps) stats.steps.push_back({true, ta + u, h, 1 - T});
      ctl.succeeded(hcap);
      f[0] = f[4], at[0] = at[4];
      std::fill(known + 1, known + 5, false);
      u = h >= y - u ? y : u + h;
    }
  };

  // Not below the floor, where every step is accepted anyway: that keeps
  // each step long enough to advance u whatever the cap (1 / huge tau).
  // A piece whose cap (step_cap) lies under the floor is dense: no accepted
  // step could resolve it, so `exact`'s quadrature takes it
  // (integrate_dense, PieceIntegrator about x, with the gradient's cubics
  // about x too where lit).
  auto piece_cap = [&](double cap) { return std::max(hfloor_, std::min(hmax_, cap)); };
  auto integrate_dense = [&](const Cubic& s, double ta, double x, double y) {
    PieceIntegrator::Accumulator acc;
    acc.T = T;
    std::copy(C, C + 3, acc.C);
    const Cubic grad_x[3] = {shifted(grad[0], x), shifted(grad[1], x), shifted(grad[2], x)};
    const PieceIntegrator::Lit lit{shader_ ? &*shader_ : nullptr, grad_x, ray.dir, nullptr, 0};
    dense_.integrate(shifted(s, x), y - x, colour_density, acc, shader_ ? &lit : nullptr);
    stats.evaluations += 15 * acc.panels;
    for (int c = 0; c < 4; ++c) stats.error_estimate[c] += T * colour_density * (y - x);
    T = acc.T;
    std::copy(acc.C, acc.C + 3, C);
    if (stats.record_steps) stats.steps.push_back({true, ta + x, y - x, 1 - T});
  };

  // Unlit, up to four pieces wait here and their first tries are made
  // together (guaranteed_tries.hpp). An accepted first try is added from
  // its lane, as integrate_piece would add it from the same bytes, and a
  // piece longer than its cap goes on from the try's end (integrate_piece
  // from there steps as it would have: its control starts at the cap
  // again). A rejected try runs integrate_piece from the piece's start,
  // whose first try is that lane's again.
  struct Pending {
    Cubic s;
    const TfSegment* seg;
    double ta, x, y, hcap;
  };
  Pending pending[simpson5::PieceTries::kLanes];
  simpson5::PieceTries tries;
  int npending = 0;
  const auto flush = [&] {
    tries.run(npending);
    for (int l = 0; l < npending && T > cutoff; ++l) {
      const Pending& p = pending[l];
      const double h = std::min(p.y - p.x, p.hcap);
      const double depth_err = T * tries.depth_err[l];
      if ((T * tries.err[l] <= colour_density * h && depth_err <= depth_density * h) || h <= hfloor_) {
        stats.evaluations += 5;
        for (int c = 0; c < 4; ++c) stats.error_estimate[c] += T * tries.channel_err[c][l] + depth_err;
        const double boole[4] = {tries.boole[0][l], tries.boole[1][l], tries.boole[2][l], tries.boole[3][l]};
        T = simpson5::add_step(tries.attenuation[l], boole, T, C);
        if (stats.record_steps) stats.steps.push_back({true, p.ta + p.x, h, 1 - T});
        if (h < p.y - p.x) integrate_piece(p.s, *p.seg, p.ta, p.x + h, p.y, p.hcap);
        continue;
      }
      integrate_piece(p.s, *p.seg, p.ta, p.x, p.y, p.hcap);
    }
    npending = 0;
  };

  // Unlit, the pieces of one cell (its cubic s on [0, len], t from ta) wait
  // for their first tries.
  const auto split_unlit = [&](const Cubic& s, double ta, double len) {
    splitter_->split(s, len, [&](double x, double y, const TfSegment& seg) {
      const double cap = step_cap(s, seg, x, y);
      if (cap < hfloor_) {  // dense, after the pieces in front of it
        flush();
        if (T > cutoff) integrate_dense(s, ta, x, y);
        return;
      }
      const double hcap = piece_cap(cap);
      tries.set(npending, s, seg, x, std::min(y - x, hcap));
      pending[npending++] = {s, &seg, ta, x, y, hcap};
      if (npending == tries.kLanes) flush();
    });
  };
  // And the cells wait for their cubics, made four at a time
  // (cell_cubics.hpp, the bytes of trilinear_along).
  CellCubics cubics;
  double cell_ta[CellCubics::kLanes], cell_len[CellCubics::kLanes];
  int ncells = 0;
  const auto flush_cells = [&] {
    cubics.run(ncells);
    for (int l = 0; l < ncells; ++l)
      if (!zero_bins_.over(cubics.lo[l] - margin_, cubics.hi[l] + margin_))
        split_unlit({{cubics.c[0][l], cubics.c[1][l], cubics.c[2][l], cubics.c[3][l]}}, cell_ta[l], cell_len[l]);
    ncells = 0;
  };

  // A brick walks its own part (GridVolume::Brick); the densities above stay
  // the whole ray's, so the bricks' errors add up to one machine's budget.
  // Only the runs of non-empty macro cells are walked.
  const auto walk_cell = [&](const CellSegment& cs) {
    // A cell whose corners' range (with the macro cells' margin for
    // rounding) has zero extinction is transparent on every piece: skipped
    // before its cubic is built (on its bit where the cells were classified).
    if (transparent_ && transparent_->transparent(cs.cell[0], cs.cell[1], cs.cell[2])) return T > cutoff;
    if (!shader_) {
      cubics.set(ncells, values, volume_, cs);
      cell_ta[ncells] = cs.ta, cell_len[ncells] = cs.tb - cs.ta;
      if (++ncells == CellCubics::kLanes) flush_cells();
      return T > cutoff;
    }
    const std::array<float, 8> c = corners_as_float(values + volume_.index(cs.cell[0], cs.cell[1], cs.cell[2]), sy, sz);
    const std::array<double, 8> corners = {c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]};
    const auto [lo, hi] = std::minmax_element(corners.begin(), corners.end());
    if (zero_bins_.over(*lo - margin_, *hi + margin_)) return T > cutoff;
    const Cubic s = trilinear_along(corners, cs);
    // Lit, one cell at a time: |N.d| has a kink where N.d changes sign;
    // pieces are cut there too.
    double kinks[3];
    const int nkinks = gradient_along(shader_->gradients(), cs, ray.dir, grad, kinks);
    splitter_->split(s, cs.tb - cs.ta, [&](double x, double y, const TfSegment& seg) {
      const double cap = step_cap(s, seg, x, y), x0 = x;
      if (cap < hfloor_) {  // dense
        if (T > cutoff) integrate_dense(s, cs.ta, x, y);
        return;
      }
      for (int k = 0; k < nkinks; ++k)
        if (kinks[k] > x && kinks[k] < y) {
          integrate_piece(s, seg, cs.ta, x, kinks[k], piece_cap(step_cap(s, seg, x, kinks[k])));
          x = kinks[k];
        }
      integrate_piece(s, seg, cs.ta, x, y, piece_cap(x == x0 ? cap : step_cap(s, seg, x, y)));
    });
    return T > cutoff;
  };
  for_each_occupied_run(skipping_.space(), ray, owned_part(*iv), [&](const Interval& part) {
    for_each_cell_segment(volume_, ray, part, walk_cell);
    return T > cutoff;
  });
  if (ncells) flush_cells();
  if (npending) flush();
  return {C[0], C[1], C[2], 1 - T};
}

}  // namespace vri
