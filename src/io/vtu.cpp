// VTK XML unstructured grids (.vtu) of tetrahedra: the file machinery (XML,
// base64, appended data, zlib blocks) is vtk_xml, shared with the .vti reader.
// Format: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html
#include "io/vtu.hpp"

#include <charconv>
#include <string_view>
#include <vector>

#include "core/checked_size.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "vtk_values.hpp"
#include "vtk_xml.hpp"

namespace vri {

namespace {

TetMesh parse(std::string_view text, const std::string& wanted) {
  const vtk::xml::Document doc = vtk::xml::read_document(text, "UnstructuredGrid");
  auto count = [&](const char* key) {
    const std::string v = doc.piece.attr(key);
    std::size_t n = 0;
    const auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
    if (ec != std::errc() || p != v.data() + v.size()) throw Error("Piece lacks a valid " + std::string(key));
    return n;
  };
  const std::size_t n_points = count("NumberOfPoints"), n_cells = count("NumberOfCells");
  const vtk::xml::Array* pts = doc.find("Points");
  const vtk::xml::Array* conn = doc.find("Cells", "connectivity");
  const vtk::xml::Array* offs = doc.find("Cells", "offsets");
  const vtk::xml::Array* types = doc.find("Cells", "types");
  if (!pts || pts->components != 3) throw Error("no Points array of 3 components");
  if (!conn || !offs || !types) throw Error("Cells needs connectivity, offsets and types arrays");
  const auto xyz = vtk::xml::values(doc, *pts, checked_product({3, n_points}, "NumberOfPoints"));
  auto ends = vtk::to_indices(vtk::xml::values(doc, *offs, n_cells), "offsets");
  ChargedVector<std::int64_t> starts(1, 0);
  starts.insert(starts.end(), ends.begin(), ends.end());  // VTK stores where each cell ends
  const std::size_t n_conn = ends.empty() ? 0 : static_cast<std::size_t>(ends.back());
  const auto connectivity = vtk::to_indices(vtk::xml::values(doc, *conn, n_conn), "connectivity");
  const auto cell_types = vtk::to_indices(vtk::xml::values(doc, *types, n_cells), "types");
  // Unnamed: the first one-component array (docs/MESHES.md), not the active scalars.
  const auto s = vtk::xml::values(doc, doc.point_array(wanted, ""), n_points);
  return TetMesh(vtk::points_from(xyz), vtk::tets_from_cells(connectivity, starts, cell_types),
                 std::vector<float>(s.begin(), s.end()));
}

}  // namespace

TetMesh parse_vtu(std::span<const std::byte> bytes, const std::string& scalars, const std::string& source) {
  try {
    return parse(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), scalars);
  } catch (const Error& e) {
    throw Error(source + ": " + e.what());
  }
}

TetMesh read_vtu(const std::filesystem::path& path, const std::string& scalars) {
  const auto bytes = read_file(path);
  return parse_vtu(bytes, scalars, "mesh '" + path.string() + "'");
}

}  // namespace vri
