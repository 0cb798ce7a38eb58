#include "adaptive_simpson.hpp"

#include <algorithm>
#include <cmath>

#include "methods/march/early_stop.hpp"
#include "simpson_colour_step.hpp"
#include "vri/error.hpp"
#include "volume/empty_space.hpp"

namespace vri {

AdaptiveSimpsonIntegrator::AdaptiveSimpsonIntegrator(const GridVolume& volume,
                                                     const TransferFunction& tf,
                                                     const AdaptiveParams& params,
                                                     const Lighting& lighting, const FastPath& fast)
    : volume_(volume), tf_(tf), tolerance_(params.tolerance), skipping_(volume, ZeroOpacity(tf), fast, "adaptive") {
  params.validate();
  if (lighting.enabled) shader_.emplace(lighting, volume);
  if (fast.skip_empty) cutoff_ = early_stop_transmittance(tolerance_, brightest_colour(shader_));
  if (params.strategy == AdaptiveStrategy::Guaranteed)
    throw Error("adaptive: AdaptiveSimpsonIntegrator implements coupled and decoupled only");
  const double vu = volume.voxel_unit();
  h0_ = params.h0 * vu;
  hmin_ = params.hmin * vu;
  hmax_ = params.hmax * vu;
  coupled_ = params.strategy == AdaptiveStrategy::Coupled;
}

namespace {

// The last evaluations along the ray, found again by their exact t. Step
// positions are t + h*(k/4) with h halved or doubled (exact in binary), so a
// point shared by a step and its halves, or by adjacent steps, compares equal.
class SampleCache {
 public:
  template <class Eval>
  const TfSample& get(double t, Eval&& eval) {
    for (int i = 0; i < used_; ++i)
      if (t_[i] == t) return v_[i];
    next_ = (next_ + 1) % kSize;
    used_ = std::max(used_, next_ + 1);
    t_[next_] = t;
    v_[next_] = eval(t);
    return v_[next_];
  }

 private:
  static constexpr int kSize = 12;
  double t_[kSize];
  TfSample v_[kSize];
  int used_ = 0, next_ = -1;
};

}  // namespace

Rgba AdaptiveSimpsonIntegrator::integrate(const Ray& ray, RayStats& stats) const {
  return volume_.visit([&](auto values) { return integrate_typed(values.data(), ray, stats); });
}

template <class Value>
Rgba AdaptiveSimpsonIntegrator::integrate_typed(const Value* values, const Ray& ray, RayStats& stats) const {
  const auto iv = volume_.clip(ray);
  if (!iv) return {0, 0, 0, 0};
  SampleCache cache;
  // The ray in grid coordinates, u(t) = u0 + t du: no division per sample.
  const Vec3 u0 = volume_.grid_position(ray.origin);
  Vec3 du;
  for (int a = 0; a < 3; ++a) du[a] = ray.dir[a] / volume_.spacing()[a];
  auto eval = [&](double t) {
    ++stats.evaluations;
    const TfSample v = tf_(volume_.sample_grid(values, u0 + t * du));
    if (!shader_) return v;
    const auto lt = shader_->at(ray.at(t), ray.dir);
    return simpson5::lit(v, lt.a, lt.b);
  };
  TfSample f[5];
  auto sample_step = [&](double t, double h) {
    for (int k = 0; k < 5; ++k) f[k] = cache.get(t + h * (0.25 * k), eval);
  };
  auto tau_integrals = [&](double h, double& s, double& d) {
    const double tau[5] = {f[0].tau, f[1].tau, f[2].tau, f[3].tau, f[4].tau};
    s = simpson5::whole(tau, h);
    d = simpson5::halves(tau, h);
  };
  // eps halves and doubles with the step: it is tolerance_ at h0.
  auto accepted = [&](double err, double h) { return err <= tolerance_ * h / h0_ || h <= hmin_; };

  double T = 1;  // transmittance at the start of the next outer step
  double C[3] = {0, 0, 0};
  simpson5::StepControl inner{h0_}, outer{h0_};

  // I_O of Algorithm 3: colour and alpha over [a, b].
  auto outer_integral = [&](double a, double b) {
    for (double u = a; u < b;) {
      const double h = std::min(outer.h, b - u);
      sample_step(u, h);
      const auto st = simpson5::colour_step(f, h);
      if (!accepted(T * st.err, h)) {
        outer.failed(h, hmin_);
        continue;
      }
      double tau_s, tau_d;
      tau_integrals(h, tau_s, tau_d);
      const double depth_err = T * simpson5::error(tau_d, tau_s);
      for (int c = 0; c < 4; ++c) stats.error_estimate[c] += T * simpson5::error(st.D[c], st.S[c]) + depth_err;
      T = simpson5::add_step(st, T, C);
      if (stats.record_steps) stats.steps.push_back({true, u, h, 1 - T});
      outer.succeeded(hmax_);
      u = h >= b - u ? b : u + h;
    }
  };

  // Algorithm 3 over [t0, t_end]: inner steps, each covered by the outer integral.
  auto integrate_run = [&](double t0, double t_end) {
    inner = outer = simpson5::StepControl{h0_};
    for (double t = t0; t < t_end && T >= cutoff_;) {
      // I_I of Algorithm 3: the first step from t on which the optical depth is accurate.
      double h;
      for (;;) {
        h = std::min(inner.h, t_end - t);
        sample_step(t, h);
        double s, d;
        tau_integrals(h, s, d);
        if (accepted(simpson5::error(d, s), h)) break;
        inner.failed(h, hmin_);
      }
      inner.succeeded(hmax_);
      if (stats.record_steps) stats.steps.push_back({false, t, h, 0});
      const double b = h >= t_end - t ? t_end : t + h;
      const bool empty = std::all_of(f, f + 5, [](const TfSample& v) { return v.tau == 0; });
      if (!empty) {
        if (coupled_) outer = simpson5::StepControl{h};
        outer_integral(t, b);
      }
      t = b;
    }
    return T >= cutoff_;
  };
  // A brick integrates its own part (GridVolume::Brick).
  for_each_occupied_run(skipping_.space(), ray, owned_part(*iv),
                        [&](const Interval& part) { return integrate_run(part.t0, part.t1); });
  return {C[0], C[1], C[2], 1 - T};
}

}  // namespace vri
