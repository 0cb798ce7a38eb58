// Scene JSON (SPEC §8) -> Scene. Unknown keys are ignored (the format may
// grow); known keys are checked for type and range.
#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>
#include <string>

#include "vri/core/error.hpp"
#include "vri/io/file_io.hpp"
#include "vri/io/nrrd.hpp"
#include "vri/io/raw_volume.hpp"
#include "vri/io/volvis_dat.hpp"
#include "vri/io/vtk_legacy.hpp"
#include "vri/io/vtu.hpp"
#include "vri/tables/second_order_table.hpp"
#include "vri/mesh/tetrahedralize.hpp"
#include "vri/scene/scene.hpp"
#include "vri/volume/builtin_volumes.hpp"

namespace vri {

namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

json parse_json(std::string_view text, const std::string& source) {
  try {
    return json::parse(text);
  } catch (const json::exception& e) {  // parse_error, or out_of_range for a number like 1E99999
    std::string what = e.what();
    if (auto p = what.find("] "); p != std::string::npos) what = what.substr(p + 2);
    throw Error(source + ": malformed JSON: " + what);
  }
}

std::string text_of(const fs::path& path) {
  const auto bytes = read_file(path);
  return std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

// Typed access with errors naming the key.
struct Reader {
  std::string ctx;  // e.g. "scene 'a.json': camera"

  const json& object(const json& j) const {
    if (!j.is_object()) throw Error(ctx + " must be a JSON object");
    return j;
  }
  double number(const json& j, const char* key, std::optional<double> def = std::nullopt) const {
    if (!j.contains(key)) {
      if (def) return *def;
      throw Error(ctx + ": missing '" + key + "'");
    }
    const json& v = j.at(key);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      throw Error(ctx + ": '" + key + "' must be a finite number");
    return v.get<double>();
  }
  int integer(const json& j, const char* key, std::optional<int> def = std::nullopt) const {
    const double v = number(j, key, def ? std::optional<double>(*def) : std::nullopt);
    if (v != std::floor(v) || std::abs(v) > 1e9) throw Error(ctx + ": '" + key + "' must be an integer");
    return static_cast<int>(v);
  }
  bool boolean(const json& j, const char* key, bool def) const {
    if (!j.contains(key)) return def;
    if (!j.at(key).is_boolean()) throw Error(ctx + ": '" + key + "' must be true or false");
    return j.at(key).get<bool>();
  }
  std::string string(const json& j, const char* key, std::optional<std::string> def = std::nullopt) const {
    if (!j.contains(key)) {
      if (def) return *def;
      throw Error(ctx + ": missing '" + key + "'");
    }
    if (!j.at(key).is_string()) throw Error(ctx + ": '" + key + "' must be a string");
    return j.at(key).get<std::string>();
  }
  std::vector<double> numbers(const json& v, const std::string& what, std::size_t n) const {
    if (!v.is_array() || v.size() != n)
      throw Error(ctx + ": '" + what + "' must be an array of " + std::to_string(n) + " numbers");
    std::vector<double> out;
    for (const auto& e : v) {
      if (!e.is_number() || !std::isfinite(e.get<double>()))
        throw Error(ctx + ": '" + what + "' must be an array of " + std::to_string(n) + " finite numbers");
      out.push_back(e.get<double>());
    }
    return out;
  }
  Vec3 vec3(const json& j, const char* key, std::optional<Vec3> def = std::nullopt) const {
    if (!j.contains(key)) {
      if (def) return *def;
      throw Error(ctx + ": missing '" + key + "'");
    }
    const auto v = numbers(j.at(key), key, 3);
    return {v[0], v[1], v[2]};
  }
  std::array<std::int64_t, 3> dims(const json& j, const char* key) const {
    const auto v = numbers(j.at(key), key, 3);
    std::array<std::int64_t, 3> d{};
    for (int a = 0; a < 3; ++a) {
      if (v[a] != std::floor(v[a]) || std::abs(v[a]) > 1e12)
        throw Error(ctx + ": '" + key + "' must hold three integers");
      d[a] = static_cast<std::int64_t>(v[a]);
    }
    GridVolume::checked_sample_count(d);
    return d;
  }
};

TransferFunction transfer_function_from(const json& j, const std::string& source) {
  const Reader r{source};
  r.object(j);
  auto rows = [&](const char* key) {
    const json& a = j.at(key);
    if (!a.is_array() || a.empty()) throw Error(source + ": '" + std::string(key) + "' must be a non-empty array");
    std::vector<std::vector<double>> out;
    for (std::size_t i = 0; i < a.size(); ++i)
      out.push_back(r.numbers(a[i], std::string(key) + "[" + std::to_string(i) + "]", 5));
    return out;
  };
  try {
    if (j.contains("points")) {
      std::vector<ControlPoint> cps;
      for (const auto& p : rows("points")) cps.push_back({p[0], p[1], p[2], p[3], p[4]});
      return TransferFunction(std::move(cps));
    }
    if (j.contains("opacity_points")) {
      std::vector<TransferFunction::OpacityPoint> ops;
      for (const auto& p : rows("opacity_points")) ops.push_back({p[0], p[1], p[2], p[3], p[4]});
      return TransferFunction::from_opacity(ops, r.number(j, "unit_distance"));
    }
  } catch (const Error& e) {
    const std::string msg = e.what();
    if (msg.rfind(source, 0) == 0) throw;
    throw Error(source + ": " + msg);
  }
  throw Error(source + ": needs 'points' or 'opacity_points'");
}

GridVolume grid_volume_from(const json& j, const fs::path& base, const std::string& source) {
  const Reader r{source};
  r.object(j);
  std::optional<GridVolume> vol;
  if (j.contains("builtin")) {
    const std::string name = r.string(j, "builtin");
    auto dims_or = [&](std::array<int, 3> def) {
      if (!j.contains("dims")) return def;
      const auto d = r.dims(j, "dims");
      return std::array<int, 3>{int(d[0]), int(d[1]), int(d[2])};
    };
    if (name == "marschner_lobb")
      vol.emplace(marschner_lobb(dims_or({41, 41, 41}), r.number(j, "f_m", 6.0), r.number(j, "alpha", 0.25)));
    else if (name == "sphere")
      vol.emplace(sphere_distance(dims_or({64, 64, 64}), r.number(j, "radius", 0.0)));
    else if (name == "random") {
      const double seed = r.number(j, "seed", 1.0);
      if (seed < 0 || seed != std::floor(seed)) throw Error(r.ctx + ": 'seed' must be a non-negative integer");
      vol.emplace(random_field(dims_or({32, 32, 32}), static_cast<std::uint64_t>(seed)));
    } else
      throw Error(r.ctx + ": unknown builtin '" + name + "' (known: marschner_lobb, sphere, random, tetrahedralized)");
  } else {
    fs::path file = r.string(j, "file");
    if (file.is_relative()) file = base / file;
    const std::string ext = file.extension().string();
    if (ext == ".nrrd" || ext == ".nhdr") {
      vol.emplace(read_nrrd(file, NrrdOptions{r.boolean(j, "allow_outside_paths", false)}));
    } else if (ext == ".dat") {
      vol.emplace(read_volvis_dat(file));
    } else {
      if (!j.contains("dims")) throw Error(r.ctx + ": a raw file needs 'dims'");
      const auto dims = r.dims(j, "dims");
      const ScalarType type = parse_scalar_type(r.string(j, "type", "uint8"));
      const std::string endian = r.string(j, "endian", "little");
      if (endian != "little" && endian != "big") throw Error(r.ctx + ": 'endian' must be little or big");
      vol.emplace(read_raw_volume(file, dims, type, endian == "big" ? Endian::Big : Endian::Little));
    }
  }
  // Keys in the scene override the file's own header (SPEC §8).
  if (j.contains("spacing")) {
    const Vec3 s = r.vec3(j, "spacing");
    if (!(s.x > 0 && s.y > 0 && s.z > 0)) throw Error(r.ctx + ": 'spacing' must be positive");
    vol->set_spacing(s);
  }
  if (j.contains("origin")) vol->set_origin(r.vec3(j, "origin"));
  return std::move(*vol);
}

// A mesh file (.vtk, .vtu) or {"builtin": "tetrahedralized", "grid": {...},
// "tets_per_cell": 5|6}; anything else is a grid.
Volume volume_from(const json& j, const fs::path& base, const std::string& source) {
  const Reader r{source + ": volume"};
  r.object(j);
  const bool tetrahedralized = j.contains("builtin") && r.string(j, "builtin") == "tetrahedralized";
  fs::path file = j.contains("file") && !j.contains("builtin") ? fs::path(r.string(j, "file")) : fs::path();
  const std::string ext = file.extension().string();
  if (!tetrahedralized && ext != ".vtk" && ext != ".vtu") return grid_volume_from(j, base, r.ctx);
  for (const char* key : {"spacing", "origin", "dims"})
    if (j.contains(key)) throw Error(r.ctx + ": '" + key + "' applies to grid volumes, not to meshes");
  if (tetrahedralized) {
    if (!j.contains("grid")) throw Error(r.ctx + ": 'tetrahedralized' needs a 'grid' volume to split");
    const Reader g{r.ctx + ": grid"};
    return tetrahedralize(grid_volume_from(g.object(j.at("grid")), base, g.ctx), r.integer(j, "tets_per_cell", 5));
  }
  if (file.is_relative()) file = base / file;
  const std::string scalars = r.string(j, "scalars", "");
  try {
    return ext == ".vtk" ? read_vtk_legacy(file, scalars) : read_vtu(file, scalars);
  } catch (const Error& e) {
    throw Error(r.ctx + ": " + e.what());
  }
}

CameraSpec camera_from(const json& j, const std::string& source) {
  const Reader r{source + ": camera"};
  r.object(j);
  CameraSpec c;
  c.eye = r.vec3(j, "eye");
  c.target = r.vec3(j, "target");
  c.up = r.vec3(j, "up", Vec3{0, 1, 0});
  c.fov_y = r.number(j, "fov_y", 30.0);
  c.width = r.integer(j, "width", 512);
  c.height = r.integer(j, "height", 512);
  const std::string proj = r.string(j, "projection", "perspective");
  if (proj == "perspective") c.projection = Projection::Perspective;
  else if (proj == "orthographic") c.projection = Projection::Orthographic;
  else throw Error(r.ctx + ": 'projection' must be perspective or orthographic");
  if (c.projection == Projection::Orthographic) c.ortho_height = r.number(j, "ortho_height");
  Camera check(c);  // validates now, so a bad camera fails before any volume work
  return c;
}

}  // namespace

TransferFunction parse_transfer_function(std::string_view text, const std::string& source) {
  return transfer_function_from(parse_json(text, source), source);
}

TransferFunction load_transfer_function(const fs::path& path) {
  return parse_transfer_function(text_of(path), "transfer function '" + path.string() + "'");
}

Scene parse_scene(std::string_view text, const fs::path& base, const std::string& source) {
  const json j = parse_json(text, source);
  const Reader r{source};
  r.object(j);
  for (const char* key : {"volume", "transfer_function", "camera"})
    if (!j.contains(key)) throw Error(source + ": missing '" + std::string(key) + "'");

  const CameraSpec camera = camera_from(j.at("camera"), source);

  MethodSpec method;
  if (j.contains("method")) {
    const Reader m{source + ": method"};
    const json& mj = m.object(j.at("method"));
    method.name = m.string(mj, "name", "exact");
    method.step = m.number(mj, "step", method.step);
    method.tolerance = m.number(mj, "tolerance", method.tolerance);
    method.table_size = m.integer(mj, "table_size", method.table_size);
    method.table_size_given = mj.contains("table_size");
    method.length_samples = m.integer(mj, "length_samples", method.length_samples);
    method.planes = m.integer(mj, "planes", method.planes);
    method.iterations = m.integer(mj, "iterations", method.iterations);
    if (method.iterations < 1 || method.iterations > kMaxSecondOrderIterations)
      throw Error(m.ctx + ": 'iterations' must be in [1, " + std::to_string(kMaxSecondOrderIterations) + "]");
    method.h0 = m.number(mj, "h0", method.h0);
    method.hmin = m.number(mj, "hmin", method.hmin);
    method.hmax = m.number(mj, "hmax", method.hmax);
    method.strategy = m.string(mj, "strategy", method.strategy);
    method.builder = m.string(mj, "builder", method.builder);
    method.fast.termination = m.number(mj, "termination", method.fast.termination);
    method.fast.skip_empty = m.boolean(mj, "skip_empty", method.fast.skip_empty);
    method.fast.float_math = m.boolean(mj, "float_math", method.fast.float_math);
  }

  Lighting lighting;
  if (j.contains("lighting")) {
    const Reader l{source + ": lighting"};
    const json& lj = l.object(j.at("lighting"));
    lighting.enabled = l.boolean(lj, "enabled", false);
    lighting.ambient = l.number(lj, "ambient", lighting.ambient);
    lighting.diffuse = l.number(lj, "diffuse", lighting.diffuse);
    lighting.specular = l.number(lj, "specular", lighting.specular);
    lighting.shininess = l.number(lj, "shininess", lighting.shininess);
    lighting.mode = l.string(lj, "mode", lighting.mode);
    if (lighting.mode != "sampled" && lighting.mode != "interpolated")
      throw Error(l.ctx + ": 'mode' must be sampled or interpolated");
    for (double v : {lighting.ambient, lighting.diffuse, lighting.specular, lighting.shininess})
      if (v < 0) throw Error(l.ctx + ": coefficients and shininess must be >= 0");
  }

  Vec3 background{0, 0, 0};
  if (j.contains("background")) {
    const auto b = r.numbers(j.at("background"), "background", 3);
    background = {b[0], b[1], b[2]};
  }

  const json& tfj = j.at("transfer_function");
  std::optional<TransferFunction> tf;
  if (tfj.is_object() && tfj.contains("file")) {
    fs::path file = Reader{source + ": transfer_function"}.string(tfj, "file");
    if (file.is_relative()) file = base / file;
    tf.emplace(load_transfer_function(file));
  } else {
    tf.emplace(transfer_function_from(tfj, source + ": transfer_function"));
  }

  Volume volume = volume_from(j.at("volume"), base, source);
  return Scene{std::move(volume), std::move(*tf), camera, lighting, background, method};
}

Scene load_scene(const fs::path& path) {
  const std::string source = "scene '" + path.string() + "'";
  return parse_scene(text_of(path), path.has_parent_path() ? path.parent_path() : fs::path("."), source);
}

}  // namespace vri
