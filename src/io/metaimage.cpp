// MetaImage volumes (.mha, .mhd; metaimage.hpp): ITK's MetaIO format, as
// documented at https://itk.org/Wiki/ITK/MetaIO/Documentation and as MetaIO's
// metaImage.cxx reads it (element sizes from metaTypes.h: MET_LONG is 4 bytes).
// The header is read first (at most its first 1 MiB); the samples then go
// from the file straight into the volume's storage, compressed data through
// zlib, after every size has been checked against the bytes present and the
// memory budget.
#include "io/metaimage.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <map>
#include <vector>

#include "grid_samples.hpp"
#include "gzip.hpp"
#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "vri/io.hpp"

namespace vri {

namespace fs = std::filesystem;

namespace {

constexpr std::uint64_t kMaxHeader = std::uint64_t{1} << 20;

// Bytes of a file on disk or in memory: their count and a reader.
struct Source {
  std::uint64_t size;
  std::function<void(std::uint64_t, std::span<std::byte>)> read;
};

Source file_source(const fs::path& path) {
  return {checked_file_size(path), [path](std::uint64_t offset, std::span<std::byte> out) {
            read_file_range(path, offset, out);
          }};
}

// Header text quoted in a message: printable, and short.
std::string shown(const std::string& s) {
  std::string out = s.substr(0, 60);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
  return out + (s.size() > 60 ? "..." : "");
}

struct Header {
  std::map<std::string, std::string> fields;  // keys lower-cased
  std::uint64_t end = 0;                      // the first byte after the ElementDataFile line
};

// "Key = Value" lines up to ElementDataFile, which MetaIO writes last.
Header parse_header(std::span<const std::byte> prefix, std::uint64_t file_size, const std::string& where) {
  const std::string_view text(reinterpret_cast<const char*>(prefix.data()), prefix.size());
  Header h;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    const std::size_t next = nl == std::string_view::npos ? text.size() : nl + 1;
    const std::string line = trim_blanks(std::string(text.substr(pos, next - pos - (nl == std::string_view::npos ? 0 : 1))));
    pos = next;
    if (line.empty()) continue;
    const auto eq = line.find('=');
    if (eq == std::string::npos) throw Error(where + " has a malformed header line '" + shown(line) + "' (Key = Value)");
    const std::string key = to_lower(trim_blanks(line.substr(0, eq)));
    h.fields[key] = trim_blanks(line.substr(eq + 1));
    if (key == "elementdatafile") {
      if (nl == std::string_view::npos && prefix.size() < file_size) break;  // the line runs past the prefix
      h.end = pos;
      return h;
    }
  }
  throw Error(where + (prefix.size() < file_size ? " has no ElementDataFile line in its first 1 MiB"
                                                 : " lacks ElementDataFile (the header's last line)"));
}

class Fields {
 public:
  Fields(const Header& h, const std::string& where) : h_(h), where_(where) {}

  // The value of the first of `keys` present (lower-case), or nullptr.
  const std::string* find(std::initializer_list<const char*> keys) const {
    for (const char* k : keys)
      if (auto it = h_.fields.find(k); it != h_.fields.end()) return &it->second;
    return nullptr;
  }
  const std::string& required(const char* key, const char* name) const {
    const std::string* v = find({key});
    if (!v) throw Error(where_ + " lacks " + name);
    return *v;
  }
  long long integer(const std::string& text, const char* name, long long lo, long long hi) const {
    long long v = 0;
    const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || ec != std::errc() || p != text.data() + text.size() || v < lo || v > hi)
      throw Error(where_ + ": " + name + " must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
                  ", got '" + shown(text) + "'");
    return v;
  }
  // Exactly `count` finite numbers separated by spaces.
  std::vector<double> numbers(const std::string& text, const char* name, std::size_t count) const {
    std::vector<double> out;
    std::size_t i = 0;
    while (i < text.size()) {
      while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
      if (i == text.size()) break;
      double v = 0;
      const auto [p, ec] = std::from_chars(text.data() + i, text.data() + text.size(), v);
      if (ec != std::errc() || !std::isfinite(v) || (p != text.data() + text.size() && *p != ' ' && *p != '\t'))
        throw Error(where_ + ": " + name + " has a bad number in '" + shown(text) + "'");
      out.push_back(v);
      i = std::size_t(p - text.data());
    }
    if (out.size() != count)
      throw Error(where_ + ": " + name + " needs " + std::to_string(count) + " numbers, got '" + shown(text) + "'");
    return out;
  }
  bool flag(std::initializer_list<const char*> keys, const char* name, bool fallback) const {
    const std::string* v = find(keys);
    if (!v) return fallback;
    const std::string t = to_lower(*v);
    if (t == "true" || t == "1") return true;
    if (t == "false" || t == "0") return false;
    throw Error(where_ + ": " + name + " must be True or False, got '" + shown(*v) + "'");
  }

 private:
  const Header& h_;
  const std::string& where_;
};

FileSampleType element_type(const std::string& name, const std::string& where) {
  static const std::map<std::string, FileSampleType> types = {
      {"MET_CHAR", FileSampleType::Int8},         {"MET_UCHAR", FileSampleType::UInt8},
      {"MET_SHORT", FileSampleType::Int16},       {"MET_USHORT", FileSampleType::UInt16},
      {"MET_INT", FileSampleType::Int32},         {"MET_UINT", FileSampleType::UInt32},
      {"MET_LONG", FileSampleType::Int32},        {"MET_ULONG", FileSampleType::UInt32},
      {"MET_LONG_LONG", FileSampleType::Int64},   {"MET_ULONG_LONG", FileSampleType::UInt64},
      {"MET_FLOAT", FileSampleType::Float32},     {"MET_DOUBLE", FileSampleType::Float64}};
  const auto it = types.find(name);
  if (it == types.end())
    throw Error(where + ": ElementType '" + shown(name) + "' is not supported (MET_CHAR, MET_UCHAR, MET_SHORT, "
                "MET_USHORT, MET_INT, MET_UINT, MET_LONG, MET_ULONG, MET_LONG_LONG, MET_ULONG_LONG, MET_FLOAT, MET_DOUBLE)");
  return it->second;
}

GridVolume read_volume(const Source& header_file, std::span<const std::byte> prefix, const fs::path& base_dir,
                       const std::string& where, const MetaImageOptions& options) {
  const Header header = parse_header(prefix, header_file.size, where);
  const Fields f(header, where);
  if (const auto* type = f.find({"objecttype"}); type && to_lower(*type) != "image")
    throw Error(where + ": ObjectType '" + shown(*type) + "' is not an image");
  const long long ndims = f.integer(f.required("ndims", "NDims"), "NDims", 1, 16);
  if (ndims != 3) throw Error(where + " is " + std::to_string(ndims) + "-D (NDims); vri reads 3-D volumes");
  std::array<std::int64_t, 3> dims{};
  {
    const auto v = f.numbers(f.required("dimsize", "DimSize"), "DimSize", 3);
    for (int a = 0; a < 3; ++a) {
      if (v[a] != std::floor(v[a]) || v[a] < 1 || v[a] > double(std::int64_t{1} << 40))
        throw Error(where + ": DimSize must be 3 positive integers, got '" + shown(*f.find({"dimsize"})) + "'");
      dims[a] = std::int64_t(v[a]);
    }
  }
  const auto in_file = [&](auto&& fn) { return naming_file(where, fn); };
  const std::uint64_t n = in_file([&] { return GridVolume::checked_sample_count(dims); });
  if (const auto* c = f.find({"elementnumberofchannels"})) {
    const long long channels = f.integer(*c, "ElementNumberOfChannels", 1, 1 << 20);
    if (channels != 1)
      throw Error(where + " has " + std::to_string(channels) +
                  " channels a sample (ElementNumberOfChannels); vri reads scalar volumes");
  }
  const FileSampleType type = element_type(f.required("elementtype", "ElementType"), where);

  Vec3 spacing{1, 1, 1}, origin{0, 0, 0};
  if (const auto* s = f.find({"elementspacing", "elementsize"})) {
    const auto v = f.numbers(*s, "ElementSpacing", 3);
    for (int a = 0; a < 3; ++a) {
      if (!(v[a] > 0)) throw Error(where + ": ElementSpacing must be positive, got '" + shown(*s) + "'");
      spacing[a] = v[a];
    }
  }
  if (const auto* o = f.find({"offset", "origin", "position"})) {
    const auto v = f.numbers(*o, "Offset", 3);
    origin = {v[0], v[1], v[2]};
  }
  // Axis-aligned grids only: a diagonal of ±1, a -1 storing that axis backwards.
  std::array<bool, 3> flip{false, false, false};
  if (const auto* m = f.find({"transformmatrix", "orientation", "rotation", "direction"})) {
    const auto v = f.numbers(*m, "TransformMatrix", 9);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        if (std::abs(r == c ? std::abs(v[3 * r + c]) - 1 : v[3 * r + c]) > 1e-6)
          throw Error(where + ": TransformMatrix '" + shown(*m) + "' is not a diagonal of 1 and -1; vri reads "
                      "axis-aligned grids only (resample the volume)");
    for (int a = 0; a < 3; ++a) {
      flip[a] = v[4 * a] < 0;
      if (flip[a]) origin[a] -= double(dims[a] - 1) * spacing[a];
    }
  }
  if (!f.flag({"binarydata"}, "BinaryData", true)) throw Error(where + ": ASCII data (BinaryData False) are not supported");
  const Endian endian = f.flag({"binarydatabyteordermsb", "elementbyteordermsb"}, "BinaryDataByteOrderMSB", false)
                            ? Endian::Big
                            : Endian::Little;
  const bool compressed = f.flag({"compresseddata"}, "CompressedData", false);
  constexpr long long kMax = std::numeric_limits<long long>::max();
  const long long header_size =
      f.find({"headersize"}) ? f.integer(*f.find({"headersize"}), "HeaderSize", -1, kMax) : 0;

  // The data: after the header (LOCAL) or in a file beside it.
  const std::string& data_file = f.required("elementdatafile", "ElementDataFile");
  Source data = header_file;
  std::uint64_t start = header.end;
  if (to_lower(data_file) != "local") {
    if (data_file.rfind("LIST", 0) == 0 || data_file.find('%') != std::string::npos)
      throw Error(where + ": multi-file data (ElementDataFile = " + shown(data_file) + ") is not supported");
    data = file_source(detached_data_path(base_dir, data_file, options.allow_outside_paths, where, "ElementDataFile"));
    start = 0;
  }
  if (header_size > 0) {  // MetaIO seeks to it from the data file's start
    const std::string named = where + ": HeaderSize " + std::to_string(header_size);
    if (std::uint64_t(header_size) < start) throw Error(named + " points inside the header");
    if (std::uint64_t(header_size) > data.size) throw Error(named + " runs past the data");
    start = std::uint64_t(header_size);
  }
  const std::uint64_t need = n * file_sample_size(type), present = data.size - start;
  const auto volume = [&](const std::function<void(std::span<std::byte>)>& fill) {
    return in_file([&] {
      GridVolume::Samples samples = decode_file_samples(type, endian, n, fill);
      flip_samples(samples, {int(dims[0]), int(dims[1]), int(dims[2])}, flip);
      return GridVolume({int(dims[0]), int(dims[1]), int(dims[2])}, std::move(samples), spacing, origin);
    });
  };
  if (!compressed) {
    if (header_size == -1) {
      if (present < need) throw Error(where + " holds fewer data bytes than DimSize and ElementType need");
      start = data.size - need;
    } else if (present != need) {
      throw Error(where + " holds " + std::to_string(present) + " data bytes, but DimSize and ElementType need " +
                  std::to_string(need));
    }
    return volume([&](std::span<std::byte> out) { data.read(start, out); });
  }
  std::uint64_t packed_size = present;
  if (const auto* c = f.find({"compresseddatasize"})) {
    packed_size = std::uint64_t(f.integer(*c, "CompressedDataSize", 1, kMax));
    if (packed_size > present)
      throw Error(where + ": CompressedDataSize " + std::to_string(packed_size) + " is more than the " +
                  std::to_string(present) + " bytes present");
    if (header_size == -1) start = data.size - packed_size;
  } else if (header_size == -1) {
    throw Error(where + ": HeaderSize -1 with compressed data needs CompressedDataSize");
  }
  // deflate expands at most 1032:1: refuse sizes the compressed bytes cannot hold.
  if (need > 1032 * packed_size)
    throw Error(where + " declares " + std::to_string(need) + " data bytes, more than its " +
                std::to_string(packed_size) + " compressed bytes can hold");
  check_allocation(packed_size, 1, where + "'s compressed data");
  std::vector<std::byte> packed(packed_size);
  data.read(start, packed);
  return volume([&](std::span<std::byte> out) {
    const std::size_t got = gunzip_into(packed, 0, out);
    if (got != need)
      throw Error("the compressed data hold " + std::to_string(got) + " bytes, DimSize and ElementType need " +
                  std::to_string(need));
  });
}

std::string where_of(const std::string& source) { return "MetaImage '" + source + "'"; }

}  // namespace

GridVolume read_metaimage(const fs::path& path, const MetaImageOptions& options) {
  const Source file = file_source(path);
  std::vector<std::byte> prefix(std::min(file.size, kMaxHeader));
  file.read(0, prefix);
  return read_volume(file, prefix, path.parent_path(), where_of(path.string()), options);
}

GridVolume parse_metaimage(std::span<const std::byte> bytes, const fs::path& base_dir, const std::string& source,
                           const MetaImageOptions& options) {
  const Source memory{bytes.size(), [bytes](std::uint64_t offset, std::span<std::byte> out) {
                        copy_range(bytes, offset, out);
                      }};
  return read_volume(memory, bytes.first(std::min<std::size_t>(bytes.size(), kMaxHeader)), base_dir, where_of(source), options);
}

}  // namespace vri
