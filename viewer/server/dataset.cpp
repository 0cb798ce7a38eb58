#include "dataset.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include "core/json_support.hpp"
#include "scene/scene_json.hpp"
#include "scene/volume_scene.hpp"
#include "vri/camera.hpp"
#include "vri/error.hpp"
#include "vri/volume.hpp"

namespace vri::viewer {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw FileError("cannot read '" + printable(file.string()) + "'");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every "file" inside the volume block made absolute: the saved scene works from anywhere.
void absolute_files(json& j, const fs::path& base) {
  if (j.is_object()) {
    for (auto& [key, value] : j.items()) {
      if (key == "file" && value.is_string()) {
        const fs::path p = value.get<std::string>();
        value = fs::absolute(p.is_relative() ? base / p : p).lexically_normal().string();
      } else {
        absolute_files(value, base);
      }
    }
  } else if (j.is_array()) {
    for (auto& v : j) absolute_files(v, base);
  }
}

// The page's view of the volume: what it is, its range and box, the unit of the opacity axis.
json describe(const Dataset& d, const Histogram& h) {
  const auto [lo, hi] = bounds(d.volume);
  json v = {{"name", d.id},
            {"range", {h.lo, h.hi}},
            {"bounds", {{lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z}}},
            {"json", d.volume_json}};
  if (const auto* g = std::get_if<GridVolume>(&d.volume)) {
    v["kind"] = "grid";
    v["dims"] = g->dims();
    v["unit_distance"] = g->voxel_unit();
  } else {
    const TetMesh& m = std::get<TetMesh>(d.volume);
    v["kind"] = "mesh";
    v["cells"] = m.tets().size();
    // A mesh has no voxel: the edge of a cube of the mean cell volume.
    const Vec3 e = hi - lo;
    v["unit_distance"] = std::cbrt(std::max(e.x * e.y * e.z, 1e-300) / double(m.tets().size()));
  }
  return {{"volume", v}, {"histogram", {{"range", {h.lo, h.hi}}, {"counts", h.counts}}}};
}

}  // namespace

std::shared_ptr<const Dataset> load_dataset(const fs::path& file, const std::string& id) {
  const fs::path base = fs::absolute(file).parent_path();
  std::string source = "'";  // appended, not "'" + ... (GCC 12's -Wrestrict misfires on that)
  source.append(printable(file.string())).append("'");
  json scene, volume_json;
  std::optional<Volume> volume;
  std::optional<Histogram> h;  // one pass over the samples, for the description and a bare volume's scene
  if (file.extension() == ".json") {
    const std::string text = read_text(file);
    if (json_depth(text) > kMaxJsonDepth)
      throw Error("scene " + source + ": JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    scene = json::parse(text, nullptr, false);
    if (!scene.is_object() || !scene.contains("volume"))
      throw Error("scene " + source + ": not a scene file (a JSON object with a 'volume')");
    Scene loaded = load_scene(file);  // every check `vri render` makes
    volume.emplace(std::move(loaded.volume));
    volume_json = scene.at("volume");
    absolute_files(volume_json, base);
    scene.erase("volume");
    scene["transfer_function"] = transfer_function_json(loaded.transfer_function);
    scene["camera"] = camera_json(loaded.camera);
    scene["lighting"] = lighting_json(loaded.lighting);
    scene["background"] = {loaded.background.x, loaded.background.y, loaded.background.z};
    // `exact` (named, or the default of a scene that names no method, SPEC §9)
    // takes seconds a frame: the viewer opens such a scene with the fast method
    // of its kind, and renders exact in the background as the error map's
    // reference and the refinement.
    if (loaded.method.name == "exact") scene["method"] = default_method_json(*volume);
  } else {
    volume_json = {{"file", fs::absolute(file).lexically_normal().string()}};
    volume.emplace(load_volume(file));
    h = histogram(*volume);
    scene = volume_scene_json(*volume, {}, &*h);  // as `vri render VOLUME` sees it
    scene["lighting"] = lighting_json(Lighting{});
    scene["background"] = {0, 0, 0};
  }
  auto d = std::make_shared<Dataset>(Dataset{id, base, std::move(*volume), std::move(volume_json), std::move(scene), {}});
  if (!h) h = histogram(d->volume);
  d->description = describe(*d, *h);
  return d;
}

DatasetCatalog::DatasetCatalog(const fs::path& given, const fs::path& bundled_dir) {
  if (!given.empty()) entries_.push_back({given.stem().string(), given, nullptr});
  std::error_code ec;
  std::vector<fs::path> bundled;
  if (!bundled_dir.empty() && fs::is_directory(bundled_dir, ec))
    for (const auto& e : fs::directory_iterator(bundled_dir, ec))
      if (e.path().extension() == ".json") bundled.push_back(e.path());
  std::sort(bundled.begin(), bundled.end());
  for (const fs::path& p : bundled) {
    if (!given.empty() && fs::equivalent(p, given, ec)) continue;
    std::string id = p.stem().string();
    while (std::any_of(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.id == id; })) id += "_";
    entries_.push_back({id, p, nullptr});
  }
  if (entries_.empty()) throw Error("no volume to show: give a scene or volume file");
}

json DatasetCatalog::list() const {
  json out = json::array();
  for (const Entry& e : entries_) out.push_back({{"id", e.id}, {"name", e.id}});
  return out;
}

const std::string& DatasetCatalog::first_id() const { return entries_.front().id; }

std::shared_ptr<const Dataset> DatasetCatalog::open(const std::string& id) {
  std::lock_guard lock(mutex_);
  for (Entry& e : entries_)
    if (e.id == id) {
      if (!e.loaded) e.loaded = load_dataset(e.file, e.id);
      return e.loaded;
    }
  throw Error("no dataset '" + printable(id) + "' in the list");
}

}  // namespace vri::viewer
