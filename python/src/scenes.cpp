// vri.Scene: everything one render needs (SPEC §8), from a file or a dict.
#include <filesystem>
#include <string>
#include <variant>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "vri/error.hpp"

namespace vri::python {

namespace {

namespace fs = std::filesystem;

// A dict as JSON text; numpy scalars and arrays become numbers and lists.
std::string json_of(const py::dict& d) {
  const py::cpp_function as_list([](const py::object& o) -> py::object {
    if (py::hasattr(o, "tolist")) return o.attr("tolist")();
    throw py::type_error("scene: cannot write a " + py::type::of(o).attr("__name__").cast<std::string>() + " as JSON");
  });
  return py::module_::import("json").attr("dumps")(d, py::arg("default") = as_list, py::arg("allow_nan") = false)
      .cast<std::string>();
}

bool is_path(const py::handle& o) {
  return py::isinstance<py::str>(o) || py::isinstance(o, py::module_::import("os").attr("PathLike"));
}

std::shared_ptr<Scene> scene_from_dict(const py::dict& d, const std::optional<fs::path>& base_dir) {
  const fs::path base = base_dir.value_or(fs::current_path());
  if (d.contains("volume")) {
    const py::object v = d["volume"];
    std::optional<Volume> given;
    if (py::isinstance<GridVolume>(v)) given.emplace(v.cast<const GridVolume&>());  // shares the samples
    else if (py::isinstance<TetMesh>(v)) given.emplace(v.cast<const TetMesh&>());
    if (given) {
      // A shallow copy: py::dict(d) would be `d` itself, and popping its
      // "volume" broke the caller's second call (issue 47).
      py::dict rest = d.attr("copy")();
      rest.attr("pop")("volume");
      return std::make_shared<Scene>(parse_scene(json_of(rest), std::move(*given), base, "scene"));
    }
  }
  return std::make_shared<Scene>(parse_scene(json_of(d), base, "scene"));
}

py::object volume_object(const Volume& v) {
  if (const auto* g = std::get_if<GridVolume>(&v)) return py::cast(std::make_shared<GridVolume>(*g));
  return py::cast(std::make_shared<TetMesh>(std::get<TetMesh>(v)));
}
py::object volume_of(const Scene& s) { return volume_object(s.volume); }

py::list points_of(const TransferFunction& tf) {
  py::list out;
  for (const ControlPoint& p : tf.points()) out.append(py::make_tuple(p.s, p.r, p.g, p.b, p.tau));
  return out;
}

}  // namespace

std::shared_ptr<Scene> scene_of(const py::handle& o) {
  if (py::isinstance<Scene>(o)) return o.cast<std::shared_ptr<Scene>>();
  if (py::isinstance<py::dict>(o)) return scene_from_dict(o.cast<py::dict>(), std::nullopt);
  if (is_path(o)) {  // a scene file, or a volume file seen as `vri render VOLUME` sees it (SPEC §12)
    const fs::path path = o.cast<fs::path>();
    if (is_volume_file(path)) return std::make_shared<Scene>(volume_scene(load_volume(path)));
    return std::make_shared<Scene>(load_scene(path));
  }
  throw py::type_error("expected a vri.Scene, a dict of scene keys, a scene file path or a volume file path, got " +
                       py::type::of(o).attr("__name__").cast<std::string>());
}

TransferFunction transfer_function_of(const py::handle& o) {
  if (py::isinstance<Scene>(o)) return o.cast<const Scene&>().transfer_function;
  if (py::isinstance<py::dict>(o)) return parse_transfer_function(json_of(o.cast<py::dict>()));
  if (is_path(o)) return load_transfer_function(o.cast<fs::path>());
  throw py::type_error("expected a transfer function dict, a file path or a vri.Scene, got " +
                       py::type::of(o).attr("__name__").cast<std::string>());
}

void bind_scenes(py::module_& m) {
  py::class_<Scene, std::shared_ptr<Scene>>(m, "Scene",
      "A scene (SPEC §8): volume, transfer function, camera, lighting, background, method.\n"
      "vri.render takes a Scene, a dict of the same keys or a scene file path.")
      .def(py::init(&scene_from_dict), py::arg("scene"), py::kw_only(), py::arg("base_dir") = py::none(),
           "A scene from a dict of SPEC §8 keys. Its \"volume\" may be a vri.Volume or a vri.Mesh\n"
           "instead of a file; relative file paths are relative to base_dir (default: the current\n"
           "directory). Raises ValueError naming the key of any bad value.")
      .def_property_readonly("kind", [](const Scene& s) {
            return std::holds_alternative<GridVolume>(s.volume) ? "grid" : "mesh";
          }, "'grid' or 'mesh'")
      .def_property_readonly("volume", &volume_of, "the vri.Volume or vri.Mesh (sharing the samples)")
      .def_property_readonly("method", [](const Scene& s) { return s.method.name; }, "the scene's method name")
      .def_property_readonly("width", [](const Scene& s) { return s.camera.width; })
      .def_property_readonly("height", [](const Scene& s) { return s.camera.height; })
      .def_property_readonly("background", [](const Scene& s) {
            return py::make_tuple(s.background.x, s.background.y, s.background.z);
          })
      .def_property_readonly("transfer_function", [](const Scene& s) { return points_of(s.transfer_function); },
                             "the control points (s, r, g, b, tau)")
      .def("__repr__", [](const Scene& s) {
        return "<vri.Scene " + std::string(std::holds_alternative<GridVolume>(s.volume) ? "grid" : "mesh") + ", " +
               std::to_string(s.camera.width) + "x" + std::to_string(s.camera.height) + ", method '" +
               s.method.name + "'>";
      });
  m.def("load_scene", [](const fs::path& path) { return std::make_shared<Scene>(load_scene(path)); },
        py::arg("path"),
        "Loads a scene file (SPEC §8); paths inside it are relative to the file. Raises OSError\n"
        "for a file that cannot be read, ValueError for bad content (the CLI's message).");
  m.def("load_volume", [](const fs::path& path) { return volume_object(load_volume(path)); }, py::arg("path"),
        "Loads a volume file of any format `vri info` reads: a vri.Volume (a regular grid) or a\n"
        "vri.Mesh (tetrahedra). vri.render(path) renders it as `vri render VOLUME` does. Raises\n"
        "OSError for a file that cannot be read, ValueError for bad content.");
}

}  // namespace vri::python
