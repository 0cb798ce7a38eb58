#pragma once
// A volume standing where a scene does (SPEC §12: `vri render VOLUME`,
// `vri view VOLUME`): the scene JSON without its "volume", as the viewer
// sends it to its page and volume_scene() reads it. Inside the project only
// (nlohmann_json stays out of the installed headers).
#include <nlohmann/json.hpp>

#include "vri/scene.hpp"

namespace vri {

// {"transfer_function", "camera", "method"} of `volume` seen as `look` says
// (vri/scene.hpp, VolumeLook); vri::Error naming the flag for a bad value.
// `histogram`: the volume's 256-bin histogram where the caller has made it
// (the viewer describes the volume with it), else made here.
nlohmann::json volume_scene_json(const Volume& volume, const VolumeLook& look = {},
                                 const Histogram* histogram = nullptr);

// The method a volume of this kind opens with: interactive and accurate
// (preint1 at step 1 on grids, tet-raycast on meshes).
nlohmann::json default_method_json(const Volume& volume);

}  // namespace vri
