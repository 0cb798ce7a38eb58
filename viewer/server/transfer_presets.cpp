#include "transfer_presets.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "embedded_files.hpp"
#include "scene/scene_json.hpp"
#include "vri/transfer_function.hpp"

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

nlohmann::json transfer_presets(const Volume& volume) {
  nlohmann::json list = transfer_presets();
  const auto [lo, hi] = bounds(volume);
  const double tau = std::log(2.0) / (0.1 * std::max(length(hi - lo), 1e-9));
  for (const std::string& name : colormap_names()) {
    const nlohmann::json tf = {{"colormap", name}, {"range", "data"}, {"opacity", {{0, 0}, {1, tau}}}};
    list.push_back({{"name", "colormap: " + name},
                    {"transfer_function",
                     transfer_function_json(parse_transfer_function(tf.dump(), "colormap " + name, &volume))}});
  }
  return list;
}

}  // namespace vri::viewer
