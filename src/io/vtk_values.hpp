#pragma once
// The numeric types of VTK files (legacy names and XML names) and their
// decoding to double, shared by the legacy and the .vtu readers.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "vri/mesh/tet_mesh.hpp"

namespace vri::vtk {

enum class Num { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };

// Legacy names (unsigned_char, short, int, long, float, double, vtktypeint64, ...)
// and XML names (Int8 ... Float64); nullopt for an unknown name.
std::optional<Num> parse_num(const std::string& name);
std::size_t num_size(Num type);

// Decodes `count` packed values (little or big endian) to double.
std::vector<double> decode(std::span<const std::byte> bytes, Num type, std::size_t count, bool big_endian);

// Converts values used as indices, refusing negative and fractional ones.
// `what` names the array in the error message.
std::vector<std::int64_t> to_indices(const std::vector<double>& values, const std::string& what);

// The tetrahedra of an unstructured grid given as cell i = connectivity[offsets[i] ..
// offsets[i+1]) with VTK cell type types[i]. Any cell other than VTK_TETRA (10)
// with 4 points is refused, naming the cell and its type.
std::vector<TetMesh::Tet> tets_from_cells(const std::vector<std::int64_t>& connectivity,
                                          const std::vector<std::int64_t>& offsets,
                                          const std::vector<std::int64_t>& types);

// Points given as 3 doubles each.
std::vector<Vec3> points_from(const std::vector<double>& xyz);

}  // namespace vri::vtk
