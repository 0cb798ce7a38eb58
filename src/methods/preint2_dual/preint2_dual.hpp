#pragma once
// Preint2DualIntegrator (SPEC §9 `preint2-dual`): second-order pre-integration
// with samples on the dual-voxel (cell) faces, El Hajjar, Marchesin, Dischler
// & Mongenet 2008, Section 4. The ray is cut where it crosses cell faces
// (cell_traversal.hpp) and sampled at each crossing and at the midpoint of
// each crossing interval, so every slab lies inside one cell, where the
// trilinear signal is a true cubic, and the parabola through its front,
// middle and back samples (eq. 2) follows it closely. Slab lengths vary, so
// the lookups go to a SecondOrderLengthTable over (l, s_f, s_m, s_b) (the
// paper's 4D table, eq. 2-3): kLengths lengths from 0 to the longest in-cell
// chord, sqrt(3) times the largest grid spacing, linear in l between them.
//
// Memory: kLengths * table_size^3 RGBA float32 entries, 128 MiB at the
// default table_size 64; over kMaxSecondOrderEntries (1 GiB, table_size > 128)
// build_second_order_length_table refuses before building anything. The
// float path adds a bit per table spot (ZeroSpots, 32 KiB at 64) and, with
// skipping, a bit per cell of the non-empty macro cells (TransparentCells).
//
// Lighting (SPEC §5, as preint2): `sampled`, one normal per slab, the mean of
// the three samples' gradients; `interpolated`, the shading quadratic through
// the three samples, with the weighted tables of second_order_weighted.hpp at
// every length: 3x the memory, 384 MiB at the default table_size 64.
//
// Fast path (fast_path.hpp): segments in runs of empty macro cells (classified
// for second-order entries) are not sampled, which changes no byte; on the
// float path neither are the segments of transparent cells inside the
// others (TransparentCells, classified the same way), and lookups of spots
// whose entries are all zero read nothing (ZeroSpots); and
// `termination` stops a ray once T falls below it. `float_math` (the
// default) samples, looks up and shades in float and composites in double,
// unlit and lit (dual_march.hpp), on packets of 8 rays where the CPU has AVX2
// (float_packet_dual.cpp: the same bytes, faster, leaping over empty runs).
#include <memory>
#include <optional>
#include <string>

#include "methods/fast_path.hpp"
#include "vri/methods.hpp"  // the constructors' types
#include "shading/headlight_shader.hpp"
#include "vri/lighting.hpp"
#include "tables/discrete_tf.hpp"
#include "tables/second_order_table.hpp"
#include "tables/second_order_weighted.hpp"
#include "volume/float_sampler.hpp"
#include "vri/volume.hpp"
#include "volume/transparent_cells.hpp"

namespace vri {

namespace detail {
class DualFloatLookup;  // methods/preint2_dual/dual_march.hpp
class FloatShading;     // methods/march/float_shading.hpp
struct Leap;            // methods/march/ray_steps.hpp
}

class Preint2DualIntegrator final : public Integrator {
 public:
  static constexpr int kDefaultTableSize = 64;
  static constexpr int kLengths = 32;
  // The table's longest slab: the longest chord of a cell, sqrt(3) times the
  // largest grid spacing.
  static double max_slab_length(const GridVolume& volume);

  // Throws vri::Error when the table would exceed kMaxSecondOrderEntries or
  // the iterations are out of range (see preint2.hpp for the builder), or for
  // a lighting mode other than sampled or interpolated.
  Preint2DualIntegrator(const GridVolume& volume, const TransferFunction& tf, int table_size, int iterations,
                        const std::string& builder, const Lighting& lighting = {}, const FastPath& fast = {});
  ~Preint2DualIntegrator() override;
  Rgba integrate(const Ray& ray) const override;
  void integrate_row(const Ray* rays, int n, Rgba* out) const override;
  const Footprint* footprint() const override { return &fast_.footprint(); }
  std::string_view name() const override { return "preint2-dual"; }

  // The unweighted table (the weighted tables' `full` when interpolated).
  const SecondOrderLengthTable& table() const;

 private:
  const GridVolume& volume_;
  std::optional<HeadlightShader> shader_;                   // when lit
  DiscreteTf tf_;
  Skipping fast_;
  std::optional<SecondOrderLengthTable> table_;             // unless interpolated
  std::optional<SecondOrderWeightedLengthTables> weighted_;  // when lit and interpolated
  FloatSampler float_sampler_;
  std::unique_ptr<detail::DualFloatLookup> float_table_;     // the float path
  std::unique_ptr<detail::FloatShading> float_shading_;      // the float path, lit
  bool packets_ = false;                                     // integrate_row marches packets (float path)
  std::optional<TransparentCells> transparent_;              // the float path, with skipping
  detail::Leap leap() const;
};

// The registry's constructors (src/methods/method_registry.cpp): the integrator (table_size 64 unless the scene names one) from
// a scene's method block, and its GPU renderer (vulkan_preint2_dual.cpp, Vulkan builds only).
std::unique_ptr<Integrator> make_preint2_dual(const MethodSpec& spec, const GridVolume& volume, const TransferFunction& tf,
                                              const Lighting& lighting);
std::unique_ptr<GpuSceneRenderer> make_vulkan_preint2_dual(const Scene& scene);

}  // namespace vri
