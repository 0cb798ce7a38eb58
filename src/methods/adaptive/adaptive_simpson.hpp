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
// precision throughout.
// Beyond the paper (issue 21: the uniform marchers' machinery), with the
// fast path's skip_empty (FastPath; `--no-skip` turns it off, leaving the
// paper's algorithm as written):
//  - the ray integrates only its runs of non-empty macro cells
//    (for_each_occupied_run, volume/empty_space.hpp), each as a ray of its
//    own would be (step controls from h0), the transmittance carried: the
//    leaps add exactly nothing, as the integrand is zero there, but the
//    steps after a leap start from the run's entry, so the image is not
//    the one without skipping to the byte (docs/ADAPTIVE.md);
//  - the ray stops once T < 0.1 tol / (the brightest lit colour): what it
//    drops is under a tenth of the tolerance in every channel.
// Lit (SPEC §5): every sample's colour is c_lit, so the error control applies
// to the lit integrand.
#include <optional>

#include "adaptive_params.hpp"
#include "vri/methods.hpp"
#include "methods/fast_path.hpp"
#include "shading/headlight_shader.hpp"
#include "vri/transfer_function.hpp"
#include "vri/volume.hpp"

namespace vri {

class AdaptiveSimpsonIntegrator final : public ErrorEstimatingIntegrator {
 public:
  // Throws vri::Error for bad parameters or a strategy other than coupled/decoupled.
  AdaptiveSimpsonIntegrator(const GridVolume& volume, const TransferFunction& tf,
                            const AdaptiveParams& params, const Lighting& lighting = {},
                            const FastPath& fast = {});
  using ErrorEstimatingIntegrator::integrate;
  Rgba integrate(const Ray& ray, RayStats& stats) const override;
  const Footprint* footprint() const override { return &skipping_.footprint(); }
  std::string_view name() const override { return "adaptive"; }

 private:
  template <class Value>
  Rgba integrate_typed(const Value* values, const Ray& ray, RayStats& stats) const;

  const GridVolume& volume_;
  const TransferFunction& tf_;
  double tolerance_;
  double h0_, hmin_, hmax_;  // world units
  bool coupled_;
  std::optional<HeadlightShader> shader_;
  Skipping skipping_;  // the empty macro cells against tf_ (none with skipping off)
  double cutoff_ = 0;          // the early stop: T below it (0: never)
};

}  // namespace vri
