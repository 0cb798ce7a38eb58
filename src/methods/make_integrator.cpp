#include "vri/methods.hpp"
#include "methods/mesh_tables.hpp"

#include <algorithm>
#include <optional>
#include <string>

#include "vri/error.hpp"  // format_g
#include "tables/table_builder.hpp"
#include "tables/weighted_tables.hpp"

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

void check_mesh_termination(const MethodSpec& spec) {
  if (spec.fast.termination != 0)
    throw Error(spec.name + ": early ray termination is not supported on tetrahedral meshes yet");
}

std::unique_ptr<Integrator> make_integrator(const MethodSpec& spec, const GridVolume& volume,
                                            const TransferFunction& tf, const Lighting& lighting) {
  check_volume_kind(spec, false);
  check_termination(spec);
  check_jitter(spec);
  const MethodInfo& m = known_method(spec.name);
  if (!m.make_grid) throw Error("method '" + spec.name + "' is in the method registry without a grid integrator");
  return m.make_grid(spec, volume, tf, lighting);
}

std::unique_ptr<Integrator> make_integrator(const MethodSpec& spec, const TetMesh& mesh,
                                            const TransferFunction& tf, const Lighting& lighting) {
  check_volume_kind(spec, true);
  const MethodInfo& m = known_method(spec.name);
  if (!m.per_ray)
    throw Error("method '" + spec.name + "' projects whole tetrahedra; it has no per-ray integrator");
  check_jitter(spec);
  check_mesh_termination(spec);
  if (!m.make_mesh) throw Error("method '" + spec.name + "' is in the method registry without a mesh integrator");
  return m.make_mesh(spec, mesh, tf, lighting);
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
  const auto builder = make_table_builder(spec.builder);
  // Before anything is built (issue 47): a builder of O(n^3) work, one table
  // per length, runs for minutes at sizes that fit in memory.
  const DiscreteTf discrete(tf, spec.table_size, scalar_range(mesh));
  const double work = builder->length_table_work(discrete, spec.length_samples, mesh.max_edge_length());
  if (work > spec.max_work)
    throw Error("'" + spec.name + "': the (l, s_f, s_b) table by builder '" + std::string(builder->name()) +
                "' takes about " + format_g(work) + " evaluations (" + std::to_string(spec.length_samples - 1) +
                " lengths of " + std::to_string(spec.table_size) + "^2 entries), over the cap of " +
                format_g(spec.max_work) + "; raise it with --max-work N (scene method.max_work), or use a smaller "
                "table_size or length_samples, or builder incremental");
  return std::make_unique<LengthTable>(
      build_length_table(*builder, discrete, spec.length_samples, mesh.max_edge_length()));
}

std::unique_ptr<WeightedLengthTables> make_weighted_length_tables(const MethodSpec& spec, const TetMesh& mesh,
                                                                  const TransferFunction& tf,
                                                                  const Lighting& lighting) {
  if (!lighting.enabled || lighting.mode != "interpolated") return nullptr;
  return std::make_unique<WeightedLengthTables>(
      build_weighted_length_tables(DiscreteTf(tf, spec.table_size, scalar_range(mesh)), spec.length_samples, mesh.max_edge_length()));
}

}  // namespace vri
