#include "vri/io/vtk_legacy.hpp"

#include <cctype>
#include <charconv>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "vri/core/checked_size.hpp"
#include "vri/core/error.hpp"
#include "vri/core/memory_limit.hpp"
#include "vri/io/file_io.hpp"
#include "vtk_values.hpp"

namespace vri {

namespace {

// Reads header lines and the ASCII or binary data that follows them.
class Cursor {
 public:
  Cursor(std::span<const std::byte> bytes) : bytes_(bytes) {}
  bool binary = false;

  bool at_end() {
    skip_space();
    return pos_ >= bytes_.size();
  }
  // The next non-empty line, without its end of line.
  std::string line() {
    skip_space();
    std::string out;
    while (pos_ < bytes_.size() && char(bytes_[pos_]) != '\n') out += char(bytes_[pos_++]);
    if (pos_ < bytes_.size()) ++pos_;
    if (!out.empty() && out.back() == '\r') out.pop_back();
    return out;
  }
  // A raw line, possibly empty (the title).
  std::string raw_line() {
    std::string out;
    while (pos_ < bytes_.size() && char(bytes_[pos_]) != '\n') out += char(bytes_[pos_++]);
    if (pos_ < bytes_.size()) ++pos_;
    return out;
  }
  std::vector<double> values(vtk::Num type, std::size_t count) {
    if (binary) {
      auto out = vtk::decode(bytes_.subspan(pos_), type, count, /*big_endian=*/true);
      pos_ += count * vtk::num_size(type);
      return out;
    }
    // Each ASCII value takes at least two bytes (a digit and a separator):
    // a count the remaining bytes cannot hold is refused before allocating.
    if (count > (bytes_.size() - pos_) / 2 + 1)
      throw Error("data ends early: " + std::to_string(count) + " values declared, " +
                  std::to_string(bytes_.size() - pos_) + " bytes left");
    check_allocation(count, sizeof(double), "a mesh array of " + std::to_string(count) + " values");
    std::vector<double> out(count);
    for (std::size_t i = 0; i < count; ++i) {
      skip_space();
      const char* first = reinterpret_cast<const char*>(bytes_.data()) + pos_;
      const char* last = reinterpret_cast<const char*>(bytes_.data()) + bytes_.size();
      if (first < last && *first == '+') ++first;
      const auto [ptr, ec] = std::from_chars(first, last, out[i]);
      if (ec != std::errc() || (ptr < last && !std::isspace(static_cast<unsigned char>(*ptr))))
        throw Error(first == last ? "data ends early" : "bad number '" + std::string(first, std::min<std::size_t>(20, last - first)) + "'");
      pos_ = ptr - reinterpret_cast<const char*>(bytes_.data());
    }
    return out;
  }

 private:
  void skip_space() {
    while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
  }
  std::span<const std::byte> bytes_;
  std::size_t pos_ = 0;
};

std::vector<std::string> split(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::size_t count_of(const std::string& word, const std::string& what) {
  std::size_t n = 0;
  const auto [ptr, ec] = std::from_chars(word.data(), word.data() + word.size(), n);
  if (ec != std::errc() || ptr != word.data() + word.size() || n > (std::size_t{1} << 40))
    throw Error("bad " + what + " count '" + word + "'");
  return n;
}

vtk::Num num_of(const std::string& word) {
  const auto t = vtk::parse_num(word);
  if (!t) throw Error("unsupported data type '" + word + "'");
  return *t;
}

TetMesh parse(Cursor& in, const std::string& wanted) {
  const std::string magic = in.raw_line();
  const std::string prefix = "# vtk DataFile Version ";
  if (magic.rfind(prefix, 0) != 0) throw Error("not a VTK legacy file (no '# vtk DataFile Version' header)");
  const bool offsets_form = std::atoi(magic.c_str() + prefix.size()) >= 5;  // 5.x: OFFSETS/CONNECTIVITY
  in.raw_line();  // title
  const std::string mode = in.line();
  if (mode == "BINARY") in.binary = true;
  else if (mode != "ASCII") throw Error("third line must be ASCII or BINARY, got '" + mode + "'");
  const auto dataset = split(in.line());
  if (dataset.size() != 2 || dataset[0] != "DATASET")
    throw Error("expected a DATASET line");
  if (dataset[1] != "UNSTRUCTURED_GRID")
    throw Error("dataset is " + dataset[1] + "; only UNSTRUCTURED_GRID meshes are supported");

  std::optional<std::vector<double>> xyz;
  std::vector<std::int64_t> connectivity, offsets, types;
  bool have_cells = false, have_types = false;
  std::vector<std::pair<std::string, std::vector<double>>> point_arrays;
  enum class Section { None, Point, Cell } section = Section::None;
  std::size_t section_n = 0, n_points = 0;

  // Skips or keeps one attribute array of n tuples of `comps` components.
  auto attribute = [&](const std::string& name, vtk::Num type, std::size_t comps) {
    auto v = in.values(type, checked_product({section_n, comps}, "the declared array size"));
    if (section == Section::Point && comps == 1) point_arrays.emplace_back(name, std::move(v));
  };
  auto need = [](const std::vector<std::string>& w, std::size_t n) {
    if (w.empty()) throw Error("the file ends where a line was expected");
    if (w.size() < n) throw Error("incomplete '" + w[0] + "' line");
  };

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
    } else if (key == "POINT_DATA" || key == "CELL_DATA") {
      need(w, 2);
      section = key == "POINT_DATA" ? Section::Point : Section::Cell;
      section_n = count_of(w[1], key);
      if (section == Section::Point && section_n != n_points)
        throw Error("POINT_DATA has " + w[1] + " values for " + std::to_string(n_points) + " points");
    } else if (section != Section::None && key == "SCALARS") {
      need(w, 3);
      const std::size_t comps = w.size() > 3 ? count_of(w[3], "component") : 1;
      const vtk::Num type = num_of(w[2]);
      const auto lut = split(in.line());
      if (lut.empty() || lut[0] != "LOOKUP_TABLE") throw Error("SCALARS " + w[1] + " lacks its LOOKUP_TABLE line");
      attribute(w[1], type, comps);
    } else if (section != Section::None && key == "LOOKUP_TABLE") {
      need(w, 3);
      in.values(in.binary ? vtk::Num::UInt8 : vtk::Num::Float64, checked_product({4, count_of(w[2], "table")}, "the declared table size"));
    } else if (section != Section::None && key == "COLOR_SCALARS") {
      need(w, 3);
      in.values(in.binary ? vtk::Num::UInt8 : vtk::Num::Float64, checked_product({section_n, count_of(w[2], "component")}, "the declared array size"));
    } else if (section != Section::None && (key == "VECTORS" || key == "NORMALS")) {
      need(w, 3);
      attribute(w[1], num_of(w[2]), 3);
    } else if (section != Section::None && (key == "TENSORS" || key == "TENSORS6")) {
      need(w, 3);
      attribute(w[1], num_of(w[2]), key == "TENSORS" ? 9 : 6);
    } else if (section != Section::None && key == "TEXTURE_COORDINATES") {
      need(w, 4);
      attribute(w[1], num_of(w[3]), count_of(w[2], "dimension"));
    } else if (section != Section::None && (key == "GLOBAL_IDS" || key == "PEDIGREE_IDS")) {
      need(w, 3);
      attribute(w[1], num_of(w[2]), 1);
    } else if (key == "FIELD") {
      need(w, 3);
      const std::size_t arrays = count_of(w[2], "array");
      for (std::size_t a = 0; a < arrays; ++a) {
        auto aw = split(in.line());
        if (!aw.empty() && aw[0] == "METADATA") throw Error("METADATA blocks are not supported");
        need(aw, 4);
        const std::size_t comps = count_of(aw[1], "component"), tuples = count_of(aw[2], "tuple");
        auto v = in.values(num_of(aw[3]), checked_product({comps, tuples}, "the declared FIELD array size"));
        if (section == Section::Point && comps == 1 && tuples == n_points)
          point_arrays.emplace_back(aw[0], std::move(v));
      }
    } else {
      throw Error("unsupported section '" + key + "'");
    }
  }
  if (!xyz) throw Error("no POINTS");
  if (!have_cells) throw Error("no CELLS");
  if (!have_types) throw Error("no CELL_TYPES");
  if (offsets.empty() && !types.empty()) throw Error("no cells");
  if (point_arrays.empty()) throw Error("no one-component point scalars");
  const std::vector<double>* chosen = nullptr;
  std::string names;
  for (const auto& [name, v] : point_arrays) {
    names += (names.empty() ? "" : ", ") + name;
    if (!chosen && (wanted.empty() || wanted == name)) chosen = &v;
  }
  if (!chosen) throw Error("no point scalars named '" + wanted + "' (the file has: " + names + ")");
  std::vector<float> scalars(chosen->begin(), chosen->end());
  return TetMesh(vtk::points_from(*xyz), vtk::tets_from_cells(connectivity, offsets, types), std::move(scalars));
}

}  // namespace

TetMesh parse_vtk_legacy(std::span<const std::byte> bytes, const std::string& scalars, const std::string& source) {
  try {
    Cursor in(bytes);
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
