#pragma once
// Dataset: one volume the viewer can show - loaded once, shared by every
// client - with the scene it opens with, its histogram and the description
// the page gets. DatasetCatalog: the datasets a client may open (the file
// `vri view` was given and the bundled scenes), by id, never by path.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "vri/scene.hpp"

namespace vri::viewer {

struct Dataset {
  std::string id;
  std::filesystem::path base_dir;  // where the scene's relative paths resolve
  Volume volume;                   // grid samples are shared by copies
  nlohmann::json volume_json;      // the scene's "volume" block, paths absolute
  nlohmann::json scene_json;       // the scene without "volume", transfer function as points
  nlohmann::json description;      // "volume" and "histogram" of the welcome message
};

// A scene file (.json) with its own camera, transfer function and method, or
// a volume file (.nrrd, .dat, .vtk, .vtu) shown with a default scene: a grey
// ramp over the data range, a camera that frames the volume, `preint1` at
// step 1 (grids) or `tet-raycast` (meshes). vri::Error with one line if the
// file cannot be read.
std::shared_ptr<const Dataset> load_dataset(const std::filesystem::path& file, const std::string& id);


class DatasetCatalog {
 public:
  // `given`: the file `vri view` was started with (may be empty); `bundled_dir`: a
  // folder of bundled scenes (*.json; may be missing). The first dataset is the given
  // file, else the first bundled scene.
  DatasetCatalog(const std::filesystem::path& given, const std::filesystem::path& bundled_dir);

  // [{"id", "name"}] in the order shown.
  nlohmann::json list() const;
  const std::string& first_id() const;
  // The dataset, loaded on first use; vri::Error for an id not in the list.
  std::shared_ptr<const Dataset> open(const std::string& id);

 private:
  struct Entry {
    std::string id;
    std::filesystem::path file;
    std::shared_ptr<const Dataset> loaded;
  };
  std::vector<Entry> entries_;
  std::mutex mutex_;  // clients open datasets from their own workers
};

}  // namespace vri::viewer
