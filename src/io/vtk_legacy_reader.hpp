#pragma once
// The legacy VTK format ("# vtk DataFile Version x.y") machinery shared by the
// unstructured-grid reader (vtk_legacy.cpp) and the STRUCTURED_POINTS reader
// (vtk_structured_points.cpp): the header, a cursor over header lines and
// ASCII or BINARY (big-endian) data, and the attribute sections (POINT_DATA,
// CELL_DATA, SCALARS, COLOR_SCALARS, FIELD, ... and METADATA blocks), whose
// arrays are located and skipped, so that only the chosen one is decoded.
// Format: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html
// ("Simple Legacy Formats").
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "vtk_values.hpp"

namespace vri::vtk::legacy {

// Reads header lines and the ASCII or binary data that follows them.
class Cursor {
 public:
  explicit Cursor(std::span<const std::byte> bytes) : bytes_(bytes) {}
  bool binary = false;

  bool at_end();
  // The next non-empty line, without its end of line.
  std::string line();
  // A raw line, possibly empty (the title).
  std::string raw_line();
  // Skips a METADATA block's lines, up to and with the empty line that ends it.
  void skip_metadata();
  // `count` values of `type` (binary: big-endian) as doubles.
  ChargedVector<double> values(Num type, std::size_t count);
  // The same values skipped: checked (present, numbers), nothing allocated.
  void skip(Num type, std::size_t count);

  std::size_t position() const { return pos_; }
  void seek(std::size_t pos) { pos_ = pos; }
  // The bytes from the position on.
  std::span<const std::byte> rest() const { return bytes_.subspan(pos_); }
  std::string_view rest_text() const {
    return {reinterpret_cast<const char*>(bytes_.data()) + pos_, bytes_.size() - pos_};
  }

 private:
  void skip_space();
  std::span<const std::byte> bytes_;
  std::size_t pos_ = 0;
};

std::vector<std::string> split(const std::string& line);
// A count from the file: a whole number of at most 2^40.
std::size_t count_of(const std::string& word, const std::string& what);
Num num_of(const std::string& word);
// Refuses a missing line (w empty) or one with fewer than n words.
void need(const std::vector<std::string>& w, std::size_t n);

struct Header {
  int version = 0;      // the major version: 5 has OFFSETS/CONNECTIVITY cells
  std::string dataset;  // UNSTRUCTURED_GRID, STRUCTURED_POINTS, ...
};
// The four header lines (magic, title, ASCII|BINARY, DATASET); sets in.binary.
Header read_header(Cursor& in);

// A point array found in the attribute sections, located in the file.
struct ArrayRef {
  std::string name;
  Num type = Num::Float32;
  std::size_t components = 1;
  std::size_t tuples = 0;  // values per component
  std::size_t at = 0;      // the cursor position of its first value
  bool color = false;  // COLOR_SCALARS: ASCII floats in [0, 1] for unsigned chars
};

// The attribute sections of a file and the point arrays they hold.
class Attributes {
 public:
  // Reads the section whose first line is `w` (POINT_DATA, CELL_DATA, an
  // attribute, FIELD, METADATA, LOOKUP_TABLE), skipping its values; false
  // when `w` starts no such section. `n_points`: the dataset's point count.
  bool read(Cursor& in, const std::vector<std::string>& w, std::size_t n_points);
  // The point array to render (choose_point_array: named, else the first
  // one-component one); vri::Error unless it holds `n_points` values.
  const ArrayRef& choose(const std::string& wanted, std::size_t n_points) const;
  // Its values as doubles (COLOR_SCALARS as unsigned chars 0..255).
  ChargedVector<double> values(Cursor& in, const ArrayRef& array) const;

 private:
  enum class Section { None, Point, Cell } section_ = Section::None;
  std::size_t section_n_ = 0;
  std::vector<ArrayRef> arrays_;
  void attribute(Cursor& in, const std::string& name, Num type, std::size_t comps, bool color = false);
};

}  // namespace vri::vtk::legacy
