#pragma once
// Preint1Integrator (SPEC §9 `preint1`): first-order pre-integrated ray
// casting (Engel, Kraus & Ertl 2001). Samples at t_k = t0 + k h; the slab
// between two samples is one lookup of a PreintegrationTable for length h at
// (s_k, s_{k+1}), and each back sample is the next slab's front sample. The
// last, partial slab of length r = (t1 - t0) - N h < h is integrated exactly
// under the table's own discretisation (exact_slab): a dedicated lookup
// instead of a table with lengths, so it costs O(pieces crossed) once per ray
// and adds no interpolation error in the length.
//
// Lighting (SPEC §5, `lighting.mode`): `sampled` lights each slab's
// pre-integrated colour with one normal, the mean of its two samples'
// gradients; `interpolated` (Lum, Wilson & Ma 2004) interpolates the shading
// across the slab with the weighted tables of tables/weighted_tables.hpp.
//
// FastPath (fast_path.hpp): the ray leaps over runs of empty macro cells from
// sample to sample (whole steps, so on the same samples): every slab inside a
// run reads zero table entries. It may stop once T < termination. Unless
// fast.float_math is off it works in float, unlit and lit in both modes
// (float_march.hpp, float_shading.hpp), on packets of 8 rays with AVX2.
#include <memory>
#include <optional>
#include <string>

#include "methods/fast_path.hpp"
#include "vri/methods.hpp"  // the constructors' types
#include "shading/headlight_shader.hpp"
#include "vri/lighting.hpp"
#include "tables/discrete_tf.hpp"
#include "tables/float_lookup.hpp"
#include "tables/preintegration_table.hpp"
#include "tables/weighted_tables.hpp"
#include "volume/float_sampler.hpp"
#include "vri/volume.hpp"

namespace vri {

namespace detail {
class FloatShading;  // src/methods/march/float_shading.hpp
}

class Preint1Integrator final : public Integrator {
 public:
  // step in voxel units (1e-4 .. 1e4); the table has table_size entries a side
  // and is built with the named builder (table_builder.hpp). Throws
  // vri::Error for a lighting mode other than sampled or interpolated.
  Preint1Integrator(const GridVolume& volume, const TransferFunction& tf, double step, int table_size,
                    const std::string& builder, const Lighting& lighting = {}, const FastPath& fast = {});
  ~Preint1Integrator() override;
  Rgba integrate(const Ray& ray) const override;
  // On the float path, on a CPU with AVX2: packets of 8 neighbouring
  // rays (float_packet.hpp), the same bytes as integrate.
  void integrate_row(const Ray* rays, int n, Rgba* out) const override;
  const Footprint* footprint() const override { return &fast_.footprint(); }
  std::string_view name() const override { return "preint1"; }

  const PreintegrationTable& table() const { return table_; }

 private:
  const GridVolume& volume_;
  double h_;  // world units
  DiscreteTf tf_;
  PreintegrationTable table_;
  std::optional<HeadlightShader> shader_;     // when lit
  std::optional<WeightedTables> weighted_;    // when lit and interpolated
  Skipping fast_;
  bool float_math_;
  FloatSampler float_sampler_;
  FloatLookup float_table_;
  std::unique_ptr<detail::FloatShading> float_shading_;  // lit, on the float path
  bool packets_;  // integrate_row marches packets
};

// The registry's constructors (src/methods/method_registry.cpp): the integrator from
// a scene's method block, and its GPU renderer (vulkan_preint.cpp, for preint1 and preint2, Vulkan builds only).
std::unique_ptr<Integrator> make_preint1(const MethodSpec& spec, const GridVolume& volume, const TransferFunction& tf,
                                         const Lighting& lighting);
std::unique_ptr<GpuSceneRenderer> make_vulkan_preint(const Scene& scene);

}  // namespace vri
