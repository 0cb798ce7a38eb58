#pragma once
// Preint2Integrator (SPEC §9 `preint2`): second-order pre-integrated ray
// casting (El Hajjar, Marchesin, Dischler & Mongenet 2008, "Second order
// pre-integrated volume rendering", PacificVis). Samples at t_i = t0 + i h;
// slab k spans [t_2k, t_2k+2] (length 2h) and is one lookup of a
// SecondOrderTable at (s_2k, s_2k+1, s_2k+2): the scalar along it is taken as
// the parabola through the three samples (the paper's eq. 2: the quadratic
// Lagrange polynomial P(u) = A u^2 + B u + C, u in [0, 1], with
// A = 2 s_f - 4 s_m + 2 s_b, B = -3 s_f + 4 s_m - s_b, C = s_f), and the
// slabs composite front to back (eq. 3). This is the paper's constant-length
// sampling (its Section 5). The back sample is the next slab's front.
// Per pair of steps: two volume samples, one lookup, one composite (preint1:
// two lookups, two composites).
//
// The last partial slab of length r < 2h (ray lengths not a multiple of 2h)
// is cut into two halves of r/2 < h, each integrated exactly under the table's
// discretisation with the scalar linear along it (ray_steps.hpp, shared with
// preint1): no table with lengths, no slab dropped or counted twice, and the
// result is continuous in the ray length (r -> 0 adds nothing).
//
// Lighting (SPEC §5, `lighting.mode`; docs/LIGHTING.md, "Second order"):
// `sampled` lights each slab's pre-integrated colour with one normal, the
// mean of its three samples' gradients; `interpolated` interpolates the
// shading quadratically through the three samples with the weighted tables
// of second_order_weighted.hpp (three tables: 3x the memory, 768 MiB at 256
// entries a side). The partial last slab is lit as preint1 lights its own.
//
// Fast path (fast_path.hpp): the slabs whose three samples lie in a run of
// macro cells classified empty for second-order entries (ZeroOpacity with
// TableOrder::Second: the parabola's overshoot stays in zero opacity) are
// leapt over on the same samples, so the image keeps its bytes; early
// termination as in preint1. Unless fast.float_math is off, preint2 works in
// float as preint1 does (float_march.hpp, SecondOrderFloatLookup), unlit and
// lit in both modes, on packets of 8 rays where the CPU has AVX2.
#include <memory>
#include <optional>
#include <string>

#include "methods/fast_path.hpp"
#include "vri/methods.hpp"  // the constructors' types
#include "shading/headlight_shader.hpp"
#include "vri/lighting.hpp"
#include "tables/discrete_tf.hpp"
#include "tables/second_order_float_lookup.hpp"
#include "tables/second_order_table.hpp"
#include "tables/second_order_weighted.hpp"
#include "volume/float_sampler.hpp"
#include "vri/volume.hpp"

namespace vri {

namespace detail {
class FloatShading;  // src/methods/march/float_shading.hpp
}

// The second-order builder a MethodSpec's `builder` selects: itself when it
// names one (plain, fast), else fast (the first-order builders' names, such
// as the default incremental, do not apply to order 2).
std::string second_order_builder_name(const std::string& builder);

class Preint2Integrator final : public Integrator {
 public:
  // step h in voxel units (1e-4 .. 1e4; slabs are 2h long); the table has
  // table_size entries a side, each entry the parabola cut into `iterations`
  // chords (1 .. kMaxSecondOrderIterations), built by the named second-order
  // builder. Throws vri::Error for a lighting mode other than sampled or interpolated.
  Preint2Integrator(const GridVolume& volume, const TransferFunction& tf, double step, int table_size,
                    int iterations, const std::string& builder, const Lighting& lighting = {},
                    const FastPath& fast = {});
  ~Preint2Integrator() override;
  Rgba integrate(const Ray& ray) const override;
  // On the float path, on a CPU with AVX2: packets of 8 neighbouring
  // rays (float_packet.hpp), the same bytes as integrate.
  void integrate_row(const Ray* rays, int n, Rgba* out) const override;
  const Footprint* footprint() const override { return &fast_.footprint(); }
  std::string_view name() const override { return "preint2"; }

  // The unweighted table (weighted tables' `full` when interpolated).
  const SecondOrderTable& table() const;

 private:
  const GridVolume& volume_;
  double h_;  // world units
  DiscreteTf tf_;
  std::optional<SecondOrderTable> table_;              // unless interpolated
  std::optional<SecondOrderWeightedTables> weighted_;  // when lit and interpolated
  std::optional<HeadlightShader> shader_;              // when lit
  Skipping fast_;
  FloatSampler float_sampler_;
  std::optional<SecondOrderFloatLookup> float_table_;  // on the float path
  std::unique_ptr<detail::FloatShading> float_shading_;  // lit, on the float path
  bool packets_;                                       // integrate_row marches packets
};

// The registry's constructors (src/methods/method_registry.cpp): the integrator from
// a scene's method block.
std::unique_ptr<Integrator> make_preint2(const MethodSpec& spec, const GridVolume& volume, const TransferFunction& tf,
                                         const Lighting& lighting);
// On the GPU: make_vulkan_preint (preint1.hpp).

}  // namespace vri
