#pragma once
// The numeric types of VTK files (legacy names and XML names), their decoding
// from packed bytes and from ASCII text, and the choice of the point array to
// render: shared by the legacy (.vtk) and the XML (.vtu, .vti) readers.
// Formats: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "vri/memory.hpp"
#include "vri/volume.hpp"

namespace vri::vtk {

enum class Num { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };

// Legacy names (unsigned_char, short, int, long, float, double, vtktypeint64, ...)
// and XML names (Int8 ... Float64); nullopt for an unknown name.
std::optional<Num> parse_num(const std::string& name);
std::size_t num_size(Num type);
// The XML name (Int8 ... Float64), for messages.
std::string num_name(Num type);

// Decodes `count` packed values (little or big endian) to double.
ChargedVector<double> decode(std::span<const std::byte> bytes, Num type, std::size_t count, bool big_endian);

// Refuses `count` ASCII values in `bytes_left` bytes of text before anything is
// allocated: each value takes at least two bytes (a digit and a separator).
void check_ascii_count(std::uint64_t count, std::uint64_t bytes_left);
// Parses out.size() / num_size(type) whitespace-separated numbers from `text`
// into `out`, packed in `type` in this machine's byte order (floats parsed as
// float, integers checked to be whole and in range); returns the characters
// consumed. vri::Error "data ends early" or "bad number".
std::size_t parse_ascii(Num type, std::string_view text, std::span<std::byte> out);

// Converts values used as indices, refusing negative and fractional ones.
// `what` names the array in the error message.
ChargedVector<std::int64_t> to_indices(std::span<const double> values, const std::string& what);

// The tetrahedra of an unstructured grid given as cell i = connectivity[offsets[i] ..
// offsets[i+1]) with VTK cell type types[i]. Any cell other than VTK_TETRA (10)
// with 4 points is refused, naming the cell and its type.
std::vector<TetMesh::Tet> tets_from_cells(std::span<const std::int64_t> connectivity,
                                          std::span<const std::int64_t> offsets,
                                          std::span<const std::int64_t> types);

// Points given as 3 doubles each.
std::vector<Vec3> points_from(std::span<const double> xyz);

// A point-data array as the readers list it.
struct NamedArray {
  std::string name;
  std::size_t components = 1;
};
// The index of the array to render: the one named `wanted`; else, when
// `wanted` is empty, the file's active scalars `active` if that is one
// component, else the first one-component array. vri::Error when the named
// array is missing or has several components, or no array has one.
std::size_t choose_point_array(const std::vector<NamedArray>& arrays, const std::string& wanted,
                               const std::string& active = "");

}  // namespace vri::vtk
