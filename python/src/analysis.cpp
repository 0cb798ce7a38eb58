// vri.table, vri.compare, vri.ray and the memory budget: the `vri table`,
// `vri compare` and `vri ray` commands on numpy arrays.
#include <optional>
#include <string>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "interruptible.hpp"
#include "vri/analysis.hpp"
#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "vri/render.hpp"

namespace vri::python {

namespace {

py::array_t<float> table(const py::object& tf_object, int size, int order, double length, std::optional<int> lengths,
                         std::optional<double> max_length, std::optional<std::string> builder,
                         std::optional<int> iterations, int steps, std::string accumulation, std::string backend) {
  const TransferFunction tf = transfer_function_of(tf_object);
  const TableRequest request{size,  order, length, lengths, max_length, std::move(builder), iterations, steps,
                             std::move(accumulation), std::move(backend)};
  const BuiltTable built = interruptible([&](const Cancellation&) { return build_table(tf, request); });
  // The array views the table; the capsule keeps it alive.
  auto* owner = new std::shared_ptr<const void>(built.owner);
  const py::capsule capsule(owner, [](void* p) { delete static_cast<std::shared_ptr<const void>*>(p); });
  return py::array_t<float>(built.shape, built.data.data(), capsule);
}

std::vector<ChannelDifference> compare(const py::array& a_object, const py::array& b_object, double tolerance) {
  if (!(tolerance >= 0)) throw Error("--tolerance: expected a number >= 0");
  const auto a = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(a_object);
  const auto b = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(b_object);
  if (!a || !b) throw py::error_already_set();
  const std::vector<py::ssize_t> sa(a.shape(), a.shape() + a.ndim()), sb(b.shape(), b.shape() + b.ndim());
  if (sa != sb) throw Error("vri.compare: the arrays have different shapes");
  // As `vri compare`: the last axis is the channels of an image (H, W, C).
  const int channels = a.ndim() >= 3 ? int(sa.back()) : 1;
  if (channels < 1) throw Error("vri.compare: empty arrays");
  const std::vector<float> va(a.data(), a.data() + a.size()), vb(b.data(), b.data() + b.size());
  return compare_images(va, vb, channels, tolerance);
}

py::dict ray(const py::object& scene_object, std::array<int, 2> pixel, std::optional<double> step) {
  const auto scene = scene_of(scene_object);
  const RaySignal signal = pixel_signal(*scene, pixel[0], pixel[1], step);
  const std::vector<RaySignalRow> rows = signal_rows(signal);
  const std::size_t n = rows.size();
  py::array_t<double> t(n), s(n), o0(n), o1(n), o2(n);
  py::array_t<bool> is_sample(n);
  for (std::size_t i = 0; i < n; ++i) {
    t.mutable_at(i) = rows[i].t;
    s.mutable_at(i) = rows[i].signal;
    o0.mutable_at(i) = rows[i].order[0];
    o1.mutable_at(i) = rows[i].order[1];
    o2.mutable_at(i) = rows[i].order[2];
    is_sample.mutable_at(i) = rows[i].is_sample;
  }
  py::dict out;
  out["t"] = t;
  out["signal"] = s;
  out["order0"] = o0;
  out["order1"] = o1;
  out["order2"] = o2;
  out["is_sample"] = is_sample;
  out["xi"] = py::make_tuple(signal.xi(0), signal.xi(1), signal.xi(2));
  out["samples"] = signal.sample_t().size();
  return out;
}

void set_max_memory(const py::object& size) {
  std::optional<std::uint64_t> bytes;
  if (py::isinstance<py::str>(size)) bytes = parse_byte_size(size.cast<std::string>());
  else if (size.cast<long long>() > 0) bytes = size.cast<std::uint64_t>();
  else if (size.cast<long long>() == 0) bytes = 0;  // the default again
  if (!bytes) throw Error("set_max_memory expects a size such as 1073741824, '512M' or '4G'");
  set_memory_limit(*bytes);
}

}  // namespace

void bind_analysis(py::module_& m) {
  m.def("table", &table, py::arg("tf"), py::kw_only(), py::arg("size") = 256, py::arg("order") = 1,
        py::arg("length") = 1.0, py::arg("lengths") = py::none(), py::arg("max_length") = py::none(),
        py::arg("builder") = py::none(), py::arg("iterations") = py::none(), py::arg("steps") = 0,
        py::arg("accumulation") = "fp32", py::arg("backend") = "cpu",
        "A pre-integration table as `vri table` writes it (SPEC §10), float32 premultiplied RGBA:\n"
        "order 1 (N, N, 4) indexed [s_f, s_b]; with lengths=M and max_length (M, N, N, 4) indexed\n"
        "[l, s_f, s_b]; order 2 (N, N, N, 4) indexed [s_f, s_m, s_b]. Entry i stands for\n"
        "s_lo + i (s_hi - s_lo) / (N - 1) over the control points' span. tf: a dict ({\"points\":\n"
        "[[s, r, g, b, tau], ...]}), a transfer-function file or a vri.Scene. builder: order 1\n"
        "brute, incremental (default), sliced, engel or exact; order 2 plain, fast (default) or exact.\n"
        "backend='vulkan' builds on the GPU: order 1 incremental (the default) or sliced, order 2 fast.");
  py::class_<ChannelDifference>(m, "ChannelDifference", "One channel of vri.compare.")
      .def_readonly("share_over", &ChannelDifference::share_over, "share of pixels with |a - b| > tolerance")
      .def_readonly("rms", &ChannelDifference::rms)
      .def_readonly("max", &ChannelDifference::max, "NaN when any difference is NaN")
      .def_readonly("nan", &ChannelDifference::nan, "pixels whose difference is NaN")
      .def("__repr__", [](const ChannelDifference& d) {
        return "ChannelDifference(share_over=" + py::repr(py::float_(d.share_over)).cast<std::string>() +
               ", rms=" + py::repr(py::float_(d.rms)).cast<std::string>() +
               ", max=" + py::repr(py::float_(d.max)).cast<std::string>() + ", nan=" + std::to_string(d.nan) + ")";
      });
  m.def("compare", &compare, py::arg("a"), py::arg("b"), py::arg("tolerance") = 1.0 / 255.0,
        "Per channel (the last axis of an (H, W, C) image), the share of pixels whose absolute\n"
        "difference exceeds tolerance, the RMS and the maximum difference - `vri compare`.");
  m.def("ray", &ray, py::arg("scene"), py::arg("pixel"), py::kw_only(), py::arg("step") = py::none(),
        "The scalar signal along the ray of pixel (x, y) and its order 0 (nearest-sample hold),\n"
        "1 (linear) and 2 (parabolic) approximations from the same samples - `vri ray`: a dict of\n"
        "arrays 't', 'signal', 'order0', 'order1', 'order2', 'is_sample' (8 rows per sample\n"
        "interval), 'xi' (the three errors, integral of |signal - approximation| dt) and\n"
        "'samples'. step: voxel units; None samples at cell faces and cell midpoints.");
  m.def("set_max_memory", &set_max_memory, py::arg("size"),
        "The budget for volumes, meshes and tables (`--max-memory`): bytes, or '512M', '4G'; 0\n"
        "restores the default (75% of physical memory).");
  m.def("max_memory", &memory_limit, "The current memory budget in bytes.");
}

}  // namespace vri::python
