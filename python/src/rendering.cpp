// vri.render, vri.error_estimate, vri.trace: a scene rendered as the CLI's
// `vri render` renders it (the same SceneOverrides and SceneRenderer), with
// the GIL released while the C++ threads work, and Ctrl-C heard (interruptible.hpp).
#include <optional>
#include <string>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "vri/error.hpp"
#include "vri/methods.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri::python {

namespace {

template <class T>
std::optional<T> keyword(const char* function, const std::string& key, const py::handle& value) {
  try {
    return value.cast<T>();
  } catch (const py::cast_error&) {
    throw py::type_error(std::string(function) + "(): '" + key + "' expected " +
                         (std::is_same_v<T, std::string> ? "a str" : std::is_same_v<T, bool> ? "a bool"
                          : std::is_same_v<T, int> ? "an int" : "a number") +
                         ", got " + py::type::of(value).attr("__name__").cast<std::string>());
  }
}

// The keyword arguments shared by render, error_estimate and trace: the
// `vri render` flags by their Python names (None leaves the scene's value).
struct RenderRequest {
  SceneOverrides overrides;
  int threads = 0;
  Backend backend = Backend::Cpu;
};

RenderRequest request_of(const char* function, const py::kwargs& kwargs) {
  RenderRequest r;
  SceneOverrides& o = r.overrides;
  for (const auto& [k, v] : kwargs) {
    const std::string key = k.cast<std::string>();
    if (v.is_none()) continue;
    auto number = [&] { return keyword<double>(function, key, v); };
    auto integer = [&] { return keyword<int>(function, key, v); };
    auto text = [&] { return keyword<std::string>(function, key, v); };
    if (key == "method") o.method = text();
    else if (key == "step") o.step = number();
    else if (key == "tolerance") o.tolerance = number();
    else if (key == "table_size") o.table_size = integer();
    else if (key == "iterations") o.iterations = integer();
    else if (key == "width") o.width = integer();
    else if (key == "height") o.height = integer();
    else if (key == "termination") o.termination = number();
    else if (key == "skip_empty") o.skip_empty = keyword<bool>(function, key, v);
    else if (key == "double") o.float_math = !*keyword<bool>(function, key, v);
    else if (key == "h0") o.h0 = number();
    else if (key == "hmin") o.hmin = number();
    else if (key == "hmax") o.hmax = number();
    else if (key == "strategy") o.strategy = text();
    else if (key == "fit") o.fit = keyword<bool>(function, key, v);
    else if (key == "azimuth") o.azimuth = number();
    else if (key == "elevation") o.elevation = number();
    else if (key == "roll") o.roll = number();
    else if (key == "zoom") o.zoom = number();
    else if (key == "backend") r.backend = parse_backend(*text());
    else if (key == "clip") {  // a dict as the scene's "clip" (SPEC §12)
      const auto text = py::module_::import("json").attr("dumps")(v).cast<std::string>();
      o.clip = parse_clip(text, std::string(function) + "()");
    } else if (key == "max_samples") o.max_samples = number();
    else if (key == "max_work") o.max_work = number();
    else if (key == "jitter") {
      const long long seed = *keyword<long long>(function, key, v);
      if (seed < 0 || seed > (1LL << 53))  // the CLI's --jitter and the scene's method.jitter say the same
        throw py::value_error(std::string(function) + "(): jitter: expected an integer seed in [0, 2^53], found " +
                              std::to_string(seed));
      o.jitter = static_cast<std::uint64_t>(seed);
    } else if (key == "threads") r.threads = *integer();
    else throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" + key + "'");
  }
  checked_threads(r.threads);
  return r;
}

// The scene with the overrides applied: a vri.Scene is copied (its samples
// shared), a path or a dict is loaded straight into the value.
Scene scene_for(const py::handle& scene, const RenderRequest& request) {
  Scene copy = py::isinstance<Scene>(scene) ? Scene(scene.cast<const Scene&>()) : Scene(std::move(*scene_of(scene)));
  apply_overrides(copy, request.overrides);
  return copy;
}

void warn(const std::string& message) {
  if (PyErr_WarnEx(PyExc_RuntimeWarning, message.c_str(), 2) != 0) throw py::error_already_set();
}

py::array_t<float> render(const py::object& scene_object, const py::kwargs& kwargs) {
  const RenderRequest request = request_of("render", kwargs);
  const Scene scene = scene_for(scene_object, request);
  std::optional<std::string> transparent;
  Image image = interruptible([&](const Cancellation& cancel) {
    const SceneRenderer renderer(scene, request.backend);
    Image rendered = renderer.render({.threads = request.threads, .cancel = cancel.flag()});
    transparent = transparency_cause(rendered, scene, renderer.camera());
    return rendered;
  });
  if (transparent) warn("vri: every pixel is transparent: " + *transparent);
  return to_numpy(std::move(image));
}

py::array_t<float> error_estimate(const py::object& scene_object, const py::kwargs& kwargs) {
  const RenderRequest request = request_of("error_estimate", kwargs);
  const Scene scene = scene_for(scene_object, request);
  Image estimate = interruptible([&](const Cancellation& cancel) {
    return SceneRenderer(scene, request.backend).render_error_estimate({.threads = request.threads, .cancel = cancel.flag()});
  });
  return to_numpy(std::move(estimate));
}

py::dict trace(const py::object& scene_object, std::array<int, 2> pixel, const py::kwargs& kwargs) {
  const RenderRequest request = request_of("trace", kwargs);
  const Scene scene = scene_for(scene_object, request);
  RayStats stats;
  stats.record_steps = true;
  {
    py::gil_scoped_release release;
    const SceneRenderer renderer(scene);
    const ErrorEstimatingIntegrator& integrator = renderer.error_estimating("vri.trace");
    const Camera& camera = renderer.camera();
    const auto [px, py] = pixel;
    if (px < 0 || py < 0 || px >= camera.width() || py >= camera.height())
      throw Error("vri.trace: pixel (" + std::to_string(px) + ", " + std::to_string(py) + ") lies outside the image");
    integrator.integrate(camera.ray(px, py), stats);
  }
  const double unit = scene.grid().voxel_unit();
  const std::size_t n = stats.steps.size();
  py::array_t<bool> outer(n);
  py::array_t<double> t(n), h(n), alpha(n);
  for (std::size_t i = 0; i < n; ++i) {
    const AdaptiveStep& s = stats.steps[i];
    outer.mutable_at(i) = s.outer;
    t.mutable_at(i) = s.t / unit;
    h.mutable_at(i) = s.h / unit;
    alpha.mutable_at(i) = s.alpha;
  }
  py::dict out;
  out["outer"] = outer;
  out["t"] = t;
  out["h"] = h;
  out["alpha"] = alpha;
  return out;
}

const char* kKeywords =
    "Keyword arguments override the scene as the `vri render` flags do (None keeps the scene's):\n"
    "method, step, tolerance, table_size, iterations, width, height, threads (0: all cores),\n"
    "termination, skip_empty (False: --no-skip), double (True: --double), h0, hmin, hmax,\n"
    "strategy, max_samples, max_work, jitter (riemann: a seed), fit (frame the volume), azimuth,\n"
    "elevation, roll (degrees), zoom, backend ('cpu' or 'vulkan': vri.devices() lists the GPUs).\n"
    "Raises ValueError with the CLI's message for bad values.";

}  // namespace

py::array_t<float> to_numpy(Image image) {
  const auto h = static_cast<std::size_t>(image.height()), w = static_cast<std::size_t>(image.width());
  auto* data = new ZeroedFloats(std::move(image).release());
  const py::capsule owner(data, [](void* p) { delete static_cast<ZeroedFloats*>(p); });
  return py::array_t<float>({h, w, std::size_t{4}}, data->data(), owner);
}

// The method registry (vri/methods.hpp), one dict a method.
py::list methods() {
  py::list out;
  for (const MethodInfo& info : vri::methods()) {
    py::dict d;
    d["name"] = std::string(info.name);
    d["paper"] = std::string(info.paper);
    d["grid"] = info.grid;
    d["mesh"] = info.mesh;
    d["gpu_grid"] = info.gpu_grid;
    d["gpu_mesh"] = info.gpu_mesh;
    d["distributed"] = info.distributed;
    d["termination"] = info.termination;
    d["jitter"] = info.jitter;
    py::list parameters;
    for (const std::string_view key : info.parameters) parameters.append(std::string(key));
    d["parameters"] = parameters;
    out.append(d);
  }
  return out;
}

py::list method_parameters() {
  py::list out;
  for (const MethodParameter& p : vri::method_parameters()) {
    py::dict d;
    d["key"] = std::string(p.key);
    d["flag"] = std::string(p.flag);
    d["expects"] = std::string(p.expects);
    out.append(d);
  }
  return out;
}

void bind_rendering(py::module_& m) {
  m.def("methods", &methods,
        "The integration methods (SPEC §9), one dict each: name, paper, and what it supports -\n"
        "grid, mesh (the volume kinds it renders), gpu_grid, gpu_mesh (backend='vulkan'),\n"
        "distributed (mpirun), termination (early ray termination), jitter, and parameters (the\n"
        "method keys that shape its image). The CLI, the viewer and the checks read the same\n"
        "list (vri/methods.hpp).");
  m.def("method_parameters", &method_parameters,
        "The numeric method parameters, one dict each: key (the scene's method.KEY and render()'s\n"
        "keyword), flag (the command line's, or '') and expects (its rule in words). One check holds\n"
        "each for scene files, flags, the viewer and render() alike.");
  m.def("devices", &list_vulkan_devices,
        "The Vulkan devices backend='vulkan' can use, one str each (`vri devices`): index, name, type,\n"
        "Vulkan version. [] when there are none; ValueError when vri or the machine lacks Vulkan.");
  m.def("render", &render, py::arg("scene"),
        (std::string("Renders a scene (a vri.Scene, a dict of SPEC §8 keys or a scene file path) and\n"
                     "returns float32 (H, W, 4): premultiplied RGBA before the background, row 0 at the\n"
                     "top - the same bytes as `vri render SCENE -o OUT.npy` with the same settings. The\n"
                     "GIL is released while rendering. Warns (RuntimeWarning) when every pixel is transparent.\n\n") +
         kKeywords).c_str());
  m.def("error_estimate", &error_estimate, py::arg("scene"),
        (std::string("The per-pixel error estimate of method 'adaptive' (`vri render --error-estimate`):\n"
                     "float32 (H, W, 4), each channel the sum of the ray's accepted error terms.\n\n") +
         kKeywords).c_str());
  m.def("trace", &trace, py::arg("scene"), py::arg("pixel"),
        (std::string("The steps method 'adaptive' accepts along the ray of pixel (x, y) (`vri render\n"
                     "--trace`): a dict of arrays 'outer' (bool: outer or inner integral), 't', 'h' (voxel\n"
                     "units) and 'alpha'.\n\n") +
         kKeywords).c_str());
}

}  // namespace vri::python
