// vri.Volume (a regular grid) and vri.Mesh (tetrahedra) from numpy arrays.
#include <array>
#include <cstdint>
#include <string>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "vri/error.hpp"
#include "vri/volume.hpp"

namespace vri::python {

namespace {

// Keeps a Python object (the array a volume views) alive from C++; the last
// owner may let go without the GIL, so the release takes it.
std::shared_ptr<const void> keep_alive(py::object object) {
  return std::shared_ptr<const void>(new py::object(std::move(object)), [](const void* p) {
    py::gil_scoped_acquire gil;
    delete static_cast<const py::object*>(p);
  });
}

// `a` viewed as samples of type T: no copy when it is already C-ordered,
// aligned, native T; else numpy makes such a copy (forcecast), viewed then.
template <class T>
GridVolume view_as(const py::array& a, std::array<int, 3> dims, Vec3 spacing, Vec3 origin) {
  auto typed = py::array_t<T, py::array::c_style | py::array::forcecast>::ensure(a);
  if (!typed) throw py::error_already_set();
  const std::span<const T> samples(typed.data(), static_cast<std::size_t>(typed.size()));
  return GridVolume(dims, GridVolume::SampleView(samples), keep_alive(std::move(typed)), spacing, origin);
}

Vec3 vec3(const std::array<double, 3>& v) { return {v[0], v[1], v[2]}; }
py::tuple tuple_of(Vec3 v) { return py::make_tuple(v.x, v.y, v.z); }

std::shared_ptr<GridVolume> volume_from_numpy(const py::array& a, std::array<double, 3> spacing,
                                              std::array<double, 3> origin) {
  if (a.ndim() != 3)
    throw Error("Volume.from_numpy: expected a 3-D array indexed [z, y, x], got " + std::to_string(a.ndim()) + "-D");
  const char kind = a.dtype().kind();
  if (kind != 'u' && kind != 'i' && kind != 'f')
    throw Error("Volume.from_numpy: expected a numeric array (unsigned, signed integer or float), got dtype '" +
                py::str(a.dtype()).cast<std::string>() + "'");
  // [z, y, x]: x is the last index. The count check bounds each axis (2^24).
  GridVolume::checked_sample_count({a.shape(2), a.shape(1), a.shape(0)});
  const std::array<int, 3> dims{int(a.shape(2)), int(a.shape(1)), int(a.shape(0))};
  const std::size_t size = a.itemsize();
  // The types a GridVolume keeps as they are; every other converts to float32,
  // as the file readers convert them.
  if (kind == 'u' && size == 1) return std::make_shared<GridVolume>(view_as<std::uint8_t>(a, dims, vec3(spacing), vec3(origin)));
  if (kind == 'u' && size == 2) return std::make_shared<GridVolume>(view_as<std::uint16_t>(a, dims, vec3(spacing), vec3(origin)));
  if (kind == 'i' && size == 2) return std::make_shared<GridVolume>(view_as<std::int16_t>(a, dims, vec3(spacing), vec3(origin)));
  return std::make_shared<GridVolume>(view_as<float>(a, dims, vec3(spacing), vec3(origin)));
}

// The samples as a read-only numpy array [z, y, x] that keeps the volume alive.
py::array samples_of(const std::shared_ptr<GridVolume>& v) {
  const auto& d = v->dims();
  return v->visit([&](auto samples) -> py::array {
    using T = typename decltype(samples)::value_type;
    py::capsule owner(new std::shared_ptr<GridVolume>(v),
                      [](void* p) { delete static_cast<std::shared_ptr<GridVolume>*>(p); });
    py::array_t<T> out({std::size_t(d[2]), std::size_t(d[1]), std::size_t(d[0])}, samples.data(), owner);
    out.attr("setflags")(py::arg("write") = false);
    return out;
  });
}

std::shared_ptr<TetMesh> mesh_from_numpy(const py::array& points, const py::array& cells, const py::array& scalars) {
  const auto p = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
  const auto c = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(cells);
  const auto s = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(scalars);
  if (!p || !c || !s) throw py::error_already_set();
  if (p.ndim() != 2 || p.shape(1) != 3) throw Error("Mesh.from_numpy: points must have shape (N, 3)");
  if (c.ndim() != 2 || c.shape(1) != 4) throw Error("Mesh.from_numpy: cells must have shape (M, 4)");
  if (s.ndim() != 1 || s.shape(0) != p.shape(0))
    throw Error("Mesh.from_numpy: scalars must have shape (N,), one per point (N = " + std::to_string(p.shape(0)) + ")");
  std::vector<Vec3> pts(static_cast<std::size_t>(p.shape(0)));
  for (std::size_t i = 0; i < pts.size(); ++i) pts[i] = {p.at(i, 0), p.at(i, 1), p.at(i, 2)};
  std::vector<TetMesh::Tet> tets(static_cast<std::size_t>(c.shape(0)));
  for (std::size_t t = 0; t < tets.size(); ++t)
    for (int k = 0; k < 4; ++k) {
      const std::int64_t index = c.at(t, k);
      if (index < 0 || index >= p.shape(0))
        throw Error("Mesh.from_numpy: cell " + std::to_string(t) + " names point " + std::to_string(index) +
                    ", outside [0, " + std::to_string(p.shape(0)) + ")");
      tets[t][k] = static_cast<std::int32_t>(index);
    }
  std::vector<float> values(s.data(), s.data() + s.size());
  return std::make_shared<TetMesh>(std::move(pts), std::move(tets), std::move(values));
}

std::string repr(const GridVolume& v) {
  const auto& d = v.dims();
  return "<vri.Volume " + std::to_string(d[0]) + "x" + std::to_string(d[1]) + "x" + std::to_string(d[2]) + " " +
         scalar_type_name(v.type()) + ", range [" + py::repr(py::float_(v.min_value())).cast<std::string>() + ", " +
         py::repr(py::float_(v.max_value())).cast<std::string>() + "]>";
}

}  // namespace

void bind_volumes(py::module_& m) {
  py::class_<GridVolume, std::shared_ptr<GridVolume>>(m, "Volume",
      "A scalar field on a regular grid (SPEC §1): trilinear between samples, the medium the\n"
      "box from origin to origin + (dims - 1) * spacing.")
      .def_static("from_numpy", &volume_from_numpy, py::arg("array"), py::kw_only(),
                  py::arg("spacing") = std::array<double, 3>{1, 1, 1}, py::arg("origin") = std::array<double, 3>{0, 0, 0},
                  "A volume from a 3-D numeric array indexed [z, y, x] (x fastest, as a raw file, ITK's and\n"
                  "tifffile's arrays are); spacing and origin are (x, y, z). uint8, uint16, int16 and\n"
                  "float32 arrays in C order are viewed without a copy (do not change them while the\n"
                  "volume lives); any other numeric dtype or order is copied, converted to float32 where\n"
                  "the type is not kept. Raises ValueError for non-finite samples, dims < 2 or bad spacing.")
      .def_property_readonly("dims", [](const GridVolume& v) {
            const auto& d = v.dims();
            return py::make_tuple(d[0], d[1], d[2]);
          }, "(nx, ny, nz)")
      .def_property_readonly("shape", [](const GridVolume& v) {
            const auto& d = v.dims();
            return py::make_tuple(d[2], d[1], d[0]);
          }, "(nz, ny, nx), the numpy shape")
      .def_property_readonly("spacing", [](const GridVolume& v) { return tuple_of(v.spacing()); }, "(sx, sy, sz)")
      .def_property_readonly("origin", [](const GridVolume& v) { return tuple_of(v.origin()); }, "(ox, oy, oz)")
      .def_property_readonly("dtype", [](const GridVolume& v) { return scalar_type_name(v.type()); },
                             "the stored sample type: uint8, uint16, int16 or float32")
      .def_property_readonly("range", [](const GridVolume& v) {
            return std::pair<float, float>(v.min_value(), v.max_value());
          }, "(min, max) of the samples")
      .def("to_numpy", &samples_of, "The samples, read-only, indexed [z, y, x] (no copy).")
      .def("__repr__", &repr);

  py::class_<TetMesh, std::shared_ptr<TetMesh>>(m, "Mesh",
      "A tetrahedral mesh with one scalar per point (SPEC §2); the field is linear in each\n"
      "tetrahedron. Inverted tetrahedra are reoriented and degenerate ones dropped.")
      .def_static("from_numpy", &mesh_from_numpy, py::arg("points"), py::arg("cells"), py::arg("scalars"),
                  "A mesh from points (N, 3), cells (M, 4) of point indices and scalars (N,).\n"
                  "Raises ValueError for an index out of range, a non-finite value or a face shared\n"
                  "by more than two tetrahedra.")
      .def_property_readonly("n_points", [](const TetMesh& t) { return t.points().size(); })
      .def_property_readonly("n_cells", [](const TetMesh& t) { return t.size(); },
                             "tetrahedra kept (degenerate ones dropped)")
      .def_property_readonly("dropped", &TetMesh::dropped, "degenerate tetrahedra dropped")
      .def_property_readonly("range", [](const TetMesh& t) {
            return std::pair<float, float>(t.min_value(), t.max_value());
          }, "(min, max) of the scalars")
      .def("__repr__", [](const TetMesh& t) {
        return "<vri.Mesh " + std::to_string(t.points().size()) + " points, " + std::to_string(t.size()) +
               " tetrahedra>";
      });
}

}  // namespace vri::python
