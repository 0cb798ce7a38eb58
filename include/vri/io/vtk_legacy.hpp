#pragma once
// VTK legacy unstructured grids of tetrahedra (the "vtk DataFile" format,
// versions 2.0 to 5.1, ASCII or BINARY; binary legacy data is big-endian).
// Points of any numeric type; cells as count-prefixed lists (versions < 5)
// or OFFSETS/CONNECTIVITY (5.1); CELL_TYPES must all be VTK_TETRA (10).
// The field is a one-component point-data array - SCALARS or a FIELD array -
// chosen by name; every other section is skipped.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

#include "vri/mesh/tet_mesh.hpp"

namespace vri {

// scalars: the point array to use; empty picks the first one in the file.
// Throws vri::Error with one line naming the file and the problem.
TetMesh read_vtk_legacy(const std::filesystem::path& path, const std::string& scalars = "");
TetMesh parse_vtk_legacy(std::span<const std::byte> bytes, const std::string& scalars,
                         const std::string& source);

}  // namespace vri
