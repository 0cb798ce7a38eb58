#include "vri/core/error.hpp"
#include "vri/scene/scene.hpp"

namespace vri {

const GridVolume& Scene::grid() const {
  if (const auto* g = std::get_if<GridVolume>(&volume)) return *g;
  throw Error("this scene's volume is a tetrahedral mesh, not a regular grid");
}

const TetMesh& Scene::mesh() const {
  if (const auto* m = std::get_if<TetMesh>(&volume)) return *m;
  throw Error("this scene's volume is a regular grid, not a tetrahedral mesh");
}

}  // namespace vri
