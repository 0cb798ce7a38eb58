#pragma once
// The VTK XML file machinery shared by the .vtu (unstructured grid) and .vti
// (image data) readers: enough XML for VTK files, the <VTKFile> attributes
// (byte_order, header_type, compressor), one <Piece>, the DataArrays of each
// section in format "ascii", inline "binary" (base64) or "appended" (raw or
// base64 encoding), optionally compressed by vtkZLibDataCompressor, with
// UInt32 or UInt64 headers, either byte order. Every size a binary header
// declares is checked against the bytes present before anything is allocated.
// Format: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html
// ("XML File Formats"; binary data: a header of block sizes, then the data).
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "vri/error.hpp"
#include "vtk_values.hpp"

namespace vri::vtk::xml {

// One XML tag (no entities in the attributes VTK writes).
struct Tag {
  std::string name;
  std::map<std::string, std::string> attrs;
  bool closing = false, self_closing = false;
  std::size_t end = 0;  // just after '>'
  std::string attr(const std::string& key, const std::string& def = "") const {
    const auto it = attrs.find(key);
    return it == attrs.end() ? def : it->second;
  }
};

// The next tag at or after `pos` (comments and declarations skipped); nullopt at the end.
std::optional<Tag> next_tag(std::string_view text, std::size_t& pos);

// How the binary arrays of a file are laid out (the <VTKFile> attributes).
enum class Compressor { None, ZLib, LZ4 };  // vtkZLibDataCompressor, vtkLZ4DataCompressor
struct Format {
  bool big_endian = false;
  Num header = Num::UInt32;
  Compressor compressor = Compressor::None;
};

struct Array {
  std::string section, name, format;
  Num type = Num::Float32;
  std::size_t components = 1;
  std::size_t content_begin = 0, content_end = 0;  // inline text
  std::size_t offset = 0;                          // appended
};

// A VTK XML file of one dataset type, scanned: its arrays located, nothing decoded.
struct Document {
  std::string_view text;
  Format format;
  Tag dataset;                 // <ImageData ...>, <UnstructuredGrid>
  Tag piece;                   // the one <Piece>
  std::string active_scalars;       // <PointData Scalars="...">
  std::string active_cell_scalars;  // <CellData Scalars="...">
  std::vector<Array> arrays;
  std::optional<std::size_t> appended;  // first byte of the appended data (after '_')
  std::string appended_encoding;

  // The first array of `section` named `name` (any name when empty), or null.
  const Array* find(const std::string& section, const std::string& name = "") const;
  // The point array to render: choose_point_array over the PointData arrays
  // with `active` as the active scalars (active_scalars, or "" for none).
  const Array& point_array(const std::string& wanted, const std::string& active) const;
  // The same over the arrays of `section` (PointData or CellData).
  const Array& section_array(const std::string& section, const std::string& wanted, const std::string& active) const;
  // Whether `section` holds scalars to render: the one named `wanted`, or
  // (none wanted) a one-component array.
  bool has_scalars(const std::string& section, const std::string& wanted) const;
};

// Scans `text`; vri::Error unless it is a <VTKFile> of `type` with one <Piece>.
Document read_document(std::string_view text, const std::string& type);

// The bytes of a binary or appended array of `bytes` bytes: every size its
// header declares is checked against the data present on construction, before
// anything of the array's size is allocated; copy_to() then writes the bytes
// (decompressed) into a span of exactly that size.
class Payload {
 public:
  Payload(const Document& doc, const Array& array, std::uint64_t bytes);
  Payload(const Payload&) = delete;
  Payload& operator=(const Payload&) = delete;
  void copy_to(std::span<std::byte> out) const;

 private:
  struct Block {
    std::uint64_t at, csize, usize;
  };
  Format format_;
  ChargedVector<std::byte> decoded_;  // base64 decoded
  std::span<const std::byte> stream_;
  std::vector<Block> blocks_;  // compressed blocks; empty: stored at data_at_
  std::uint64_t data_at_ = 0, bytes_ = 0;
};

// `count` values of an array as doubles (ASCII, binary or appended).
ChargedVector<double> values(const Document& doc, const Array& array, std::size_t count);

// Runs f(); a vri::Error it throws is rethrown prefixed with "DataArray 'name': ".
template <class F>
auto for_array(const Array& array, F&& f) {
  try {
    return f();
  } catch (const Error& e) {
    throw Error("DataArray '" + array.name + "': " + e.what());
  }
}

}  // namespace vri::vtk::xml
