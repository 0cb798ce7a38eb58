#include "vri/io/vtu.hpp"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "vri/core/checked_size.hpp"
#include "vri/core/error.hpp"
#include "vri/core/memory_limit.hpp"
#include "vri/io/file_io.hpp"
#include "vtk_values.hpp"

namespace vri {

namespace {

// One XML tag; enough XML for VTK files (no entities in the attributes we use).
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

std::optional<Tag> next_tag(std::string_view text, std::size_t& pos) {
  while (true) {
    const std::size_t lt = text.find('<', pos);
    if (lt == std::string_view::npos) return std::nullopt;
    if (text.compare(lt, 4, "<!--") == 0) {
      const std::size_t e = text.find("-->", lt);
      if (e == std::string_view::npos) throw Error("unterminated XML comment");
      pos = e + 3;
      continue;
    }
    if (text.compare(lt, 2, "<?") == 0 || text.compare(lt, 2, "<!") == 0) {
      pos = text.find('>', lt);
      if (pos == std::string_view::npos) throw Error("unterminated XML declaration");
      ++pos;
      continue;
    }
    Tag tag;
    std::size_t i = lt + 1;
    if (i < text.size() && text[i] == '/') {
      tag.closing = true;
      ++i;
    }
    auto space = [&] { while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i; };
    while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) && text[i] != '>' && text[i] != '/')
      tag.name += text[i++];
    while (true) {
      space();
      if (i >= text.size()) throw Error("unterminated XML tag <" + tag.name + ">");
      if (text[i] == '>') break;
      if (text[i] == '/') {
        tag.self_closing = true;
        ++i;
        continue;
      }
      std::string key;
      while (i < text.size() && text[i] != '=' && !std::isspace(static_cast<unsigned char>(text[i]))) key += text[i++];
      space();
      if (i >= text.size() || text[i] != '=') throw Error("bad attribute '" + key + "' in <" + tag.name + ">");
      ++i;
      space();
      if (i >= text.size() || (text[i] != '"' && text[i] != '\'')) throw Error("unquoted attribute '" + key + "'");
      const char q = text[i++];
      const std::size_t close = text.find(q, i);
      if (close == std::string_view::npos) throw Error("unterminated attribute '" + key + "'");
      tag.attrs[key] = std::string(text.substr(i, close - i));
      i = close + 1;
    }
    tag.end = pos = i + 1;
    return tag;
  }
}

// Base64, decoded four characters at a time so that separately padded chunks
// (VTK encodes headers and data apart) decode as one byte stream. Stops after
// `limit` bytes or at the first character that is not base64 or space.
std::vector<std::byte> base64(std::string_view text, std::size_t limit) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    if (c == '=') return 64;
    return -1;
  };
  std::vector<std::byte> out;
  int group[4], n = 0;
  for (char c : text) {
    if (out.size() >= limit) break;
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    const int v = value(c);
    if (v < 0) break;
    group[n++] = v;
    if (n < 4) continue;
    n = 0;
    if (group[0] == 64 || group[1] == 64) throw Error("bad base64 data");
    out.push_back(std::byte((group[0] << 2) | (group[1] >> 4)));
    if (group[2] != 64) out.push_back(std::byte(((group[1] & 15) << 4) | (group[2] >> 2)));
    if (group[2] != 64 && group[3] != 64) out.push_back(std::byte(((group[2] & 3) << 6) | group[3]));
  }
  if (out.size() > limit) out.resize(limit);
  return out;
}

struct Format {
  bool big_endian = false;
  vtk::Num header = vtk::Num::UInt32;
  bool zlib = false;
};

struct Array {
  std::string section, name, format;
  vtk::Num type;
  std::size_t components = 1;
  std::size_t content_begin = 0, content_end = 0;  // inline text
  std::size_t offset = 0;                          // appended
};

// Header word k of a binary array's stream, read as an unsigned integer (a
// float round trip would make casts of values near 2^64 undefined).
std::uint64_t header_word(const Format& f, std::span<const std::byte> stream, std::uint64_t k) {
  const std::size_t hs = vtk::num_size(f.header);
  if (k >= stream.size() / hs) throw Error("binary array header ends early");
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < hs; ++i) {
    const std::size_t b = f.big_endian ? i : hs - 1 - i;
    v = (v << 8) | std::to_integer<std::uint64_t>(stream[k * hs + b]);
  }
  return v;
}

// The bytes of a binary array from its (decoded or raw) stream: header then data.
// Every size in the header is checked against the bytes present (without
// wrapping) before anything is allocated.
std::vector<std::byte> unpack(const Format& f, std::span<const std::byte> stream, std::uint64_t expected) {
  const std::size_t hs = vtk::num_size(f.header);
  auto word = [&](std::uint64_t k) { return header_word(f, stream, k); };
  if (!f.zlib) {
    const std::uint64_t n = word(0);
    if (n != expected) throw Error("binary array holds " + std::to_string(n) + " bytes, expected " + std::to_string(expected));
    if (stream.size() - hs < n) throw Error("binary array ends early");
    return std::vector<std::byte>(stream.begin() + hs, stream.begin() + hs + n);
  }
  const std::uint64_t blocks = word(0), block_size = word(1), last = word(2);
  if (blocks > stream.size() / hs) throw Error("compressed header declares " + std::to_string(blocks) + " blocks, more than the data holds");
  std::uint64_t at = (3 + blocks) * hs;
  if (at > stream.size()) throw Error("compressed header ends early");
  // zlib expands at most 1032:1, so a block that claims more is refused before
  // its output is allocated.
  constexpr std::uint64_t kMaxRatio = 1032;
  std::uint64_t total = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t csize = word(3 + b), usize = (b + 1 == blocks && last != 0) ? last : block_size;
    if (usize > expected - total) throw Error("compressed array is larger than its " + std::to_string(expected) + " bytes");
    if (csize > stream.size() - at || usize / kMaxRatio > csize) throw Error("compressed array is truncated");
    total += usize;
    at += csize;
  }
  if (total != expected) throw Error("compressed array holds " + std::to_string(total) + " bytes, expected " + std::to_string(expected));
  check_allocation(expected, "a decompressed mesh array");
  std::vector<std::byte> out(expected);
  at = (3 + blocks) * hs;
  std::uint64_t filled = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t csize = word(3 + b), usize = (b + 1 == blocks && last != 0) ? last : block_size;
    uLongf len = usize;
    if (uncompress(reinterpret_cast<Bytef*>(out.data() + filled), &len,
                   reinterpret_cast<const Bytef*>(stream.data() + at), csize) != Z_OK || len != usize)
      throw Error("cannot decompress a zlib block");
    filled += usize;
    at += csize;
  }
  return out;
}

TetMesh parse(std::string_view text, const std::string& wanted) {
  std::size_t pos = 0;
  Format f;
  std::optional<std::size_t> n_points, n_cells;
  std::string section;
  std::vector<Array> arrays;
  std::optional<std::size_t> appended;  // start of the appended data (after '_')
  std::string appended_encoding;
  int pieces = 0;
  while (auto tag = next_tag(text, pos)) {
    if (tag->closing) {
      if (tag->name == section) section.clear();
      continue;
    }
    if (tag->name == "VTKFile") {
      if (tag->attr("type") != "UnstructuredGrid")
        throw Error("VTKFile type is '" + tag->attr("type") + "'; only UnstructuredGrid is supported");
      f.big_endian = tag->attr("byte_order", "LittleEndian") == "BigEndian";
      const std::string h = tag->attr("header_type", "UInt32");
      if (h != "UInt32" && h != "UInt64") throw Error("unsupported header_type '" + h + "'");
      f.header = h == "UInt64" ? vtk::Num::UInt64 : vtk::Num::UInt32;
      const std::string c = tag->attr("compressor");
      if (!c.empty() && c != "vtkZLibDataCompressor")
        throw Error("unsupported compressor '" + c + "' (only vtkZLibDataCompressor)");
      f.zlib = !c.empty();
    } else if (tag->name == "Piece") {
      if (++pieces > 1) throw Error("only single-piece files are supported");
      auto count = [&](const char* key) {
        const std::string v = tag->attr(key);
        std::size_t n = 0;
        const auto [p, ec] = std::from_chars(v.data(), v.data() + v.size(), n);
        if (ec != std::errc() || p != v.data() + v.size()) throw Error("Piece lacks a valid " + std::string(key));
        return n;
      };
      n_points = count("NumberOfPoints");
      n_cells = count("NumberOfCells");
    } else if (tag->name == "Points" || tag->name == "Cells" || tag->name == "PointData" || tag->name == "CellData") {
      if (!tag->self_closing) section = tag->name;
    } else if (tag->name == "DataArray") {
      Array a;
      a.section = section;
      a.name = tag->attr("Name");
      const auto type = vtk::parse_num(tag->attr("type"));
      if (!type) throw Error("DataArray '" + a.name + "' has unsupported type '" + tag->attr("type") + "'");
      a.type = *type;
      a.format = tag->attr("format", "ascii");
      const std::string comps = tag->attr("NumberOfComponents", "1");
      a.components = std::strtoull(comps.c_str(), nullptr, 10);
      if (a.format == "appended") a.offset = std::strtoull(tag->attr("offset").c_str(), nullptr, 10);
      else if (a.format != "ascii" && a.format != "binary")
        throw Error("DataArray '" + a.name + "' has unknown format '" + a.format + "'");
      if (!tag->self_closing) {
        a.content_begin = tag->end;
        a.content_end = text.find('<', tag->end);
        if (a.content_end == std::string_view::npos) throw Error("unterminated DataArray '" + a.name + "'");
        pos = a.content_end;
      }
      arrays.push_back(a);
    } else if (tag->name == "AppendedData") {
      appended_encoding = tag->attr("encoding", "raw");
      if (appended_encoding != "raw" && appended_encoding != "base64")
        throw Error("unknown AppendedData encoding '" + appended_encoding + "'");
      const std::size_t u = text.find('_', tag->end);
      if (u == std::string_view::npos) throw Error("AppendedData lacks its '_' marker");
      appended = u + 1;
      break;  // raw bytes follow; nothing after them matters
    }
  }
  if (!n_points || !n_cells) throw Error("no Piece with NumberOfPoints and NumberOfCells");

  auto values = [&](const Array& a, std::size_t count) -> std::vector<double> {
    const std::string what = "DataArray '" + a.name + "': ";
    try {
      if (a.format == "ascii") {
        std::vector<double> out;
        // Each value takes at least two characters: never reserve more than the text can hold.
        out.reserve(std::min<std::uint64_t>(count, (a.content_end - a.content_begin) / 2 + 1));
        const char* p = text.data() + a.content_begin;
        const char* e = text.data() + a.content_end;
        while (out.size() < count) {
          while (p < e && std::isspace(static_cast<unsigned char>(*p))) ++p;
          if (p == e) throw Error("holds fewer than " + std::to_string(count) + " values");
          double v;
          const auto [q, ec] = std::from_chars(p, e, v);
          if (ec != std::errc()) throw Error("bad number");
          out.push_back(v);
          p = q;
        }
        return out;
      }
      const std::uint64_t bytes = checked_product({count, vtk::num_size(a.type)}, "the declared array size");
      std::vector<std::byte> decoded;
      std::span<const std::byte> stream;
      if (a.format == "binary") {
        stream = decoded = base64(text.substr(a.content_begin, a.content_end - a.content_begin), SIZE_MAX);
      } else {
        if (!appended) throw Error("is appended but the file has no AppendedData");
        if (a.offset > text.size() - *appended) throw Error("offset is past the end of the file");
        const std::size_t start = *appended + a.offset;
        if (appended_encoding == "base64") stream = decoded = base64(text.substr(start), SIZE_MAX);
        else stream = std::as_bytes(std::span(text.data() + start, text.size() - start));
      }
      return vtk::decode(unpack(f, stream, bytes), a.type, count, f.big_endian);
    } catch (const Error& e) {
      throw Error(what + e.what());
    }
  };
  auto find = [&](const std::string& sec, const std::string& name) -> const Array* {
    for (const auto& a : arrays)
      if (a.section == sec && (name.empty() || a.name == name)) return &a;
    return nullptr;
  };
  const Array* pts = find("Points", "");
  const Array* conn = find("Cells", "connectivity");
  const Array* offs = find("Cells", "offsets");
  const Array* types = find("Cells", "types");
  if (!pts || pts->components != 3) throw Error("no Points array of 3 components");
  if (!conn || !offs || !types) throw Error("Cells needs connectivity, offsets and types arrays");
  const auto xyz = values(*pts, checked_product({3, *n_points}, "NumberOfPoints"));
  auto ends = vtk::to_indices(values(*offs, *n_cells), "offsets");
  std::vector<std::int64_t> starts(1, 0);
  starts.insert(starts.end(), ends.begin(), ends.end());  // VTK stores where each cell ends
  const std::size_t n_conn = ends.empty() ? 0 : static_cast<std::size_t>(ends.back());
  const auto connectivity = vtk::to_indices(values(*conn, n_conn), "connectivity");
  const auto cell_types = vtk::to_indices(values(*types, *n_cells), "types");

  const Array* chosen = nullptr;
  std::string names;
  for (const auto& a : arrays)
    if (a.section == "PointData" && a.components == 1) {
      names += (names.empty() ? "" : ", ") + a.name;
      if (!chosen && (wanted.empty() || a.name == wanted)) chosen = &a;
    }
  if (names.empty()) throw Error("no one-component PointData arrays");
  if (!chosen) throw Error("no point scalars named '" + wanted + "' (the file has: " + names + ")");
  const auto s = values(*chosen, *n_points);
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
