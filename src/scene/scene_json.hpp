#pragma once
// Scene parts as the scene file writes them (SPEC §3, §5, §6): every key
// given, so the viewer's page can edit any of them and send the scene back,
// and `vri camera` prints a fitted camera as a scene holds it. Inside the
// project only (nlohmann_json stays out of the installed headers).
#include <nlohmann/json.hpp>

#include "vri/camera.hpp"
#include "vri/lighting.hpp"
#include "vri/transfer_function.hpp"

namespace vri {

nlohmann::json camera_json(const CameraSpec& camera);
nlohmann::json lighting_json(const Lighting& lighting);
// {"points": [[s, r, g, b, tau], ...]}: the loaded points (after any opacity
// conversion and merging), which read back to the same function.
nlohmann::json transfer_function_json(const TransferFunction& tf);

}  // namespace vri
