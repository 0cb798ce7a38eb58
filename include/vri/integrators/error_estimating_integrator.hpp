#pragma once
// An Integrator that also reports, per ray, its own error estimate, how many
// evaluations it spent and (on request) the steps it took. The adaptive
// methods implement it; `vri render --error-estimate` and the step plots of
// docs/ADAPTIVE.md read it.
#include <vector>

#include "vri/integrators/integrator.hpp"

namespace vri {

// One accepted Simpson step of the ray (for plots like Campagnolo et al. 2015, Fig. 6).
struct AdaptiveStep {
  bool outer;    // outer (colour) integral, else inner (optical depth)
  double t, h;   // start and length, world units
  double alpha;  // opacity accumulated up to t + h (outer steps; 0 for inner steps)
};

struct RayStats {
  long evaluations = 0;       // transfer-function evaluations (each at one field value)
  Rgba error_estimate{};      // per channel, the accepted steps' error terms, summed
  bool record_steps = false;  // set by the caller to fill `steps`
  std::vector<AdaptiveStep> steps;
};

class ErrorEstimatingIntegrator : public Integrator {
 public:
  // As integrate(ray), adding this ray's figures to `stats`.
  virtual Rgba integrate(const Ray& ray, RayStats& stats) const = 0;
  Rgba integrate(const Ray& ray) const final {
    RayStats stats;
    return integrate(ray, stats);
  }
};

}  // namespace vri
