// VTK legacy unstructured grids of tetrahedra (see io/vtk_legacy.hpp);
// the header, cursor and attribute sections are vtk_legacy_reader, shared
// with the STRUCTURED_POINTS reader (vtk_structured_points.cpp).
// Format: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html
#include "io/vtk_legacy.hpp"

#include <optional>
#include <utility>
#include <vector>

#include "core/checked_size.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "vtk_legacy_reader.hpp"
#include "vtk_values.hpp"

namespace vri {

namespace {

using namespace vtk::legacy;

TetMesh parse(Cursor& in, const std::string& wanted) {
  const Header header = read_header(in);
  if (header.dataset != "UNSTRUCTURED_GRID")
    throw Error("dataset is " + header.dataset + "; only UNSTRUCTURED_GRID meshes are supported");
  const bool offsets_form = header.version >= 5;  // 5.x: OFFSETS/CONNECTIVITY

  std::optional<ChargedVector<double>> xyz;
  ChargedVector<std::int64_t> connectivity, offsets, types;
  bool have_cells = false, have_types = false;
  Attributes attributes;
  std::size_t n_points = 0;

  while (!in.at_end()) {
    const auto w = split(in.line());
    if (w.empty()) continue;
    const std::string& key = w[0];
    if (key == "POINTS") {
      need(w, 3);
      n_points = count_of(w[1], "point");
      xyz = in.values(num_of(w[2]), checked_product({3, n_points}, "the declared point count"));
    } else if (key == "CELLS") {
      need(w, 3);
      const std::size_t n = count_of(w[1], "cell"), size = count_of(w[2], "cell list");
      if (offsets_form) {  // n offsets (one more than the cells), then the connectivity
        const auto off = split(in.line());
        if (off.size() < 2 || off[0] != "OFFSETS") throw Error("expected OFFSETS after CELLS");
        offsets = vtk::to_indices(in.values(num_of(off[1]), n), "OFFSETS");
        const auto conn = split(in.line());
        if (conn.size() < 2 || conn[0] != "CONNECTIVITY") throw Error("expected CONNECTIVITY after OFFSETS");
        connectivity = vtk::to_indices(in.values(num_of(conn[1]), size), "CONNECTIVITY");
      } else {  // per cell, its point count and then its points (int32)
        const auto list = vtk::to_indices(in.values(vtk::Num::Int32, size), "CELLS");
        offsets.push_back(0);
        for (std::size_t c = 0, at = 0; c < n; ++c) {
          if (at >= list.size() || list[at] + 1 > std::int64_t(list.size() - at))
            throw Error("CELLS list ends inside cell " + std::to_string(c));
          for (std::int64_t k = 1; k <= list[at]; ++k) connectivity.push_back(list[at + k]);
          at += list[at] + 1;
          offsets.push_back(std::int64_t(connectivity.size()));
        }
      }
      have_cells = true;
    } else if (key == "CELL_TYPES") {
      need(w, 2);
      types = vtk::to_indices(in.values(vtk::Num::Int32, count_of(w[1], "cell type")), "CELL_TYPES");
      have_types = true;
    } else if (!attributes.read(in, w, n_points)) {
      throw Error("unsupported section '" + key + "'");
    }
  }
  if (!xyz) throw Error("no POINTS");
  if (!have_cells) throw Error("no CELLS");
  if (!have_types) throw Error("no CELL_TYPES");
  if (offsets.empty() && !types.empty()) throw Error("no cells");
  const auto chosen = attributes.values(in, attributes.choose(wanted, n_points));
  std::vector<float> scalars(chosen.begin(), chosen.end());
  return TetMesh(vtk::points_from(*xyz), vtk::tets_from_cells(connectivity, offsets, types), std::move(scalars));
}

}  // namespace

TetMesh parse_vtk_legacy(std::span<const std::byte> bytes, const std::string& scalars, const std::string& source) {
  try {
    vtk::legacy::Cursor in(bytes);
    return parse(in, scalars);
  } catch (const Error& e) {
    throw Error(source + ": " + e.what());
  }
}

TetMesh read_vtk_legacy(const std::filesystem::path& path, const std::string& scalars) {
  const auto bytes = read_file(path);
  return parse_vtk_legacy(bytes, scalars, "mesh '" + path.string() + "'");
}

}  // namespace vri
