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
//
// Jitter (issue 20; `jitter`, a seed): the samples of a fixed step sit at the
// same depths behind the box face in every pixel, and features cut by those
// shells show as wood-grain rings. With jitter the steps stay where they are,
// but each ray samples its steps u of the way in, u in [0, 1) drawn from the
// ray's bits and the seed (so the same image for any thread count):
// t_k + u h_k. Over u that is exact in expectation for the optical depth (the
// mean of f(t_k + u h) over u is f's mean over the step), and the rings
// become fine noise. With jitter, rays are marched one by one (no packets).
#include <cstdint>
#include <memory>
#include <optional>

#include "methods/fast_path.hpp"
#include "vri/methods.hpp"  // the constructors' types
#include "shading/headlight_shader.hpp"
#include "transfer/float_transfer_function.hpp"
#include "vri/transfer_function.hpp"
#include "volume/float_sampler.hpp"
#include "vri/volume.hpp"

namespace vri {

namespace detail {
class FloatShading;  // src/methods/march/float_shading.hpp
}

class RiemannIntegrator final : public Integrator {
 public:
  // step in voxel units; throws vri::Error unless 1e-4 <= step <= 1e4.
  RiemannIntegrator(const GridVolume& volume, const TransferFunction& tf, double step,
                    const Lighting& lighting = {}, const FastPath& fast = {},
                    std::optional<std::uint64_t> jitter = {});
  ~RiemannIntegrator() override;
  Rgba integrate(const Ray& ray) const override;
  // On the float path, on a CPU with AVX2: packets of 8 neighbouring
  // rays (float_packet.hpp), the same bytes as integrate.
  void integrate_row(const Ray* rays, int n, Rgba* out) const override;
  const Footprint* footprint() const override { return &fast_.footprint(); }
  std::string_view name() const override { return "riemann"; }

 private:
  // The march on the volume's typed samples (one type dispatch per ray).
  template <class Value>
  Rgba march(const Ray& ray, const Value* values) const;

  const GridVolume& volume_;
  const TransferFunction& tf_;
  double h_;  // world units
  std::optional<HeadlightShader> shader_;
  Skipping fast_;
  bool float_path_;  // fast.float_math
  FloatSampler float_sampler_;
  FloatTransferFunction float_tf_;
  std::unique_ptr<detail::FloatShading> float_shading_;  // lit, on the float path
  std::optional<std::uint64_t> jitter_;  // the seed
  bool packets_;  // integrate_row marches packets
};

// The registry's constructors (src/methods/method_registry.cpp): the integrator from
// a scene's method block, and its GPU renderer (vulkan_riemann.cpp, Vulkan builds only).
std::unique_ptr<Integrator> make_riemann(const MethodSpec& spec, const GridVolume& volume, const TransferFunction& tf,
                                         const Lighting& lighting);
std::unique_ptr<GpuSceneRenderer> make_vulkan_riemann(const Scene& scene);

}  // namespace vri
