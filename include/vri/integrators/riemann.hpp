#pragma once
// RiemannIntegrator (SPEC §9 `riemann`): the classic ray caster. Samples at
// t_k = t0 + k*h (left end of each step, k = 0..N-1, N = ceil(L/h)); each step
// is a homogeneous slab of length h_k = min(h, t1 - t_k) with the sample's
// colour and extinction, composited front to back:
//   alpha_k = 1 - exp(-tau(s_k) h_k),  C += T c(s_k) alpha_k,  T *= 1 - alpha_k.
// A left Riemann sum of the optical depth: first-order accurate in h.
// With lighting, c(s_k) is replaced by c_lit at the sample (SPEC §5).
// FastPath (fast_path.hpp): samples in empty macro cells are leapt over (they
// have tau = 0 and add nothing), and the ray may stop once T < termination.
// Unless fast.float_math is off, riemann works in float on the same sample
// positions (float_riemann.hpp; lit, float_shading.hpp), on packets of 8 rays
// where the CPU has AVX2.
#include <memory>
#include <optional>

#include "vri/integrators/fast_path.hpp"
#include "vri/integrators/integrator.hpp"
#include "vri/shading/headlight_shader.hpp"
#include "vri/transfer/float_transfer_function.hpp"
#include "vri/transfer/transfer_function.hpp"
#include "vri/volume/float_sampler.hpp"
#include "vri/volume/grid_volume.hpp"

namespace vri {

namespace detail {
class FloatShading;  // src/integrators/float_shading.hpp
}

class RiemannIntegrator final : public Integrator {
 public:
  // step in voxel units; throws vri::Error unless 1e-4 <= step <= 1e4.
  RiemannIntegrator(const GridVolume& volume, const TransferFunction& tf, double step,
                    const Lighting& lighting = {}, const FastPath& fast = {});
  ~RiemannIntegrator() override;
  Rgba integrate(const Ray& ray) const override;
  // On the float path, on a CPU with AVX2: packets of 8 neighbouring
  // rays (float_packet.hpp), the same bytes as integrate.
  void integrate_row(const Ray* rays, int n, Rgba* out) const override;
  std::string_view name() const override { return "riemann"; }

 private:
  // The march on the volume's typed samples (one type dispatch per ray).
  template <class Value>
  Rgba march(const Ray& ray, const Value* values) const;

  const GridVolume& volume_;
  const TransferFunction& tf_;
  double h_;  // world units
  std::optional<HeadlightShader> shader_;
  detail::Skipping fast_;
  bool float_path_;  // fast.float_math
  FloatSampler float_sampler_;
  FloatTransferFunction float_tf_;
  std::unique_ptr<detail::FloatShading> float_shading_;  // lit, on the float path
  bool packets_;  // integrate_row marches packets
};

}  // namespace vri
