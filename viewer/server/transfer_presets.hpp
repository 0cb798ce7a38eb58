#pragma once
// The named transfer functions the page offers: the bundled presets/*.json,
// compiled into the binary, each as {"name", "transfer_function": {"points"}},
// and, for one volume, the named colour maps (vri/transfer_function.hpp) over
// its data range.
#include <nlohmann/json.hpp>

#include "vri/scene.hpp"

namespace vri::viewer {

// Read once; a preset that does not load is a build error caught by the tests.
const nlohmann::json& transfer_presets();

// The bundled presets, then "colormap: NAME" for each named colour map over
// the volume's data range, its opacity a ramp from 0 to the tau that stops
// half the light over a tenth of the box's diagonal (as the suggested
// transfer function of a bare volume does).
nlohmann::json transfer_presets(const Volume& volume);

}  // namespace vri::viewer
