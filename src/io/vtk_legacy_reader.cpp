// See vtk_legacy_reader.hpp.
#include "vtk_legacy_reader.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/checked_size.hpp"
#include "vri/error.hpp"
#include "vri/memory.hpp"

namespace vri::vtk::legacy {

bool Cursor::at_end() {
  skip_space();
  return pos_ >= bytes_.size();
}

std::string Cursor::line() {
  skip_space();
  std::string out = raw_line();
  if (!out.empty() && out.back() == '\r') out.pop_back();
  return out;
}

std::string Cursor::raw_line() {
  std::string out;
  while (pos_ < bytes_.size() && char(bytes_[pos_]) != '\n') out += char(bytes_[pos_++]);
  if (pos_ < bytes_.size()) ++pos_;
  return out;
}

void Cursor::skip_metadata() {
  while (pos_ < bytes_.size()) {
    const std::string l = raw_line();
    if (l.find_first_not_of(" \t\r") == std::string::npos) break;
  }
}

ChargedVector<double> Cursor::values(Num type, std::size_t count) {
  if (binary) {
    auto out = decode(rest(), type, count, /*big_endian=*/true);
    pos_ += count * num_size(type);
    return out;
  }
  check_ascii_count(count, bytes_.size() - pos_);
  check_allocation(count, sizeof(double), "an array of " + std::to_string(count) + " values");
  ChargedVector<double> out(count);
  pos_ += parse_ascii(Num::Float64, rest_text(), std::as_writable_bytes(std::span(out)));
  return out;
}

void Cursor::skip(Num type, std::size_t count) {
  if (binary) {
    if (rest().size() / num_size(type) < count)
      throw Error("binary data ends early: " + std::to_string(count) + " values need " +
                  std::to_string(count * num_size(type)) + " bytes, " + std::to_string(rest().size()) + " left");
    pos_ += count * num_size(type);
    return;
  }
  check_ascii_count(count, bytes_.size() - pos_);
  double v;  // parsed one at a time into one slot
  for (std::size_t i = 0; i < count; ++i)
    pos_ += parse_ascii(Num::Float64, rest_text(), std::as_writable_bytes(std::span(&v, 1)));
}

void Cursor::skip_space() {
  while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) ++pos_;
}

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

Num num_of(const std::string& word) {
  const auto t = parse_num(word);
  if (!t) throw Error("unsupported data type '" + word + "'");
  return *t;
}

void need(const std::vector<std::string>& w, std::size_t n) {
  if (w.empty()) throw Error("the file ends where a line was expected");
  if (w.size() < n) throw Error("incomplete '" + w[0] + "' line");
}

Header read_header(Cursor& in) {
  const std::string magic = in.raw_line();
  const std::string prefix = "# vtk DataFile Version ";
  if (magic.rfind(prefix, 0) != 0) throw Error("not a VTK legacy file (no '# vtk DataFile Version' header)");
  Header h;
  h.version = std::atoi(magic.c_str() + prefix.size());
  in.raw_line();  // title
  const std::string mode = in.line();
  if (mode == "BINARY") in.binary = true;
  else if (mode != "ASCII") throw Error("third line must be ASCII or BINARY, got '" + mode + "'");
  const auto dataset = split(in.line());
  if (dataset.size() != 2 || dataset[0] != "DATASET") throw Error("expected a DATASET line");
  h.dataset = dataset[1];
  return h;
}

void Attributes::attribute(Cursor& in, const std::string& name, Num type, std::size_t comps, bool color) {
  const std::size_t at = in.position();
  // COLOR_SCALARS: unsigned chars in binary files, floats in [0, 1] in ASCII ones.
  in.skip(color && !in.binary ? Num::Float64 : type, checked_product({section_n_, comps}, "the declared array size"));
  if (section_ == Section::Point) arrays_.push_back({name, type, comps, section_n_, at, color});
}

bool Attributes::read(Cursor& in, const std::vector<std::string>& w, std::size_t n_points) {
  const std::string& key = w[0];
  if (key == "POINT_DATA" || key == "CELL_DATA") {
    need(w, 2);
    section_ = key == "POINT_DATA" ? Section::Point : Section::Cell;
    section_n_ = count_of(w[1], key);
    if (section_ == Section::Point && section_n_ != n_points)
      throw Error("POINT_DATA has " + w[1] + " values for " + std::to_string(n_points) + " points");
  } else if (key == "METADATA") {
    in.skip_metadata();
  } else if (key == "FIELD") {
    need(w, 3);
    const std::size_t arrays = count_of(w[2], "array");
    for (std::size_t a = 0; a < arrays; ++a) {
      auto aw = split(in.line());
      while (!aw.empty() && aw[0] == "METADATA") {  // of the array before
        in.skip_metadata();
        aw = split(in.line());
      }
      need(aw, 4);
      const std::size_t comps = count_of(aw[1], "component"), tuples = count_of(aw[2], "tuple");
      const std::size_t at = in.position();
      in.skip(num_of(aw[3]), checked_product({comps, tuples}, "the declared FIELD array size"));
      if (section_ == Section::Point && tuples == n_points) arrays_.push_back({aw[0], num_of(aw[3]), comps, tuples, at});
    }
  } else if (section_ == Section::None) {
    return false;
  } else if (key == "SCALARS") {
    need(w, 3);
    const std::size_t comps = w.size() > 3 ? count_of(w[3], "component") : 1;
    const Num type = num_of(w[2]);
    const auto lut = split(in.line());
    if (lut.empty() || lut[0] != "LOOKUP_TABLE") throw Error("SCALARS " + w[1] + " lacks its LOOKUP_TABLE line");
    attribute(in, w[1], type, comps);
  } else if (key == "COLOR_SCALARS") {
    need(w, 3);
    attribute(in, w[1], Num::UInt8, count_of(w[2], "component"), /*color=*/true);
  } else if (key == "LOOKUP_TABLE") {
    need(w, 3);
    in.skip(in.binary ? Num::UInt8 : Num::Float64, checked_product({4, count_of(w[2], "table")}, "the declared table size"));
  } else if (key == "VECTORS" || key == "NORMALS") {
    need(w, 3);
    attribute(in, w[1], num_of(w[2]), 3);
  } else if (key == "TENSORS" || key == "TENSORS6") {
    need(w, 3);
    attribute(in, w[1], num_of(w[2]), key == "TENSORS" ? 9 : 6);
  } else if (key == "TEXTURE_COORDINATES") {
    need(w, 4);
    attribute(in, w[1], num_of(w[3]), count_of(w[2], "dimension"));
  } else if (key == "GLOBAL_IDS" || key == "PEDIGREE_IDS") {
    need(w, 3);
    attribute(in, w[1], num_of(w[2]), 1);
  } else {
    return false;
  }
  return true;
}

const ArrayRef& Attributes::choose(const std::string& wanted, std::size_t n_points) const {
  std::vector<NamedArray> named;
  for (const auto& a : arrays_) named.push_back({a.name, a.components});
  const ArrayRef& a = arrays_[choose_point_array(named, wanted)];
  if (a.tuples != n_points)  // POINT_DATA before the points were declared
    throw Error("point array '" + a.name + "' holds " + std::to_string(a.tuples) + " values for " +
                std::to_string(n_points) + " points");
  return a;
}

ChargedVector<double> Attributes::values(Cursor& in, const ArrayRef& a) const {
  in.seek(a.at);
  if (!a.color || in.binary) return in.values(a.type, a.tuples);
  auto v = in.values(Num::Float64, a.tuples);
  for (double& x : v) {  // as VTK's reader does: 255 * value, rounded
    x = std::floor(255.0 * x + 0.5);
    if (!(x >= 0 && x <= 255)) throw Error("COLOR_SCALARS " + a.name + " holds a value outside [0, 1]");
  }
  return v;
}

}  // namespace vri::vtk::legacy
