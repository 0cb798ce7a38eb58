#pragma once
// The early stop of the integrators that keep an error budget (exact, mesh
// exact, adaptive; the GPU's adaptive shaders compute the same from their
// push constants). Their tolerance is on colours up to 1; lit colours reach
// the shader's brightest, ka + kd + ks, and what a ray can still add behind
// transmittance T is at most T times that in each channel. Stopping once T
// falls below a tenth of the tolerance over it spends a tenth of the budget.
#include <algorithm>
#include <optional>

#include "shading/headlight_shader.hpp"

namespace vri {

// The brightest colour a ray can carry: 1 unlit, ka + kd + ks lit (not below 1).
inline double brightest_colour(const std::optional<HeadlightShader>& shader) {
  return std::max(1.0, shader ? shader->max_brightness() : 1.0);
}

// The transmittance below which a ray may stop.
inline double early_stop_transmittance(double tolerance, double brightest) { return 0.1 * tolerance / brightest; }

}  // namespace vri
