#pragma once
// The named transfer functions the page offers: the bundled presets/*.json,
// compiled into the binary, each as {"name", "transfer_function": {"points"}}.
#include <nlohmann/json.hpp>

namespace vri::viewer {

// Read once; a preset that does not load is a build error caught by the tests.
const nlohmann::json& transfer_presets();

}  // namespace vri::viewer
