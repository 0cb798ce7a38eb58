#pragma once
// VTK legacy unstructured grids of tetrahedra (the "vtk DataFile" format,
// versions 2.0 to 5.1, ASCII or BINARY; binary legacy data is big-endian).
// Points of any numeric type; cells as count-prefixed lists (versions < 5)
// or OFFSETS/CONNECTIVITY (5.1); CELL_TYPES must all be VTK_TETRA (10).
// The field is a one-component point-data array - SCALARS or a FIELD array -
// chosen by name; every other section is skipped.
// Regular grids: DATASET STRUCTURED_POINTS (DIMENSIONS, SPACING or the older
// ASPECT_RATIO, ORIGIN; POINT_DATA as above, COLOR_SCALARS included) read as
// a GridVolume; uint8, uint16, int16 and float32 keep their type, the others
// become float.
// Format: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

#include "vri/volume.hpp"

namespace vri {

// scalars: the point array to use; empty picks the first one in the file.
// Throws vri::Error with one line naming the file and the problem.
TetMesh read_vtk_legacy(const std::filesystem::path& path, const std::string& scalars = "");
TetMesh parse_vtk_legacy(std::span<const std::byte> bytes, const std::string& scalars,
                         const std::string& source);

// STRUCTURED_POINTS as a regular grid; scalars as above.
GridVolume read_vtk_structured_points(const std::filesystem::path& path, const std::string& scalars = "");
GridVolume parse_vtk_structured_points(std::span<const std::byte> bytes, const std::string& scalars,
                                       const std::string& source);
// True when `head` (a file's first bytes; the first 1 KiB is looked at) is a
// legacy VTK header whose DATASET line says STRUCTURED_POINTS: a grid .vtk,
// not a mesh .vtk.
bool vtk_legacy_is_structured_points(std::span<const std::byte> head);

}  // namespace vri
