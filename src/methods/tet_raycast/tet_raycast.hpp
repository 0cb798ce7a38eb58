#pragma once
// TetRaycastIntegrator (SPEC §9 `tet-raycast`): the cell-to-cell walk of the
// mesh `exact` (TetWalk), with each tetrahedron's piece looked up in an
// (l, s_f, s_b) table instead of integrated (Roettger & Ertl 2002, Sec. 3:
// the segment inside a tetrahedron is fully described by s_f, s_b and l), and
// composited front to back: C += T C_seg, T *= 1 - alpha_seg.
// Lit: each piece is lit by ChordLighting, with one normal (mode `sampled`) or
// with the shading at its entry and exit weighting the weighted tables (mode
// `interpolated`, Lum, Wilson & Ma 2004).
#include <memory>
#include <optional>

#include "vri/methods.hpp"  // the constructors' types
#include "mesh/tet_walk.hpp"
#include "shading/chord_lighting.hpp"
#include "tables/slab_table.hpp"
#include "tables/weighted_tables.hpp"

namespace vri {

class TetRaycastIntegrator final : public Integrator {
 public:
  // The tables must cover segments up to mesh.max_edge_length() (vri::Error
  // otherwise); `weighted` is needed for lighting mode interpolated only.
  TetRaycastIntegrator(const TetMesh& mesh, std::unique_ptr<const SlabTable> table, const Lighting& lighting = {},
                       std::unique_ptr<const WeightedLengthTables> weighted = nullptr);
  Rgba integrate(const Ray& ray) const override;
  std::string_view name() const override { return "tet-raycast"; }

 private:
  TetWalk walk_;
  std::unique_ptr<const SlabTable> table_;
  std::unique_ptr<const WeightedLengthTables> weighted_;
  std::optional<ChordLighting> lighting_;
};

// The registry's constructors (src/methods/method_registry.cpp): the
// integrator from a scene's method block, with its tables
// (methods/mesh_tables.hpp), and its GPU renderer (vulkan_tet_raycast.cpp,
// Vulkan builds only).
std::unique_ptr<Integrator> make_tet_raycast(const MethodSpec& spec, const TetMesh& mesh, const TransferFunction& tf,
                                             const Lighting& lighting);
std::unique_ptr<GpuSceneRenderer> make_vulkan_tet_raycast(const Scene& scene);

}  // namespace vri
