#pragma once
// Integrator: one method of evaluating the volume rendering integral (SPEC §4)
// along one ray. Every per-ray CPU method is a class behind this interface
// (vri/methods.hpp per_ray); pt and pt-cylindrical project whole tetrahedra
// (render_projected) and the GPU has its own kernels (render/backend.hpp). The
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
  // over two rows of a tile at a time, in blocks of 4 x 2 pixels, so a method
  // may march neighbouring rays together (the packets of 8,
  // methods/march/float_packet.hpp).
  virtual void integrate_row(const Ray* rays, int n, Rgba* out) const {
    for (int i = 0; i < n; ++i) out[i] = integrate(rays[i]);
  }
  // Where the method sees anything: a ray that misses the footprint
  // integrates to exactly {0, 0, 0, 0}, the value an image starts with, so
  // the renderer need not cast it (as VTK's ray casters cast only inside
  // the volume's projected bounds). Null (the default): every ray is cast.
  virtual const Footprint* footprint() const { return nullptr; }
  virtual std::string_view name() const = 0;
};

}  // namespace vri
