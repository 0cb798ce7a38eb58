// Scene JSON (SPEC §8) -> Scene. Unknown keys are errors with the nearest
// known key suggested (a typo is never ignored); known keys are checked for
// type and range, and every message names the file and the key path.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <optional>
#include <string>
#include <tuple>

#include "vri/camera.hpp"
#include "vri/error.hpp"
#include "io/metaimage.hpp"
#include "vri/io.hpp"
#include "io/nrrd.hpp"
#include "io/tiff.hpp"
#include "io/volvis_dat.hpp"
#include "io/vti.hpp"
#include "io/vtk_legacy.hpp"
#include "io/vtu.hpp"
#include "tables/table_builder.hpp"
#include "mesh/tetrahedralize.hpp"
#include "vri/scene.hpp"
#include "volume/builtin_volumes.hpp"
#include "core/json_support.hpp"
#include "scene/transfer_function_json.hpp"

namespace vri {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

// parse_json, found and key_suggestion: core/json_support.hpp; text_of: vri/io.hpp.

// Typed access to one object of the scene; every error names the file, the
// key path, what was expected and what was found.
struct Reader {
  std::string file;  // e.g. "scene 'a.json'"
  std::string path;  // e.g. "camera", "" at the top

  std::string ctx() const { return path.empty() ? file : file + ": " + path; }
  std::string where(const std::string& key) const { return file + ": " + (path.empty() ? key : path + "." + key); }
  Reader child(const std::string& key) const { return {file, path.empty() ? key : path + "." + key}; }
  [[noreturn]] void expected(const std::string& key, const std::string& what, const json& v) const {
    throw Error(where(key) + ": expected " + what + ", found " + found(v));
  }

  const json& object(const json& j) const {
    if (!j.is_object()) throw Error(ctx() + ": expected a JSON object, found " + found(j));
    return j;
  }
  // Known keys that do not apply here are errors too, saying `why`.
  void refused(const json& j, std::initializer_list<const char*> keys, const std::string& why) const {
    for (const char* key : keys)
      if (j.contains(key)) throw Error(where(key) + ": " + why);
  }
  // Unknown keys are errors (a typo would otherwise be ignored silently).
  void known(const json& j, std::initializer_list<std::string_view> keys) const {
    known(j, std::span<const std::string_view>(keys.begin(), keys.size()));
  }
  void known(const json& j, std::span<const std::string_view> keys) const {
    for (const auto& item : j.items()) {
      const std::string& key = item.key();
      if (std::find(keys.begin(), keys.end(), key) != keys.end()) continue;
      throw Error(where(printable(key, 40)) + ": unknown key" + key_suggestion(key, keys));
    }
  }
  double number(const json& j, const char* key, std::optional<double> def = std::nullopt) const {
    if (!j.contains(key)) {
      if (def) return *def;
      throw Error(ctx() + ": missing '" + key + "'");
    }
    const json& v = j.at(key);
    if (!v.is_number() || !std::isfinite(v.get<double>())) expected(key, "a finite number", v);
    return v.get<double>();
  }
  // Checked conversion: the value is tested against the range before any cast.
  std::int64_t integer_in(const json& j, const char* key, std::int64_t lo, std::int64_t hi,
                          std::optional<std::int64_t> def = std::nullopt) const {
    if (!j.contains(key)) {
      if (def) return *def;
      throw Error(ctx() + ": missing '" + key + "'");
    }
    const json& v = j.at(key);
    const std::string want = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (v.is_number_unsigned()) {
      const std::uint64_t u = v.get<std::uint64_t>();
      if (u > std::uint64_t(hi) || (lo > 0 && u < std::uint64_t(lo))) expected(key, want, v);
      return std::int64_t(u);
    }
    if (v.is_number_integer()) {
      if (v.get<std::int64_t>() < lo || v.get<std::int64_t>() > hi) expected(key, want, v);
      return v.get<std::int64_t>();
    }
    const double d = v.is_number_float() ? v.get<double>() : 0.5;
    if (!(d >= double(lo) && d <= double(hi)) || d != std::floor(d)) expected(key, want, v);
    return static_cast<std::int64_t>(d);
  }
  int integer(const json& j, const char* key, std::optional<int> def = std::nullopt) const {
    return int(integer_in(j, key, -1'000'000'000, 1'000'000'000, def));
  }
  bool boolean(const json& j, const char* key, bool def) const {
    if (!j.contains(key)) return def;
    if (!j.at(key).is_boolean()) expected(key, "true or false", j.at(key));
    return j.at(key).get<bool>();
  }
  std::string string(const json& j, const char* key, std::optional<std::string> def = std::nullopt) const {
    if (!j.contains(key)) {
      if (def) return *def;
      throw Error(ctx() + ": missing '" + key + "'");
    }
    if (!j.at(key).is_string()) expected(key, "a string", j.at(key));
    return j.at(key).get<std::string>();
  }
  std::vector<double> numbers(const json& v, const std::string& what, std::size_t n) const {
    const std::string want = "an array of " + std::to_string(n) + " finite numbers";
    if (!v.is_array() || v.size() != n) expected(what, want, v);
    std::vector<double> out;
    for (const auto& e : v) {
      if (!e.is_number() || !std::isfinite(e.get<double>())) expected(what, want, v);
      out.push_back(e.get<double>());
    }
    return out;
  }
  Vec3 vec3(const json& j, const char* key, std::optional<Vec3> def = std::nullopt) const {
    if (!j.contains(key)) {
      if (def) return *def;
      throw Error(ctx() + ": missing '" + key + "'");
    }
    const auto v = numbers(j.at(key), key, 3);
    return {v[0], v[1], v[2]};
  }
  std::array<std::int64_t, 3> dims(const json& j, const char* key) const {
    const auto v = numbers(j.at(key), key, 3);
    std::array<std::int64_t, 3> d{};
    for (int a = 0; a < 3; ++a) {
      if (v[a] != std::floor(v[a]) || std::abs(v[a]) > 1e12) expected(key, "three integers", j.at(key));
      d[a] = static_cast<std::int64_t>(v[a]);
    }
    GridVolume::checked_sample_count(d);
    return d;
  }
};

// Every key a volume object may hold (grid, builtin, raw, mesh).
constexpr std::array<std::string_view, 15> kVolumeKeys = {
    "builtin", "dims", "f_m", "alpha", "radius", "seed", "file", "type", "endian",
    "spacing", "origin", "scalars", "grid", "tets_per_cell", "allow_outside_paths"};

// `region`: read only the part it picks (PartialLoad); else the whole grid.
GridVolume grid_volume_from(const json& j, const fs::path& base, const Reader& r, const RegionChooser& region = {}) {
  r.object(j);
  r.known(j, kVolumeKeys);
  r.refused(j, {"grid", "tets_per_cell"}, "applies to tetrahedralized volumes only");
  std::optional<GridVolume> vol;
  if (j.contains("builtin")) {
    const std::string name = r.string(j, "builtin");
    // Keys of volume files mean nothing here: refused, not ignored.
    r.refused(j, {"file", "type", "endian", "allow_outside_paths", "scalars"},
              "applies to volume files, not to builtin volumes");
    auto dims_or = [&](std::array<int, 3> def) {
      if (!j.contains("dims")) return def;
      const auto d = r.dims(j, "dims");
      return std::array<int, 3>{int(d[0]), int(d[1]), int(d[2])};
    };
    if (name == "marschner_lobb")
      vol.emplace(marschner_lobb(dims_or({41, 41, 41}), r.number(j, "f_m", 6.0), r.number(j, "alpha", 0.25), region));
    else if (name == "sphere")
      vol.emplace(sphere_distance(dims_or({64, 64, 64}), r.number(j, "radius", 0.0), region));
    else if (name == "random") {
      const auto seed = r.integer_in(j, "seed", 0, std::int64_t(1) << 53, 1);  // exact in JSON's doubles
      vol.emplace(random_field(dims_or({32, 32, 32}), static_cast<std::uint64_t>(seed), region));
    } else
      r.expected("builtin", "marschner_lobb, sphere, random or tetrahedralized", j.at("builtin"));
  } else {
    fs::path file = r.string(j, "file");
    if (file.is_relative()) file = base / file;
    const VolumeFormat format = volume_format(file);
    const std::string what = "applies to headerless raw files; this one is " + std::string(format_name(format));
    if (format != VolumeFormat::Raw) r.refused(j, {"dims", "type", "endian"}, what);
    if (format != VolumeFormat::Vti && format != VolumeFormat::VtkStructuredPoints)
      r.refused(j, {"scalars"}, "names an array of a VTK file; this one is " + std::string(format_name(format)));
    if (format != VolumeFormat::Nrrd && format != VolumeFormat::MetaImage)
      r.refused(j, {"allow_outside_paths"}, "applies to NRRD and MetaImage headers that name a data file");
    const bool outside = r.boolean(j, "allow_outside_paths", false);
    const std::string scalars = r.string(j, "scalars", "");
    switch (format) {
      case VolumeFormat::Nrrd:
        vol.emplace(read_nrrd(file, NrrdOptions{outside, region}));
        break;
      case VolumeFormat::VolvisDat: vol.emplace(read_volvis_dat(file)); break;
      case VolumeFormat::Vti: vol.emplace(read_vti(file, scalars)); break;
      case VolumeFormat::VtkStructuredPoints: vol.emplace(read_vtk_structured_points(file, scalars)); break;
      case VolumeFormat::MetaImage: vol.emplace(read_metaimage(file, MetaImageOptions{outside})); break;
      case VolumeFormat::Npy: vol.emplace(read_npy_volume(file)); break;
      case VolumeFormat::Tiff: vol.emplace(read_tiff_volume(file)); break;
      case VolumeFormat::VtkLegacyMesh:
      case VolumeFormat::Vtu:
        throw Error(r.ctx() + ": '" + printable(file.string()) + "' is a tetrahedral mesh, not a regular grid");
      case VolumeFormat::Raw: {
        if (!j.contains("dims"))
          throw Error(r.ctx() + ": '" + printable(file.string()) + "' has no header vri knows, so it is read as " +
                      "headerless raw, which needs 'dims' (and 'type'); vri reads " +
                      std::string(supported_formats()));
        const auto dims = r.dims(j, "dims");
        const ScalarType type = parse_scalar_type(r.string(j, "type", "uint8"));
        const std::string endian = r.string(j, "endian", "little");
        if (endian != "little" && endian != "big") r.expected("endian", "little or big", j.at("endian"));
        vol.emplace(read_raw_volume(file, dims, type, endian == "big" ? Endian::Big : Endian::Little, region));
        break;
      }
    }
  }
  // The sources that cannot seek are read whole, then cut.
  if (region && !vol->brick()) vol.emplace(cut_region(*vol, region(vol->dims())));
  // Keys in the scene override the file's own header (SPEC §8); a part
  // moves with them as the whole grid does.
  if (j.contains("spacing")) {
    const Vec3 s = r.vec3(j, "spacing");
    if (!(s.x > 0 && s.y > 0 && s.z > 0)) r.expected("spacing", "three positive numbers", j.at("spacing"));
    vol->set_spacing(s);
  }
  if (j.contains("origin")) vol->set_origin(r.vec3(j, "origin"));
  return std::move(*vol);
}

// A mesh file (.vtk, .vtu) or {"builtin": "tetrahedralized", "grid": {...},
// "tets_per_cell": 5|6}; anything else is a grid.
Volume volume_from(const json& j, const fs::path& base, const Reader& top, const RegionChooser& region = {}) {
  const Reader r = top.child("volume");
  r.object(j);
  r.known(j, kVolumeKeys);
  const bool tetrahedralized = j.contains("builtin") && r.string(j, "builtin") == "tetrahedralized";
  fs::path file = j.contains("file") && !j.contains("builtin") ? fs::path(r.string(j, "file")) : fs::path();
  if (!file.empty() && file.is_relative()) file = base / file;
  const bool mesh = !file.empty() && is_mesh(volume_format(file));
  if (!tetrahedralized && !mesh) return grid_volume_from(j, base, r, region);
  r.refused(j, {"spacing", "origin", "dims"}, "applies to grid volumes, not to meshes");
  if (tetrahedralized) {
    if (!j.contains("grid")) throw Error(r.ctx() + ": 'tetrahedralized' needs a 'grid' volume to split");
    const Reader g = r.child("grid");
    return tetrahedralize(grid_volume_from(g.object(j.at("grid")), base, g), r.integer(j, "tets_per_cell", 5));
  }
  const std::string scalars = r.string(j, "scalars", "");
  try {
    return volume_format(file) == VolumeFormat::VtkLegacyMesh ? read_vtk_legacy(file, scalars) : read_vtu(file, scalars);
  } catch (const Error& e) {
    throw Error(r.ctx() + ": " + e.what());
  }
}

// A camera block (SPEC §6) and, beyond it (issue 20), "fit": frame the
// volume's box (the default when no eye is given), and VTK's motions
// "azimuth", "elevation", "roll" (degrees) and "zoom" relative to that frame or
// to the eye given. The motions and the fit need the volume: CameraRequest
// keeps them until it is loaded (place_camera).
struct CameraRequest {
  CameraSpec spec;
  bool fit = false;
  double azimuth = 0, elevation = 0, roll = 0, zoom = 1;
};

CameraRequest camera_from(const json& j, const Reader& top) {
  const Reader r = top.child("camera");
  r.object(j);
  r.known(j, {"eye", "target", "up", "fov_y", "width", "height", "projection", "ortho_height", "fit", "azimuth",
              "elevation", "roll", "zoom"});
  CameraRequest q;
  CameraSpec& c = q.spec;
  q.fit = r.boolean(j, "fit", !j.contains("eye") && !j.contains("target"));
  if (q.fit) {
    r.refused(j, {"eye", "target"}, "is replaced by the frame of \"fit\": give one or the other");
  } else {
    c.eye = r.vec3(j, "eye");
    c.target = r.vec3(j, "target");
  }
  c.up = r.vec3(j, "up", Vec3{0, 1, 0});
  c.fov_y = r.number(j, "fov_y", 30.0);
  for (const char* key : {"width", "height"})
    if (j.contains(key) && r.integer(j, key) <= 0)
      r.expected(key, "a positive integer", j.at(key));
  c.width = r.integer(j, "width", 512);
  c.height = r.integer(j, "height", 512);
  const std::string proj = r.string(j, "projection", "perspective");
  if (proj == "perspective") c.projection = Projection::Perspective;
  else if (proj == "orthographic") c.projection = Projection::Orthographic;
  else r.expected("projection", "perspective or orthographic", j.at("projection"));
  if (c.projection == Projection::Orthographic && !q.fit) c.ortho_height = r.number(j, "ortho_height");
  // Checked whatever the projection: a perspective camera ignores it, but a
  // bad value is a mistake to say (issue 47).
  if (j.contains("ortho_height"))
    if (const double h = r.number(j, "ortho_height"); !(h > 0) || !std::isfinite(h))
      r.expected("ortho_height", "a positive number", j.at("ortho_height"));
  q.azimuth = r.number(j, "azimuth", 0.0);
  q.elevation = r.number(j, "elevation", 0.0);
  q.roll = r.number(j, "roll", 0.0);
  q.zoom = r.number(j, "zoom", 1.0);
  if (!(q.zoom > 0)) r.expected("zoom", "a number > 0", j.at("zoom"));
  if (!q.fit) Camera check(c);  // validates now, so a bad camera fails before any volume work
  return q;
}

// The camera of a request, framing `volume` (which a fit needs) if asked.
CameraSpec place_camera(const CameraRequest& q, const Volume* volume, const Reader& top) {
  try {
    CameraSpec c = q.spec;
    if (q.fit) {
      if (!volume) throw Error("\"fit\" needs the volume: give eye and target");
      const auto [lo, hi] = bounds(*volume);
      c = frame_box(lo, hi, c);
    }
    c = move_camera(c, q.azimuth, q.elevation, q.roll, q.zoom);
    Camera check(c);
    return c;
  } catch (const Error& e) {
    throw Error(top.child("camera").ctx() + ": " + e.what());
  }
}

// A numeric method parameter: a finite JSON number, then its one rule
// (check_method_parameter, vri/methods.hpp), before any cast to an integer.
double parameter(const Reader& m, const json& mj, const char* key, double def) {
  if (!mj.contains(key)) return def;
  const double v = m.number(mj, key);
  try {
    check_method_parameter(key, v);
  } catch (const Error& e) {
    throw Error(m.file + ": " + e.what());
  }
  return v;
}

MethodSpec method_from(const json& mj, const Reader& top) {
  const Reader m = top.child("method");
  m.object(mj);
  m.known(mj, {"name", "step", "tolerance", "table_size", "length_samples", "planes", "iterations", "h0", "hmin",
               "hmax", "strategy", "builder", "termination", "skip_empty", "float_math", "max_samples", "max_work",
               "jitter"});
  MethodSpec method;
  method.name = m.string(mj, "name", "exact");
  method.step = parameter(m, mj, "step", method.step);
  method.tolerance = parameter(m, mj, "tolerance", method.tolerance);
  method.table_size = int(parameter(m, mj, "table_size", method.table_size));
  method.table_size_given = mj.contains("table_size");
  method.length_samples = int(parameter(m, mj, "length_samples", method.length_samples));
  method.planes = int(parameter(m, mj, "planes", method.planes));
  method.iterations = int(parameter(m, mj, "iterations", method.iterations));
  method.h0 = parameter(m, mj, "h0", method.h0);
  method.hmin = parameter(m, mj, "hmin", method.hmin);
  method.hmax = parameter(m, mj, "hmax", method.hmax);
  method.strategy = m.string(mj, "strategy", method.strategy);
  method.builder = m.string(mj, "builder", method.builder);
  // preint2* take a second-order builder; anything else would fall back silently.
  const bool second_order = method.name.rfind("preint2", 0) == 0;
  const auto& first = known_builder_names();
  if (mj.contains("builder") && second_order && method.builder != "plain" && method.builder != "fast")
    m.expected("builder", "plain or fast for " + method.name, mj.at("builder"));
  if (mj.contains("builder") && method.builder != "plain" && method.builder != "fast" &&
      std::find(first.begin(), first.end(), method.builder) == first.end()) {
    std::string list;
    for (const auto& n : first) list += n + ", ";
    m.expected("builder", list + "plain or fast", mj.at("builder"));
  }
  method.fast.termination = parameter(m, mj, "termination", method.fast.termination);
  method.fast.skip_empty = m.boolean(mj, "skip_empty", method.fast.skip_empty);
  method.fast.float_math = m.boolean(mj, "float_math", method.fast.float_math);
  method.max_samples = parameter(m, mj, "max_samples", method.max_samples);
  method.max_work = parameter(m, mj, "max_work", method.max_work);
  // riemann's jitter (riemann.hpp): its seed, an integer JSON's doubles hold exactly.
  if (mj.contains("jitter")) method.jitter = static_cast<std::uint64_t>(parameter(m, mj, "jitter", 0));
  return method;
}

Lighting lighting_from(const json& lj, const Reader& top) {
  const Reader l = top.child("lighting");
  l.object(lj);
  l.known(lj, {"enabled", "ambient", "diffuse", "specular", "shininess", "mode"});
  Lighting lighting;
  lighting.enabled = l.boolean(lj, "enabled", false);
  lighting.ambient = l.number(lj, "ambient", lighting.ambient);
  lighting.diffuse = l.number(lj, "diffuse", lighting.diffuse);
  lighting.specular = l.number(lj, "specular", lighting.specular);
  lighting.shininess = l.number(lj, "shininess", lighting.shininess);
  lighting.mode = l.string(lj, "mode", lighting.mode);
  if (lighting.mode != "sampled" && lighting.mode != "interpolated")
    l.expected("mode", "sampled or interpolated", lj.at("mode"));
  for (const char* key : {"ambient", "diffuse", "specular", "shininess"})
    if (lj.contains(key) && lj.at(key).get<double>() < 0) l.expected(key, "a number >= 0", lj.at(key));
  return lighting;
}

// "clip": {"planes": [[nx, ny, nz, d], ...], "box": [[x0, y0, z0], [x1, y1, z1]]}
// (SPEC §12): a plane's normal is not 0, a box's corners are ordered.
ClipRegion clip_from(const json& cj, const Reader& top) {
  const Reader c = top.child("clip");
  c.object(cj);
  c.known(cj, {"planes", "box"});
  ClipRegion clip;
  if (cj.contains("planes")) {
    const json& planes = cj.at("planes");
    if (!planes.is_array()) c.expected("planes", "an array of planes [nx, ny, nz, d]", planes);
    for (std::size_t i = 0; i < planes.size(); ++i) {
      const std::string key = "planes[" + std::to_string(i) + "]";
      const auto p = c.numbers(planes[i], key, 4);
      const ClipPlane plane{{p[0], p[1], p[2]}, p[3]};
      const double length2 = dot(plane.normal, plane.normal);
      if (!(length2 > 0) || !std::isfinite(length2))
        c.expected(key, "a plane [nx, ny, nz, d] whose normal is not 0", planes[i]);
      clip.planes.push_back(plane);
    }
  }
  if (cj.contains("box")) {
    const json& b = cj.at("box");
    const std::string want = "two corners [[x0, y0, z0], [x1, y1, z1]] with x0 <= x1, y0 <= y1, z0 <= z1";
    if (!b.is_array() || b.size() != 2) c.expected("box", want, b);
    const auto lo = c.numbers(b[0], "box", 3), hi = c.numbers(b[1], "box", 3);
    for (int a = 0; a < 3; ++a)
      if (!(lo[a] <= hi[a])) c.expected("box", want, b);
    clip.box = Box{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}};
  }
  return clip;
}

}  // namespace

ClipRegion parse_clip(std::string_view text, const std::string& source) {
  return clip_from(parse_json(text, source), Reader{source, ""});
}

CameraSpec parse_camera(std::string_view text, const std::string& source) {
  const Reader r{source, ""};
  return place_camera(camera_from(parse_json(text, source), r), nullptr, r);
}

namespace {

// A scene from JSON; its volume read from the JSON's "volume", or `given`.
Scene scene_from(std::string_view text, const fs::path& base, const std::string& source, std::optional<Volume> given,
                 const PartialLoad* part = nullptr) {
  const json j = parse_json(text, source);
  const Reader r{source, ""};
  r.object(j);
  r.known(j, {"volume", "transfer_function", "camera", "method", "lighting", "background", "clip"});
  for (const char* key : {"volume", "transfer_function", "camera"})
    if (!j.contains(key) && !(given && std::string_view(key) == "volume"))
      throw Error(source + ": missing '" + std::string(key) + "'");
  if (given && j.contains("volume")) throw Error(source + ": the volume is given, so 'volume' must not be");

  const CameraRequest camera = camera_from(j.at("camera"), r);
  const MethodSpec method = j.contains("method") ? method_from(j.at("method"), r) : MethodSpec{};
  const Lighting lighting = j.contains("lighting") ? lighting_from(j.at("lighting"), r) : Lighting{};
  const ClipRegion clip = j.contains("clip") ? clip_from(j.at("clip"), r) : ClipRegion{};

  Vec3 background{0, 0, 0};
  if (j.contains("background")) {
    const auto b = r.numbers(j.at("background"), "background", 3);
    // As --background: a colour (issue 47: [1e300, -5, 0.5] was taken).
    if (!std::all_of(b.begin(), b.end(), [](double x) { return x >= 0 && x <= 1; }))
      r.expected("background", "three numbers in [0, 1]", j.at("background"));
    background = {b[0], b[1], b[2]};
  }

  const json& tfj = j.at("transfer_function");
  const Reader t = r.child("transfer_function");
  // Read and checked before the volume is loaded; a "range" of "data" or
  // percentiles is resolved on the volume after.
  std::optional<TransferFunctionRequest> tf;
  if (tfj.is_object() && tfj.contains("file")) {
    t.known(tfj, {"file"});
    fs::path file = t.string(tfj, "file");
    if (file.is_relative()) file = base / file;
    tf.emplace(transfer_function_request(file));
  } else {
    tf.emplace(tfj, t.file, t.path, base, true);
  }

  RegionChooser region;
  if (part) region = [&](std::array<int, 3> dims) { return part->region(dims, method); };
  Volume volume = given ? std::move(*given) : volume_from(j.at("volume"), base, r, region);
  if (auto* g = std::get_if<GridVolume>(&volume); g && part && g->brick()) {  // the whole grid's range
    GridVolume::Brick b = *g->brick();
    std::tie(b.whole_min, b.whole_max) = part->value_range(g->min_value(), g->max_value());
    g->set_brick(b);
  }
  set_clip(volume, clip);
  const CameraSpec placed = place_camera(camera, &volume, r);
  TransferFunction resolved = tf->resolve(&volume);
  return Scene{std::move(volume), std::move(resolved), placed, lighting, background, method};
}

}  // namespace

Scene parse_scene(std::string_view text, const fs::path& base, const std::string& source) {
  return scene_from(text, base, source, std::nullopt);
}

Scene parse_scene(std::string_view text, Volume volume, const fs::path& base, const std::string& source) {
  return scene_from(text, base, source, std::move(volume));
}

Volume load_volume(const fs::path& file, const std::string& scalars) {
  json j = {{"file", file.string()}};
  if (!scalars.empty()) j["scalars"] = scalars;
  return volume_from(j, ".", Reader{"volume '" + printable(file.string()) + "'", ""});
}

Scene load_scene(const fs::path& path) {
  const std::string source = "scene '" + printable(path.string()) + "'";
  return parse_scene(text_of(path), path.has_parent_path() ? path.parent_path() : fs::path("."), source);
}

Scene load_scene(const fs::path& path, const PartialLoad& part) {
  const std::string source = "scene '" + printable(path.string()) + "'";
  return scene_from(text_of(path), path.has_parent_path() ? path.parent_path() : fs::path("."), source, std::nullopt,
                    &part);
}

}  // namespace vri
