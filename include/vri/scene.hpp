#pragma once
// vri/scene.hpp: the scene file of SPEC §5 as a value, and the command line's overrides of it.

#include <array>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <cstdint>
#include <optional>

#include "vri/camera.hpp"
#include "vri/methods.hpp"
#include "vri/volume.hpp"
#include "vri/lighting.hpp"
#include "vri/transfer_function.hpp"

// ---- scene -----------------------------------------------------------------
// Scene: everything one render needs (SPEC §8), loaded from a JSON file.

namespace vri {

// What a scene renders: a regular grid (SPEC §1) or a tetrahedral mesh (§2).
using Volume = std::variant<GridVolume, TetMesh>;

struct Scene {
  Volume volume;
  TransferFunction transfer_function;
  CameraSpec camera;
  Lighting lighting;
  Vec3 background{0, 0, 0};
  MethodSpec method;

  // The volume as one kind; vri::Error naming both kinds if it is the other.
  const GridVolume& grid() const;
  const TetMesh& mesh() const;
  // The scene's "clip" (SPEC §12), which its volume holds.
  const ClipRegion& clip() const;
};

// Sets the region a volume's rays are cut to (GridVolume::set_clip,
// TetMesh::set_clip): a scene's "clip", or a caller's override.
void set_clip(Volume& volume, ClipRegion clip);

// A volume file on its own (any format volume_file.hpp tells apart but raw,
// which needs dims and type: a scene gives them); `scalars` names the array of
// a VTK file. vri::Error with one line as in a scene.
Volume load_volume(const std::filesystem::path& file, const std::string& scalars = "");

// A volume standing where a scene does (SPEC §12: `vri render VOLUME`,
// `vri view VOLUME`; docs/SCENES.md): the transfer function `vri info`
// suggests - or, with a colour map or an opacity shape, that colour map
// (default cool_to_warm, ParaView's) under a `ramp` or `sigmoid` extinction
// up to the suggested function's largest - over `range` ("data",
// "pLO,pHI" percentiles or "LO,HI"; default the data's); the camera framing
// its box; the fast method of its kind (preint1, step 1, on grids;
// tet-raycast on meshes). vri::Error naming the flag for a bad value.
struct VolumeLook {
  std::string colormap, opacity, range;  // empty: as `vri info` suggests
};
Scene volume_scene(Volume volume, const VolumeLook& look = {});
// Whether the path is a volume file standing where a scene does: a regular
// file whose first non-blank byte is not '{' (a scene's JSON). Anything else
// - a scene, a missing file, a FIFO (not read, nor waited on) - is false,
// left to the scene loader and its messages.
bool is_volume_file(const std::filesystem::path& path);

// The histogram of a grid's samples or a mesh's point scalars over the data's range.
Histogram histogram(const Volume& volume, int bins = 256);

// The box a volume fills: a grid's (SPEC §1), a mesh's points' bounding box.
std::pair<Vec3, Vec3> bounds(const Volume& volume);

// Loading one part of a grid scene (distributed rendering, docs/
// DISTRIBUTED.md): `region` picks the points to read once the grid's dims are
// known, given the scene's method (for the ghost layer it needs); raw and
// NRRD files read only those, other sources are read whole and cut.
// `value_range` turns the part's [min, max] into the whole grid's (an
// allreduce; called once, after the part is read, by every rank that read
// its part). A percentile "range" is refused: it needs every sample.
struct PartialLoad {
  std::function<GridRegion(std::array<int, 3> dims, const MethodSpec& method)> region;
  std::function<std::pair<float, float>(float lo, float hi)> value_range;
};

// Loads a scene; relative paths inside it are relative to the scene file.
// Every problem (missing file, bad JSON, wrong sizes, bad values) throws
// vri::Error with one line naming the file and the key.
Scene load_scene(const std::filesystem::path& path);
Scene load_scene(const std::filesystem::path& path, const PartialLoad& part);
Scene parse_scene(std::string_view json_text, const std::filesystem::path& base_dir,
                  const std::string& source_name = "scene");
// A scene whose volume is given (built in memory: numpy arrays from Python)
// rather than named: the JSON holds every other key and no "volume".
Scene parse_scene(std::string_view json_text, Volume volume, const std::filesystem::path& base_dir,
                  const std::string& source_name = "scene");

// A transfer function on its own: {"points": ...}, {"opacity_points": ...,
// "unit_distance": u}, {"colormap": NAME, ...} or {"paraview": FILE, ...}, with
// an optional "range" (docs/SCENES.md, "Transfer functions"). A "range" of
// "data" or percentiles (and a colour map without "range") needs `volume`:
// without one it is a vri::Error saying to give [lo, hi]. A relative
// "paraview" path resolves against the file's folder, or `base_dir`.
TransferFunction load_transfer_function(const std::filesystem::path& path, const Volume* volume = nullptr);
TransferFunction parse_transfer_function(std::string_view json_text, const std::string& source_name = "transfer function",
                                         const Volume* volume = nullptr, const std::filesystem::path& base_dir = ".");
// A "camera" block on its own (SPEC §6), checked as in a scene; errors name `source_name`: camera.
CameraSpec parse_camera(std::string_view json_text, const std::string& source_name = "scene");
// A "clip" block on its own (SPEC §12), checked as in a scene; errors name `source_name`: clip.
ClipRegion parse_clip(std::string_view json_text, const std::string& source_name = "scene");

}  // namespace vri

// ---- scene_overrides -------------------------------------------------------
// SceneOverrides: what a caller changes in a loaded scene before rendering it
// (the `vri render` flags, the keyword arguments of the Python vri.render).
// One place applies them, so both front ends follow the same rules.

namespace vri {

struct SceneOverrides {
  std::optional<std::string> method, strategy;
  std::optional<double> step, tolerance, termination, max_samples, max_work, h0, hmin, hmax;
  std::optional<int> table_size, iterations, width, height;
  std::optional<bool> skip_empty, float_math;
  std::optional<std::uint64_t> jitter;  // riemann: the jitter's seed
  // The camera (issue 20): `fit` frames the volume's box (framing.hpp), then
  // VTK's motions in degrees and the zoom factor.
  std::optional<bool> fit;
  std::optional<double> azimuth, elevation, roll, zoom;
  std::optional<ClipRegion> clip;  // replaces the scene's "clip" (an inactive one: none)
};

// Sets every given field; the camera's size first, then the fit, then the motions. A method other than the scene's drops the scene's
// table_size (it was chosen for the scene's own method: preint2-dual then
// keeps its default, 64) unless table_size is given too.
void apply_overrides(Scene& scene, const SceneOverrides& overrides);

// The method's part of apply_overrides, alone: what a rank of a distributed
// render applies to the scene's method to choose its ghost layer while the
// scene is still loading.
void apply_method_overrides(MethodSpec& method, const SceneOverrides& overrides);

}  // namespace vri
