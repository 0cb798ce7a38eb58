#include "transfer_presets.hpp"

#include <string>

#include "embedded_files.hpp"
#include "scene_json.hpp"
#include "vri/scene/scene.hpp"

namespace vri::viewer {

const nlohmann::json& transfer_presets() {
  static const nlohmann::json presets = [] {
    nlohmann::json list = nlohmann::json::array();
    for (const EmbeddedFile& f : preset_files()) {
      const std::string name(f.name.substr(0, f.name.rfind('.')));
      const TransferFunction tf = parse_transfer_function(f.content, "preset '" + name + "'");
      list.push_back({{"name", name}, {"transfer_function", transfer_function_json(tf)}});
    }
    return list;
  }();
  return presets;
}

}  // namespace vri::viewer
