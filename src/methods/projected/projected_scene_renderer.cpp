#include "projected_scene_renderer.hpp"

#include <optional>

#include "methods/mesh_tables.hpp"
#include "projected_tetrahedra.hpp"

namespace vri {

namespace {

class ProjectedTetrahedraRenderer final : public ProjectedSceneRenderer {
 public:
  ProjectedTetrahedraRenderer(const Scene& scene, bool cylindrical)
      : mesh_(scene.mesh()),
        lighting_(scene.lighting),
        table_(make_slab_table(scene.method, mesh_, scene.transfer_function)),
        weighted_(make_weighted_length_tables(scene.method, mesh_, scene.transfer_function, scene.lighting)) {
    if (!cylindrical) return;
    const int size = scene.method.table_size, planes = scene.method.planes > 0 ? scene.method.planes : size;
    cylinder_.emplace(*table_, size, planes);
    if (weighted_)
      weighted_cylinder_.emplace(CylindricalTable(weighted_->front, size, planes),
                                 CylindricalTable(weighted_->back, size, planes));
  }

  Image render(const Camera& camera, const RenderOptions& options) const override {
    if (cylinder_)
      return render_projected(camera, mesh_, *cylinder_, options, lighting_,
                              weighted_cylinder_ ? &*weighted_cylinder_ : nullptr);
    return render_projected(camera, mesh_, *table_, options, lighting_, weighted_.get());
  }

 private:
  const TetMesh& mesh_;  // the scene's, which outlives this (SceneRenderer holds both)
  Lighting lighting_;
  std::unique_ptr<SlabTable> table_;
  std::unique_ptr<WeightedLengthTables> weighted_;  // lighting mode interpolated
  std::optional<CylindricalTable> cylinder_;        // pt-cylindrical
  std::optional<WeightedCylindricalTables> weighted_cylinder_;
};

}  // namespace

std::unique_ptr<ProjectedSceneRenderer> make_pt(const Scene& scene) {
  return std::make_unique<ProjectedTetrahedraRenderer>(scene, false);
}

std::unique_ptr<ProjectedSceneRenderer> make_pt_cylindrical(const Scene& scene) {
  return std::make_unique<ProjectedTetrahedraRenderer>(scene, true);
}

}  // namespace vri
