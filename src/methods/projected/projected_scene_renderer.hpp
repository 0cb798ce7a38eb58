#pragma once
// pt and pt-cylindrical as the registry makes them (MethodInfo::make_projected):
// the scene's tables built once - the (l, s_f, s_b) slab table, its weighted
// pair when lit `interpolated`, and for pt-cylindrical their cylindrical form
// (Roettger & Ertl 2002, §4) - then each camera's image by render_projected.
#include <memory>

#include "vri/render.hpp"

namespace vri {

std::unique_ptr<ProjectedSceneRenderer> make_pt(const Scene& scene);
std::unique_ptr<ProjectedSceneRenderer> make_pt_cylindrical(const Scene& scene);

}  // namespace vri
