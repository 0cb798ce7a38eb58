#pragma once
// Scene parts as the scene file writes them (SPEC §3, §5, §6), for the page:
// every key given, so it can edit any of them and send the scene back.
#include <nlohmann/json.hpp>

#include "vri/camera/camera.hpp"
#include "vri/shading/lighting.hpp"
#include "vri/transfer/transfer_function.hpp"

namespace vri::viewer {

nlohmann::json camera_json(const CameraSpec& camera);
nlohmann::json lighting_json(const Lighting& lighting);
// {"points": [[s, r, g, b, tau], ...]}: the loaded points (after any opacity
// conversion and merging), which read back to the same function.
nlohmann::json transfer_function_json(const TransferFunction& tf);

}  // namespace vri::viewer
