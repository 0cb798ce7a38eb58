#pragma once
// VTK XML unstructured grids (.vtu) of tetrahedra as ParaView and VTK write
// them: one Piece; DataArrays in format "ascii", inline "binary" (base64) or
// "appended" (raw or base64 encoding), optionally compressed by
// vtkZLibDataCompressor, with UInt32 or UInt64 headers, either byte order.
// Cells must all be VTK_TETRA (10). The field is a one-component PointData
// array chosen by name (the first when none is named).
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

#include "vri/volume.hpp"

namespace vri {

// Throws vri::Error with one line naming the file and the problem.
TetMesh read_vtu(const std::filesystem::path& path, const std::string& scalars = "");
TetMesh parse_vtu(std::span<const std::byte> bytes, const std::string& scalars, const std::string& source);

}  // namespace vri
