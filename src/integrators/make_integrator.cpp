#include "vri/integrators/make_integrator.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include "vri/core/error.hpp"
#include "vri/integrators/adaptive_guaranteed.hpp"
#include "vri/integrators/adaptive_simpson.hpp"
#include "vri/integrators/exact.hpp"
#include "vri/integrators/mesh_exact.hpp"
#include "vri/integrators/preint1.hpp"
#include "vri/integrators/preint2.hpp"
#include "vri/integrators/preint2_dual.hpp"
#include "vri/integrators/tet_raycast.hpp"
#include "vri/tables/table_builder.hpp"
#include "vri/tables/weighted_tables.hpp"
#include "vri/integrators/riemann.hpp"
#include "vri/methods.hpp"

namespace vri {

void check_volume_kind(const MethodSpec& spec, bool mesh) {
  const MethodInfo& m = known_method(spec.name);
  if (!mesh && !m.grid)
    throw Error("method '" + spec.name + "' needs a tetrahedral mesh (volume {\"file\": \"x.vtk\"} or " +
                "{\"builtin\": \"tetrahedralized\", ...})");
  if (mesh && !m.mesh)
    throw Error("method '" + spec.name + "' works on regular grids only; for a tetrahedral mesh use " +
                method_names([](const MethodInfo& i) { return i.mesh; }, "or"));
}

void check_jitter(const MethodSpec& spec) {
  if (spec.jitter && !known_method(spec.name).jitter)
    throw Error(spec.name + ": jitter applies to " + method_names([](const MethodInfo& m) { return m.jitter; }) +
                " only (the pre-integrated methods integrate between their "
                "samples, so their rings are faint; exact and adaptive place no fixed samples)");
}

void check_termination(const MethodSpec& spec) {
  if (spec.fast.termination != 0 && !known_method(spec.name).termination)
    throw Error(spec.name + ": early ray termination is not supported yet; it works in " +
                method_names([](const MethodInfo& m) { return m.termination; }));
}

std::unique_ptr<Integrator> make_integrator(const MethodSpec& spec, const GridVolume& volume,
                                            const TransferFunction& tf, const Lighting& lighting) {
  check_volume_kind(spec, false);
  check_termination(spec);
  if (spec.name == "riemann")
    return std::make_unique<RiemannIntegrator>(volume, tf, spec.step, lighting, spec.fast, spec.jitter);
  check_jitter(spec);
  if (spec.name == "preint1")
    return std::make_unique<Preint1Integrator>(volume, tf, spec.step, spec.table_size, spec.builder, lighting,
                                               spec.fast);
  if (spec.name == "preint2")
    return std::make_unique<Preint2Integrator>(volume, tf, spec.step, spec.table_size, spec.iterations,
                                               second_order_builder_name(spec.builder), lighting, spec.fast);
  if (spec.name == "preint2-dual") {
    const int size = spec.table_size_given ? spec.table_size : Preint2DualIntegrator::kDefaultTableSize;
    return std::make_unique<Preint2DualIntegrator>(volume, tf, size, spec.iterations,
                                                   second_order_builder_name(spec.builder), lighting, spec.fast);
  }
  if (spec.name == "adaptive") {
    const AdaptiveParams p{spec.tolerance, spec.h0, spec.hmin, spec.hmax,
                           parse_adaptive_strategy(spec.strategy)};
    if (p.strategy == AdaptiveStrategy::Guaranteed)
      return std::make_unique<GuaranteedAdaptiveIntegrator>(volume, tf, p, lighting);
    return std::make_unique<AdaptiveSimpsonIntegrator>(volume, tf, p, lighting, spec.fast);
  }
  if (spec.name == "exact") return std::make_unique<ExactIntegrator>(volume, tf, spec.tolerance, lighting);
  throw Error("method '" + spec.name + "' is in the method registry but make_integrator does not construct it");
}

std::unique_ptr<Integrator> make_integrator(const MethodSpec& spec, const TetMesh& mesh,
                                            const TransferFunction& tf, const Lighting& lighting) {
  check_volume_kind(spec, true);
  if (!known_method(spec.name).per_ray)
    throw Error("method '" + spec.name + "' projects whole tetrahedra; it has no per-ray integrator");
  check_jitter(spec);
  if (spec.fast.termination != 0)
    throw Error(spec.name + ": early ray termination is not supported on tetrahedral meshes yet");
  if (spec.name == "exact") return std::make_unique<MeshExactIntegrator>(mesh, tf, spec.tolerance, lighting);
  if (spec.name == "tet-raycast")
    return std::make_unique<TetRaycastIntegrator>(mesh, make_slab_table(spec, mesh, tf), lighting,
                                                  make_weighted_length_tables(spec, mesh, tf, lighting));
  throw Error("method '" + spec.name + "' is in the method registry but make_integrator does not construct it");
}

namespace {

// The mesh's scalars, which its tables must cover (table_axis).
std::optional<DataRange> scalar_range(const TetMesh& mesh) {
  const auto [lo, hi] = std::minmax_element(mesh.scalars().begin(), mesh.scalars().end());
  if (lo == mesh.scalars().end()) return std::nullopt;
  return DataRange{*lo, *hi};
}

}  // namespace

std::unique_ptr<SlabTable> make_slab_table(const MethodSpec& spec, const TetMesh& mesh, const TransferFunction& tf) {
  const DiscreteTf discrete(tf, spec.table_size, scalar_range(mesh));
  return std::make_unique<LengthTable>(
      build_length_table(*make_table_builder(spec.builder), discrete, spec.length_samples, mesh.max_edge_length()));
}

std::unique_ptr<WeightedLengthTables> make_weighted_length_tables(const MethodSpec& spec, const TetMesh& mesh,
                                                                  const TransferFunction& tf,
                                                                  const Lighting& lighting) {
  if (!lighting.enabled || lighting.mode != "interpolated") return nullptr;
  return std::make_unique<WeightedLengthTables>(
      build_weighted_length_tables(DiscreteTf(tf, spec.table_size, scalar_range(mesh)), spec.length_samples, mesh.max_edge_length()));
}

}  // namespace vri
