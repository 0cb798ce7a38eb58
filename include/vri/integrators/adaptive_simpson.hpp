#pragma once
// AdaptiveSimpsonIntegrator (SPEC §9 `adaptive`, strategies `coupled` and
// `decoupled`): Campagnolo, Celes & de Figueiredo, "Accurate volume rendering
// based on adaptive numerical integration", SIBGRAPI 2015.
//
// Both integrals of the volume rendering integral (paper eq. 1) are
// integrated by the paper's iterative adaptive Simpson rule (Algorithm 2):
// a step [t, t+h] is tried with S(t,h), D(t,h) = S(t,h/2) + S(t+h/2,h/2) and
// E = |D - S|/15; on E > eps the step and eps are halved, after the second
// consecutive success both are doubled, h stays in [hmin, hmax], and at hmin
// the step is taken whatever E says. eps is the tolerance at h0 and scales
// with the step.
//  - Inner integral (optical depth, Algorithm 3's I_I): finds, from the
//    current t, a step on which the optical depth is accurate.
//  - Outer integral (I_O): r, g, b and alpha in tandem over that inner
//    interval; the optical depth inside each outer try comes from the same
//    samples (the quartic through them, a fixed rule: its error is bounded
//    by the inner control). `coupled`: the outer step starts from the inner
//    step, so its first try reuses all five inner samples; `decoupled`: the
//    outer step keeps its own pace, limited only by the inner interval.
//  - An inner interval whose five samples are all transparent (zero inner
//    integral) skips the outer integral.
// Evaluations shared by adjacent steps and by halves are reused. Double
// precision throughout; no early ray termination (the paper has none).
// Lit (SPEC §5): every sample's colour is c_lit, so the error control applies
// to the lit integrand.
#include <optional>

#include "vri/integrators/adaptive_params.hpp"
#include "vri/integrators/error_estimating_integrator.hpp"
#include "vri/shading/headlight_shader.hpp"
#include "vri/transfer/transfer_function.hpp"
#include "vri/volume/grid_volume.hpp"

namespace vri {

class AdaptiveSimpsonIntegrator final : public ErrorEstimatingIntegrator {
 public:
  // Throws vri::Error for bad parameters or a strategy other than coupled/decoupled.
  AdaptiveSimpsonIntegrator(const GridVolume& volume, const TransferFunction& tf,
                            const AdaptiveParams& params, const Lighting& lighting = {});
  using ErrorEstimatingIntegrator::integrate;
  Rgba integrate(const Ray& ray, RayStats& stats) const override;
  std::string_view name() const override { return "adaptive"; }

 private:
  const GridVolume& volume_;
  const TransferFunction& tf_;
  double tolerance_;
  double h0_, hmin_, hmax_;  // world units
  bool coupled_;
  std::optional<HeadlightShader> shader_;
};

}  // namespace vri
