#include "vri/integrators/adaptive_guaranteed.hpp"

#include <algorithm>
#include <cmath>

#include "cubic.hpp"
#include "simpson5.hpp"
#include "tf_pieces.hpp"
#include "vri/volume/cell_traversal.hpp"

namespace vri {

GuaranteedAdaptiveIntegrator::GuaranteedAdaptiveIntegrator(const GridVolume& volume,
                                                           const TransferFunction& tf,
                                                           const AdaptiveParams& params)
    : volume_(volume), tolerance_(params.tolerance) {
  params.validate();
  hmax_ = params.hmax * volume.voxel_unit();
  hfloor_ = 1e-4 * volume.voxel_unit();
  splitter_ = std::make_unique<TfPieceSplitter>(tf);
}

GuaranteedAdaptiveIntegrator::~GuaranteedAdaptiveIntegrator() = default;

Rgba GuaranteedAdaptiveIntegrator::integrate(const Ray& ray, RayStats& stats) const {
  const auto iv = clip_to_box(ray, volume_.box_lo(), volume_.box_hi());
  if (!iv) return {0, 0, 0, 0};
  const double colour_density = 0.45 * tolerance_ / iv->length();
  const double depth_density = colour_density;
  const double cutoff = 0.1 * tolerance_;
  double T = 1;
  Rgba C{0, 0, 0, 0};

  // One smooth piece [x, y] (t from the cell entry) on transfer-function segment `seg`.
  auto integrate_piece = [&](const Cubic& s, const TfSegment& seg, double ta, double x, double y) {
    // The samples of the current try and where they were taken: a half step
    // reuses 0, 1/4 and 1/2 of the failed one, the next step starts at the
    // last one's end (positions compare equal as halving is exact).
    TfSample f[5];
    double at[5] = {};
    bool known[5] = {false, false, false, false, false};
    simpson5::StepControl ctl{std::min(y - x, hmax_)};
    for (double u = x; u < y;) {
      const double h = std::min(ctl.h, y - u);
      for (int k = 0; k < 5; ++k) {
        const double p = u + h * (0.25 * k);
        if (known[k] && at[k] == p) continue;
        ++stats.evaluations;
        f[k] = seg.at(s(p));
        at[k] = p;
        known[k] = true;
      }
      double tau[5], depth[5], g[4][5];
      for (int k = 0; k < 5; ++k) tau[k] = f[k].tau;
      simpson5::cumulative(tau, h, depth);
      for (int k = 0; k < 5; ++k) {
        const double w = f[k].tau * T * std::exp(-depth[k]);
        g[0][k] = f[k].r * w;
        g[1][k] = f[k].g * w;
        g[2][k] = f[k].b * w;
        g[3][k] = w;
      }
      double S[4], D[4], err = 0;
      for (int c = 0; c < 4; ++c) {
        S[c] = simpson5::whole(g[c], h);
        D[c] = simpson5::halves(g[c], h);
        err = std::max(err, simpson5::error(D[c], S[c]));
      }
      const double depth_err =
          T * simpson5::error(simpson5::halves(tau, h), simpson5::whole(tau, h));
      const bool ok = (err <= colour_density * h && depth_err <= depth_density * h) || h <= hfloor_;
      if (!ok) {
        f[4] = f[2], at[4] = at[2];
        f[2] = f[1], at[2] = at[1];
        known[1] = known[3] = false;
        ctl.failed(h, hfloor_);
        continue;
      }
      for (int c = 0; c < 4; ++c) {
        C[c] += simpson5::corrected(D[c], S[c]);
        stats.error_estimate[c] += simpson5::error(D[c], S[c]) + depth_err;
      }
      T *= std::exp(-depth[4]);
      if (stats.record_steps) stats.steps.push_back({true, ta + u, h, C[3]});
      ctl.succeeded(hmax_);
      f[0] = f[4], at[0] = at[4];
      std::fill(known + 1, known + 5, false);
      u = h >= y - u ? y : u + h;
    }
  };

  for_each_cell_segment(volume_, ray, *iv, [&](const CellSegment& cs) {
    const Cubic s = trilinear_along(volume_, cs);
    splitter_->split(s, cs.tb - cs.ta, [&](double x, double y, const TfSegment& seg) {
      integrate_piece(s, seg, cs.ta, x, y);
    });
    return T > cutoff;
  });
  return C;
}

}  // namespace vri
