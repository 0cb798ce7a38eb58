#include "scene/volume_scene.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <variant>

#include "scene/scene_json.hpp"
#include "vri/camera.hpp"
#include "vri/error.hpp"

namespace vri {

using nlohmann::json;

namespace {

// --range: "data", "pLO,pHI" (percentiles) or "LO,HI", as a transfer
// function's "range" (docs/SCENES.md).
json range_json(const std::string& text) {
  if (text == "data") return "data";
  const bool percentiles = !text.empty() && text[0] == 'p';
  double lo = 0, hi = 0;
  char tail = 0;
  const std::string numbers = percentiles ? text.substr(1) : text;
  const std::string format = percentiles ? "%lf,p%lf%c" : "%lf,%lf%c";
  if (std::sscanf(numbers.c_str(), format.c_str(), &lo, &hi, &tail) != 2 || !std::isfinite(lo) || !std::isfinite(hi))
    throw Error("--range: expected data, pLO,pHI (percentiles, such as p1,p99) or LO,HI, found '" + text + "'");
  if (percentiles) return {{"percentiles", {lo, hi}}};
  return {lo, hi};
}

// --opacity: tau over the range's fractions x, up to `top` (the suggested
// function's largest: half the light stopped over a tenth of the box's diagonal).
json opacity_json(const std::string& shape, double top) {
  if (shape == "ramp") return {{0, 0}, {1, top}};
  if (shape != "sigmoid") throw Error("--opacity: expected ramp or sigmoid, found '" + shape + "'");
  json curve = json::array();
  for (int i = 0; i <= 16; ++i) {  // a logistic step centred on the range, 17 points
    const double x = i / 16.0;
    curve.push_back({x, top / (1 + std::exp(-12 * (x - 0.5)))});
  }
  return curve;
}

}  // namespace

json default_method_json(const Volume& volume) {
  return std::holds_alternative<GridVolume>(volume) ? json{{"name", "preint1"}, {"step", 1}}
                                                    : json{{"name", "tet-raycast"}};
}

json volume_scene_json(const Volume& volume, const VolumeLook& look, const Histogram* given) {
  const auto [lo, hi] = bounds(volume);
  const TransferFunction suggested = suggest_transfer_function(given ? *given : histogram(volume), length(hi - lo));
  json tf;
  if (look.colormap.empty() && look.opacity.empty()) {
    tf = transfer_function_json(suggested);  // `vri info`'s
  } else {
    tf = {{"colormap", look.colormap.empty() ? "cool_to_warm" : look.colormap},
          {"opacity", opacity_json(look.opacity.empty() ? "ramp" : look.opacity, suggested.points().back().tau)}};
  }
  if (!look.range.empty()) tf["range"] = range_json(look.range);
  return {{"transfer_function", tf}, {"camera", camera_json(frame_box(lo, hi))}, {"method", default_method_json(volume)}};
}

Scene volume_scene(Volume volume, const VolumeLook& look) {
  const std::string text = volume_scene_json(volume, look).dump();
  return parse_scene(text, std::move(volume), ".", "volume");
}

bool is_volume_file(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  std::ifstream in(path, std::ios::binary);
  char c = 0;
  while (in.get(c))
    if (!std::isspace(static_cast<unsigned char>(c))) return c != '{';
  return true;  // empty or blank: the volume readers say what it lacks
}

}  // namespace vri
