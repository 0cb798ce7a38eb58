#pragma once
// The extension `vri._vri` (pybind11): one bind_* per part of the library,
// each in its own file; module.cpp puts them together.
#include <memory>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "vri/image.hpp"
#include "vri/scene.hpp"

namespace vri::python {

namespace py = pybind11;

void bind_errors(py::module_& m);     // vri::Error -> ValueError, FileError -> OSError
void bind_volumes(py::module_& m);    // Volume, Mesh (from numpy)
void bind_scenes(py::module_& m);     // Scene, load_scene
void bind_rendering(py::module_& m);  // render, error_estimate, trace
void bind_analysis(py::module_& m);   // table, compare, ray, memory budget
void bind_images(py::module_& m);     // vri.Image's files and PNG bytes, a volume's scene

// A scene from what Python passes: a Scene, a dict of SPEC §8 keys (its
// "volume" may be a Volume or a Mesh) or the path of a scene file.
std::shared_ptr<Scene> scene_of(const py::handle& object);

// A transfer function from a dict ({"points": ...}), a path or a Scene.
TransferFunction transfer_function_of(const py::handle& object);

// The image as a float32 (H, W, 4) array that takes over its memory.
py::array_t<float> to_numpy(Image image);

}  // namespace vri::python
