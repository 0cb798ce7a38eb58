#pragma once
// Integrator: one method of evaluating the volume rendering integral (SPEC §4)
// along one ray. Every method in vri is one class behind this interface; the
// renderer calls integrate() concurrently from several threads, so it is const
// and keeps no mutable state.
#include <string_view>

#include "vri/core/ray.hpp"
#include "vri/core/rgba.hpp"

namespace vri {

class Integrator {
 public:
  virtual ~Integrator() = default;
  // Premultiplied (C_r, C_g, C_b, alpha) of the ray, before any background.
  virtual Rgba integrate(const Ray& ray) const = 0;
  // out[i] = integrate(rays[i]) for i < n, the same bytes; the renderer hands
  // over a tile row at a time so a method may march neighbouring rays together
  // (preint1's packets, integrators/float_packet.hpp).
  virtual void integrate_row(const Ray* rays, int n, Rgba* out) const {
    for (int i = 0; i < n; ++i) out[i] = integrate(rays[i]);
  }
  virtual std::string_view name() const = 0;
};

}  // namespace vri
