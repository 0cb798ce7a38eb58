// What vri.Image (python/vri/__init__.py) and vri.render(array) need from
// C++: an image's files and PNG bytes from the writers `vri render -o`
// uses (the same bytes), and the scene of a volume seen as `vri render
// VOLUME --colormap --opacity --range` sees it (volume_scene.hpp).
#include <cstring>
#include <filesystem>
#include <string>
#include <variant>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "bindings.hpp"
#include "io/exr_output.hpp"
#include "scene/volume_scene.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "vri/transfer_function.hpp"

namespace vri::python {

namespace {

namespace fs = std::filesystem;
using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;

Image image_of(const FloatArray& a) {
  if (a.ndim() != 3 || a.shape(2) != 4 || a.shape(0) < 1 || a.shape(1) < 1)
    throw py::value_error("expected an image of shape (H, W, 4), got " + std::string(py::str(py::tuple(py::cast(
                              std::vector<py::ssize_t>(a.shape(), a.shape() + a.ndim()))))));
  Image image(static_cast<int>(a.shape(1)), static_cast<int>(a.shape(0)));
  std::memcpy(image.data().data(), a.data(), image.data().size_bytes());
  return image;
}

Vec3 colour(const std::array<double, 3>& c) { return {c[0], c[1], c[2]}; }

// .npy (the floats), .png (8 bits over the background) or .exr, as `vri render -o`.
void save_image(const fs::path& path, const FloatArray& a, const std::array<double, 3>& background) {
  const std::string ext = path.extension().string();
  const Image image = image_of(a);
  if (ext == ".npy") return write_npy(path, image);
  if (ext == ".png") return write_png(path, image, colour(background));
  if (ext == ".exr") return write_exr(path, image);
  throw Error("'" + path.string() + "' must end in .npy, .png or .exr");
}

// The 8-bit colour of the PNG: (H, W, 3), rounded as `vri render -o x.png` rounds.
py::array_t<std::uint8_t> rgb8(const FloatArray& a, const std::array<double, 3>& background) {
  const Image image = image_of(a);
  const std::vector<std::uint8_t> rgba = composite_rgba8(image, colour(background));
  py::array_t<std::uint8_t> out({static_cast<py::ssize_t>(image.height()), static_cast<py::ssize_t>(image.width()),
                                 py::ssize_t{3}});
  std::uint8_t* o = out.mutable_data();
  for (std::size_t i = 0; i < rgba.size() / 4; ++i)
    for (int c = 0; c < 3; ++c) o[3 * i + c] = rgba[4 * i + c];
  return out;
}

py::bytes png_bytes(const FloatArray& a, const std::array<double, 3>& background) {
  const std::vector<std::byte> png = encode_png(image_of(a), colour(background));
  return {reinterpret_cast<const char*>(png.data()), png.size()};
}

std::string volume_scene_text(const py::object& volume, const std::string& colormap, const std::string& opacity,
                              const std::string& range) {
  const VolumeLook look{colormap, opacity, range};
  if (py::isinstance<GridVolume>(volume)) return volume_scene_json(Volume(volume.cast<const GridVolume&>()), look).dump();
  if (py::isinstance<TetMesh>(volume)) return volume_scene_json(Volume(volume.cast<const TetMesh&>()), look).dump();
  throw py::type_error("expected a vri.Volume or a vri.Mesh, got " + py::type::of(volume).attr("__name__").cast<std::string>());
}

}  // namespace

void bind_images(py::module_& m) {
  m.def("_save_image", &save_image, py::arg("path"), py::arg("image"), py::arg("background"),
        "The image as `vri render -o PATH` writes it (.npy, .png over the background, .exr).");
  m.def("_rgb8", &rgb8, py::arg("image"), py::arg("background"), "The PNG's 8-bit colours, (H, W, 3).");
  m.def("_png_bytes", &png_bytes, py::arg("image"), py::arg("background"),
        "The PNG file `vri render -o x.png` writes, as bytes.");
  m.def("_volume_scene_json", &volume_scene_text, py::arg("volume"), py::arg("colormap") = "",
        py::arg("opacity") = "", py::arg("range") = "",
        "The scene (JSON, without its volume) of `vri render VOLUME --colormap --opacity --range`.");
  m.attr("_exr_supported") = exr_supported();
  m.def("_is_volume_file", [](const fs::path& path) { return is_volume_file(path); }, py::arg("path"),
        "Whether the path is a volume file standing where a scene does (not a scene's JSON).");
  m.def("_colormap", [](const std::string& name) -> py::object {
        const Colormap* map = find_colormap(name);
        if (!map) return py::none();
        py::list points;
        for (const ColormapPoint& p : map->points) points.append(py::make_tuple(p.x, p.r, p.g, p.b));
        return points;
      }, py::arg("name"), "A named colour map's points (x, r, g, b), x from 0 to 1; None for another name.");
  m.def("colormaps", &colormap_names, "The named colour maps a transfer function's \"colormap\" takes.");
}

}  // namespace vri::python
