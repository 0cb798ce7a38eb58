// See vtk_xml.hpp.
#include "vtk_xml.hpp"

#include <zlib.h>
#ifndef VRI_HAVE_LZ4  // set by the build (src/CMakeLists.txt, fuzz/CMakeLists.txt); 0: LZ4 refused
#define VRI_HAVE_LZ4 0
#endif
#if VRI_HAVE_LZ4
#include <lz4.h>
#endif

#include <limits>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>

#include "core/checked_size.hpp"
#include "vri/memory.hpp"

namespace vri::vtk::xml {

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

namespace {

// Base64, decoded four characters at a time so that separately padded chunks
// (VTK encodes headers and data apart) decode as one byte stream. `strict`
// (inline data, whose text ends at the next tag): any other character than
// base64 and space is an error; else (appended data, followed by the closing
// tag) decoding stops there.
ChargedVector<std::byte> base64(std::string_view text, bool strict) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    if (c == '=') return 64;
    return -1;
  };
  ChargedVector<std::byte> out;
  int group[4], n = 0;
  for (char c : text) {
    if (std::isspace(static_cast<unsigned char>(c))) continue;
    const int v = value(c);
    if (v < 0) {
      if (strict) throw Error("bad base64 data (character " + std::to_string(int(static_cast<unsigned char>(c))) + ")");
      break;
    }
    group[n++] = v;
    if (n < 4) continue;
    n = 0;
    if (group[0] == 64 || group[1] == 64) throw Error("bad base64 data");
    out.push_back(std::byte((group[0] << 2) | (group[1] >> 4)));
    if (group[2] != 64) out.push_back(std::byte(((group[1] & 15) << 4) | (group[2] >> 2)));
    if (group[2] != 64 && group[3] != 64) out.push_back(std::byte(((group[2] & 3) << 6) | group[3]));
  }
  if (strict && n != 0) throw Error("bad base64 data (length not a multiple of 4)");
  return out;
}

// Header word k of a binary array's stream, read as an unsigned integer (a
// float round trip would make casts of values near 2^64 undefined).
std::uint64_t header_word(const Format& f, std::span<const std::byte> stream, std::uint64_t k) {
  const std::size_t hs = num_size(f.header);
  if (k >= stream.size() / hs) throw Error("binary array header ends early");
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < hs; ++i) {
    const std::size_t b = f.big_endian ? i : hs - 1 - i;
    v = (v << 8) | std::to_integer<std::uint64_t>(stream[k * hs + b]);
  }
  return v;
}

}  // namespace

Payload::Payload(const Document& doc, const Array& a, std::uint64_t bytes) : format_(doc.format), bytes_(bytes) {
  const std::string_view text = doc.text;
  if (a.format == "binary") {
    decoded_ = base64(text.substr(a.content_begin, a.content_end - a.content_begin), /*strict=*/true);
    stream_ = decoded_;
  } else {
    if (!doc.appended) throw Error("is appended but the file has no AppendedData");
    if (a.offset > text.size() - *doc.appended) throw Error("offset is past the end of the file");
    const std::size_t start = *doc.appended + a.offset;
    if (doc.appended_encoding == "base64") {
      decoded_ = base64(text.substr(start), /*strict=*/false);
      stream_ = decoded_;
    } else {
      stream_ = std::as_bytes(std::span(text.data() + start, text.size() - start));
    }
  }
  const std::size_t hs = num_size(format_.header);
  auto word = [&](std::uint64_t k) { return header_word(format_, stream_, k); };
  if (format_.compressor == Compressor::None) {
    const std::uint64_t n = word(0);
    if (n != bytes) throw Error("binary array holds " + std::to_string(n) + " bytes, expected " + std::to_string(bytes));
    if (stream_.size() - hs < n) throw Error("binary array ends early");
    data_at_ = hs;
    return;
  }
  const std::uint64_t blocks = word(0), block_size = word(1), last = word(2);
  if (blocks > stream_.size() / hs)
    throw Error("compressed header declares " + std::to_string(blocks) + " blocks, more than the data holds");
  std::uint64_t at = (3 + blocks) * hs;
  if (at > stream_.size()) throw Error("compressed header ends early");
  // zlib expands at most 1032:1 and LZ4 255:1, so a block that claims more
  // is refused before its output is allocated.
  const std::uint64_t kMaxRatio = format_.compressor == Compressor::LZ4 ? 255 : 1032;
  std::uint64_t total = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const std::uint64_t csize = word(3 + b), usize = (b + 1 == blocks && last != 0) ? last : block_size;
    if (usize > bytes - total) throw Error("compressed array is larger than its " + std::to_string(bytes) + " bytes");
    if (csize > stream_.size() - at || usize / kMaxRatio > csize) throw Error("compressed array is truncated");
    blocks_.push_back({at, csize, usize});
    total += usize;
    at += csize;
  }
  if (total != bytes)
    throw Error("compressed array holds " + std::to_string(total) + " bytes, expected " + std::to_string(bytes));
}

void Payload::copy_to(std::span<std::byte> out) const {
  if (out.size() != bytes_) throw Error("internal: payload of " + std::to_string(bytes_) + " bytes copied to " + std::to_string(out.size()));
  if (format_.compressor == Compressor::None) {
    std::copy_n(stream_.begin() + data_at_, bytes_, out.begin());
    return;
  }
  std::uint64_t filled = 0;
  for (const Block& b : blocks_) {
    if (format_.compressor == Compressor::LZ4) {
#if VRI_HAVE_LZ4
      constexpr std::uint64_t kInt = std::numeric_limits<int>::max();
      if (b.csize > kInt || b.usize > kInt ||
          LZ4_decompress_safe(reinterpret_cast<const char*>(stream_.data() + b.at), reinterpret_cast<char*>(out.data() + filled),
                              int(b.csize), int(b.usize)) != int(b.usize))
        throw Error("cannot decompress an LZ4 block");
      filled += b.usize;
      continue;
#endif
    }
    uLongf len = b.usize;
    if (uncompress(reinterpret_cast<Bytef*>(out.data() + filled), &len,
                   reinterpret_cast<const Bytef*>(stream_.data() + b.at), b.csize) != Z_OK || len != b.usize)
      throw Error("cannot decompress a zlib block");
    filled += b.usize;
  }
}

const Array* Document::find(const std::string& section, const std::string& name) const {
  for (const auto& a : arrays)
    if (a.section == section && (name.empty() || a.name == name)) return &a;
  return nullptr;
}

const Array& Document::point_array(const std::string& wanted, const std::string& active) const {
  return section_array("PointData", wanted, active);
}

const Array& Document::section_array(const std::string& section, const std::string& wanted,
                                     const std::string& active) const {
  std::vector<const Array*> found;
  std::vector<NamedArray> named;
  for (const auto& a : arrays)
    if (a.section == section) {
      found.push_back(&a);
      named.push_back({a.name, a.components});
    }
  return *found[choose_point_array(named, wanted, active)];
}

bool Document::has_scalars(const std::string& section, const std::string& wanted) const {
  for (const auto& a : arrays)
    if (a.section == section && (wanted.empty() ? a.components == 1 : a.name == wanted)) return true;
  return false;
}

Document read_document(std::string_view text, const std::string& type) {
  Document doc;
  doc.text = text;
  std::size_t pos = 0;
  std::string section;
  int pieces = 0;
  bool vtk_file = false;
  while (auto tag = next_tag(text, pos)) {
    if (!vtk_file && tag->name != "VTKFile") throw Error("not a VTK XML file (no <VTKFile> element)");
    if (tag->closing) {
      if (tag->name == section) section.clear();
      continue;
    }
    if (tag->name == "VTKFile") {
      vtk_file = true;
      if (tag->attr("type") != type)
        throw Error("VTKFile type is '" + tag->attr("type") + "'; only " + type + " is supported");
      doc.format.big_endian = tag->attr("byte_order", "LittleEndian") == "BigEndian";
      const std::string h = tag->attr("header_type", "UInt32");
      if (h != "UInt32" && h != "UInt64") throw Error("unsupported header_type '" + h + "'");
      doc.format.header = h == "UInt64" ? Num::UInt64 : Num::UInt32;
      const std::string c = tag->attr("compressor");
      if (c == "vtkLZ4DataCompressor" && !VRI_HAVE_LZ4)
        throw Error("is compressed with LZ4, which this build of vri cannot read (built without liblz4)");
      if (!c.empty() && c != "vtkZLibDataCompressor" && c != "vtkLZ4DataCompressor")
        throw Error("unsupported compressor '" + c + "' (vtkZLibDataCompressor and vtkLZ4DataCompressor are read)");
      doc.format.compressor = c.empty() ? Compressor::None : c == "vtkLZ4DataCompressor" ? Compressor::LZ4 : Compressor::ZLib;
    } else if (tag->name == type) {
      doc.dataset = *tag;
    } else if (tag->name == "Piece") {
      if (++pieces > 1) throw Error("only single-piece files are supported");
      doc.piece = *tag;
    } else if (tag->name == "Points" || tag->name == "Cells" || tag->name == "PointData" || tag->name == "CellData") {
      if (tag->name == "PointData") doc.active_scalars = tag->attr("Scalars");
      if (tag->name == "CellData") doc.active_cell_scalars = tag->attr("Scalars");
      if (!tag->self_closing) section = tag->name;
    } else if (tag->name == "DataArray") {
      Array a;
      a.section = section;
      a.name = tag->attr("Name");
      const auto num = parse_num(tag->attr("type"));
      if (!num) throw Error("DataArray '" + a.name + "' has unsupported type '" + tag->attr("type") + "'");
      a.type = *num;
      a.format = tag->attr("format", "ascii");
      a.components = std::strtoull(tag->attr("NumberOfComponents", "1").c_str(), nullptr, 10);
      if (a.format == "appended") a.offset = std::strtoull(tag->attr("offset").c_str(), nullptr, 10);
      else if (a.format != "ascii" && a.format != "binary")
        throw Error("DataArray '" + a.name + "' has unknown format '" + a.format + "'");
      if (!tag->self_closing) {
        a.content_begin = tag->end;
        a.content_end = text.find('<', tag->end);
        if (a.content_end == std::string_view::npos) throw Error("unterminated DataArray '" + a.name + "'");
        pos = a.content_end;
      }
      doc.arrays.push_back(a);
    } else if (tag->name == "AppendedData") {
      doc.appended_encoding = tag->attr("encoding", "raw");
      if (doc.appended_encoding != "raw" && doc.appended_encoding != "base64")
        throw Error("unknown AppendedData encoding '" + doc.appended_encoding + "'");
      const std::size_t u = text.find('_', tag->end);
      if (u == std::string_view::npos) throw Error("AppendedData lacks its '_' marker");
      doc.appended = u + 1;
      break;  // raw bytes follow; nothing after them matters
    }
  }
  if (!vtk_file) throw Error("not a VTK XML file (no <VTKFile> element)");
  if (pieces == 0) throw Error("no <Piece>");
  return doc;
}

ChargedVector<double> values(const Document& doc, const Array& a, std::size_t count) {
  return for_array(a, [&] {
    if (a.format == "ascii") {
      const std::string_view text = doc.text.substr(a.content_begin, a.content_end - a.content_begin);
      check_ascii_count(count, text.size());
      check_allocation(count, sizeof(double), "an array of " + std::to_string(count) + " values");
      ChargedVector<double> out(count);
      parse_ascii(Num::Float64, text, std::as_writable_bytes(std::span(out)));
      return out;
    }
    const std::uint64_t bytes = checked_product({count, num_size(a.type)}, "the declared array size");
    const Payload payload(doc, a, bytes);
    check_allocation(bytes, "a decompressed array");
    ChargedVector<std::byte> packed(bytes);
    payload.copy_to(packed);
    return decode(packed, a.type, count, doc.format.big_endian);
  });
}

}  // namespace vri::vtk::xml
