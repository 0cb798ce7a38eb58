// The extension `vri._vri` of the Python package `vri` (python/vri/__init__.py
// re-exports it and adds vri.Image and the array front door of vri.render).
#include <pybind11/pybind11.h>

#include <string>

#include "bindings.hpp"
#include "vri/render.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"

namespace vri::python {

void bind_errors(py::module_&) {
  // The CLI's one-line messages, as the Python exception a caller expects.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const FileError& e) {
      PyErr_SetString(PyExc_OSError, message_line(e.what()).c_str());
    } catch (const Error& e) {
      PyErr_SetString(PyExc_ValueError, message_line(e.what()).c_str());
    }
  });
}

}  // namespace vri::python

PYBIND11_MODULE(_vri, m) {
  static const std::string doc =
      "vri: volume rendering with measurable accuracy.\n\n"
      "Render regular-grid volumes and tetrahedral meshes with the integration methods of\n"
      "SPEC §9 (" + vri::method_names() + ") and compare them against the exact integral.\n"
      "Images are float32 numpy arrays (H, W, 4), premultiplied RGBA, the same bytes as\n"
      "`vri render -o X.npy`.";
  m.doc() = doc.c_str();
  m.attr("__version__") = VRI_VERSION;
  // Whether this build has the GPU backend (backend="vulkan"; docs/GPU.md).
  m.attr("has_vulkan") = vri::vulkan_backend_built();
  vri::python::bind_errors(m);
  vri::python::bind_volumes(m);
  vri::python::bind_scenes(m);
  vri::python::bind_rendering(m);
  vri::python::bind_analysis(m);
  vri::python::bind_images(m);
}
