// NRRD volumes, read and written (nrrd.hpp); the format: https://teem.sourceforge.net/nrrd/format.html
#include "io/nrrd.hpp"

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <string>

#include "grid_samples.hpp"
#include "gzip.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "io/grid_region.hpp"

namespace vri {

namespace fs = std::filesystem;

namespace {

ScalarType nrrd_type(const std::string& raw) {
  static const std::map<std::string, ScalarType> names = {
      {"uchar", ScalarType::UInt8},        {"unsigned char", ScalarType::UInt8},
      {"uint8", ScalarType::UInt8},        {"uint8_t", ScalarType::UInt8},
      {"signed char", ScalarType::Int8},   {"int8", ScalarType::Int8},
      {"int8_t", ScalarType::Int8},        {"short", ScalarType::Int16},
      {"short int", ScalarType::Int16},    {"signed short", ScalarType::Int16},
      {"signed short int", ScalarType::Int16}, {"int16", ScalarType::Int16},
      {"int16_t", ScalarType::Int16},      {"ushort", ScalarType::UInt16},
      {"unsigned short", ScalarType::UInt16}, {"unsigned short int", ScalarType::UInt16},
      {"uint16", ScalarType::UInt16},      {"uint16_t", ScalarType::UInt16},
      {"int", ScalarType::Int32},          {"signed int", ScalarType::Int32},
      {"int32", ScalarType::Int32},        {"int32_t", ScalarType::Int32},
      {"uint", ScalarType::UInt32},        {"unsigned int", ScalarType::UInt32},
      {"uint32", ScalarType::UInt32},      {"uint32_t", ScalarType::UInt32},
      {"float", ScalarType::Float32},      {"double", ScalarType::Float64},
  };
  const auto it = names.find(to_lower(raw));
  if (it == names.end()) throw Error("NRRD type '" + raw + "' is not supported");
  return it->second;
}

std::vector<double> parse_numbers(const std::string& text, const std::string& field) {
  std::vector<double> out;
  std::string cleaned = text;
  for (char& c : cleaned)
    if (c == '(' || c == ')' || c == ',') c = ' ';
  std::istringstream in(cleaned);
  std::string tok;
  while (in >> tok) {
    if (to_lower(tok) == "none" || to_lower(tok) == "nan") {
      out.push_back(std::nan(""));
      continue;
    }
    double v;
    const auto [p, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), v);
    if (ec != std::errc() || p != tok.data() + tok.size())
      throw Error("NRRD field '" + field + "' has a bad number '" + tok + "'");
    out.push_back(v);
  }
  return out;
}

// A whole-token integer in [lo, hi]; anything else (fractions, 1e300, junk)
// is refused naming the field, instead of a wrapping or undefined cast.
long long parse_integer(const std::string& text, const std::string& field, long long lo, long long hi) {
  const std::string t = trim_blanks(text);
  long long v = 0;
  const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (ec != std::errc() || p != t.data() + t.size() || t.empty() || v < lo || v > hi)
    throw Error("NRRD field '" + field + "' must be an integer from " + std::to_string(lo) + " to " +
                std::to_string(hi) + ", got '" + t + "'");
  return v;
}

// Integers separated by spaces (the 'sizes' field).
std::vector<std::int64_t> parse_integers(const std::string& text, const std::string& field, long long hi) {
  std::vector<std::int64_t> out;
  std::istringstream in(text);
  for (std::string tok; in >> tok;) out.push_back(parse_integer(tok, field, 1, hi));
  return out;
}

// Splits "(a,b,c) (d,e,f) none" into vectors (none -> empty).
std::vector<std::vector<double>> parse_vectors(const std::string& text, const std::string& field) {
  std::vector<std::vector<double>> out;
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] == '(') {
      const auto close = text.find(')', i);
      if (close == std::string::npos) throw Error("NRRD field '" + field + "' is malformed");
      out.push_back(parse_numbers(text.substr(i + 1, close - i - 1), field));
      i = close + 1;
    } else if (to_lower(text.substr(i, 4)) == "none") {
      out.emplace_back();
      i += 4;
    } else {
      ++i;
    }
  }
  return out;
}

// The spacing along grid axis `axis` from its 'space directions' vector `d`
// ("none": spacing 1). vri grids are axis-aligned, so `d` must lie along that
// axis; a negative entry runs the axis backwards (`flip`), and the reader
// mirrors the samples so that each lands where the file puts it.
double axis_step(const std::vector<double>& d, int axis, const std::string& where, bool& flip) {
  if (d.empty()) return 1;
  std::ostringstream text;
  text << '(';
  for (std::size_t c = 0; c < d.size(); ++c) text << (c ? "," : "") << d[c];
  text << ')';
  if (d.size() != 3) throw Error(where + ": 'space directions' vector " + text.str() + " needs 3 components");
  const double along = d[axis];
  if (!std::isfinite(along) || along == 0)
    throw Error(where + ": 'space directions' vector " + text.str() + " has no step along its axis");
  for (int b = 0; b < 3; ++b)
    if (b != axis && !(std::abs(d[b]) <= 1e-6 * std::abs(along)))
      throw Error(where + ": 'space directions' vector " + text.str() +
                  " is not along its axis; vri reads axis-aligned grids only (resample the volume)");
  flip = along < 0;
  return std::abs(along);
}

}  // namespace

GridVolume read_nrrd(const fs::path& path, const NrrdOptions& options) {
  const std::string where = "NRRD '" + path.string() + "'";
  require_regular_file(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError("cannot open '" + path.string() + "': " + std::strerror(errno));
  std::string line;
  if (!std::getline(in, line) || line.rfind("NRRD000", 0) != 0)
    throw Error(where + " does not start with the NRRD magic");

  // Header: lines up to the first empty line (or the end of a detached header).
  // Only the header is read here: the payload goes straight into the volume.
  std::map<std::string, std::string> fields;
  std::uint64_t data_start = checked_file_size(path);
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) {
      data_start = static_cast<std::uint64_t>(in.tellg());
      break;
    }
    if (line[0] == '#') continue;
    if (line.find(":=") != std::string::npos) continue;  // key/value pairs: ignored
    const auto colon = line.find(": ");
    if (colon == std::string::npos) throw Error(where + " has a malformed header line '" + line + "'");
    fields[to_lower(trim_blanks(line.substr(0, colon)))] = trim_blanks(line.substr(colon + 2));
  }
  auto field = [&](std::initializer_list<const char*> keys) -> const std::string* {
    for (const char* k : keys)
      if (auto it = fields.find(k); it != fields.end()) return &it->second;
    return nullptr;
  };
  auto required = [&](const char* key) -> const std::string& {
    const std::string* v = field({key});
    if (!v) throw Error(where + " lacks the required field '" + key + "'");
    return *v;
  };

  const ScalarType type = nrrd_type(required("type"));
  const auto checked = [&](auto&& f) { return naming_file(where, f); };
  const int dimension = int(checked([&] { return parse_integer(required("dimension"), "dimension", 1, 16); }));
  const auto sizes = checked([&] { return parse_integers(required("sizes"), "sizes", std::int64_t{1} << 40); });
  if (int(sizes.size()) != dimension) throw Error(where + ": 'sizes' does not match 'dimension'");
  int skip_axes = 0;
  if (dimension == 4 && sizes[0] == 1) skip_axes = 1;  // a scalar axis of one value
  else if (dimension != 3) throw Error(where + " is " + std::to_string(dimension) + "D; vri reads 3D scalar volumes");
  const std::array<std::int64_t, 3> dims{sizes[skip_axes], sizes[skip_axes + 1], sizes[skip_axes + 2]};
  const std::uint64_t n = checked([&] { return GridVolume::checked_sample_count(dims); });

  Vec3 spacing{1, 1, 1}, origin{0, 0, 0};
  std::array<bool, 3> flip{false, false, false};  // axes the file stores backwards
  if (const auto* sp = field({"spacings"})) {
    const auto v = parse_numbers(*sp, "spacings");
    if (int(v.size()) != dimension) throw Error(where + ": 'spacings' does not match 'dimension'");
    for (int a = 0; a < 3; ++a)
      if (std::isfinite(v[a + skip_axes])) spacing[a] = std::abs(v[a + skip_axes]);
  } else if (const auto* dirs = field({"space directions"})) {
    const auto v = checked([&] { return parse_vectors(*dirs, "space directions"); });
    if (int(v.size()) != dimension) throw Error(where + ": 'space directions' does not match 'dimension'");
    for (int a = 0; a < 3; ++a) spacing[a] = axis_step(v[a + skip_axes], a, where, flip[a]);
  }
  if (const auto* so = field({"space origin"})) {
    const auto v = parse_numbers(*so, "space origin");
    if (v.size() != 3) throw Error(where + ": 'space origin' needs 3 values");
    origin = {v[0], v[1], v[2]};
  }
  // The first stored sample is the file's last one along a flipped axis.
  for (int a = 0; a < 3; ++a)
    if (flip[a]) origin[a] -= double(dims[a] - 1) * spacing[a];
  const std::array<int, 3> grid{int(dims[0]), int(dims[1]), int(dims[2])};
  const auto volume = [&](GridVolume::Samples samples) {
    flip_samples(samples, grid, flip);
    return checked([&] { return GridVolume(grid, std::move(samples), spacing, origin); });
  };
  // One part (options.region): the region it picks, read from the file's
  // mirror image of it along flipped axes, then flipped in place.
  std::optional<GridRegion> region, stored;
  if (options.region) {
    region = options.region(grid);
    check_region(*region, grid);
    stored = region;
    for (int a = 0; a < 3; ++a)
      if (flip[a]) stored->lo[a] = grid[a] - 1 - region->hi[a], stored->hi[a] = grid[a] - 1 - region->lo[a];
  }
  const auto part = [&](GridVolume::Samples samples) {
    flip_samples(samples, region->dims(), flip);
    return checked([&] { return make_part(std::move(samples), grid, *region, spacing, origin); });
  };

  const std::string encoding = to_lower(required("encoding"));
  Endian endian = Endian::Little;
  if (const auto* e = field({"endian"})) {
    if (to_lower(*e) == "big") endian = Endian::Big;
    else if (to_lower(*e) != "little") throw Error(where + ": unknown endian '" + *e + "'");
  }
  // byte skip -1 means "the data is the last bytes of the file" (raw only, per
  // the NRRD spec); other negative skips are meaningless.
  constexpr long long kMaxSkip = std::numeric_limits<long long>::max();
  long long byte_skip = 0, line_skip = 0;
  if (const auto* b = field({"byte skip", "byteskip"}))
    byte_skip = checked([&] { return parse_integer(*b, "byte skip", -1, kMaxSkip); });
  if (const auto* l = field({"line skip", "lineskip"}))
    line_skip = checked([&] { return parse_integer(*l, "line skip", 0, kMaxSkip); });

  // The data: attached after the header, or in a detached file; `start` is
  // its first byte, `size` the bytes from there to the end.
  fs::path data_path = path;
  std::uint64_t start = data_start;
  if (const auto* df = field({"data file", "datafile"})) {
    if (df->rfind("LIST", 0) == 0 || df->find('%') != std::string::npos)
      throw Error(where + ": multi-file data ('" + *df + "') is not supported");
    data_path = detached_data_path(path.parent_path(), *df, options.allow_outside_paths, where, "data file");
    start = 0;
  }
  const std::uint64_t end = checked_file_size(data_path);
  if (start >= end && n > 0) throw Error(where + " has no data after its header");
  if (line_skip > 0) {
    std::ifstream data(data_path, std::ios::binary);
    data.seekg(static_cast<std::streamoff>(start));
    for (long long l = 0; l < line_skip; ++l)
      if (!data.ignore(std::numeric_limits<std::streamsize>::max(), '\n') || data.tellg() < 0)
        throw Error(where + ": 'line skip' runs past the data");
    start = static_cast<std::uint64_t>(data.tellg());
  }
  const auto rest = [&] {
    std::vector<std::byte> bytes(end - start);
    read_file_range(data_path, start, bytes);
    return bytes;
  };

  const std::uint64_t need = n * scalar_type_size(type);
  const auto wrong_size = [&](std::uint64_t size) {
    return Error(where + " holds " + std::to_string(size) + " data bytes, but its sizes and type need " +
                 std::to_string(need));
  };
  if (encoding == "raw") {
    if (byte_skip == -1) {
      if (end - start < need) throw Error(where + " holds fewer bytes than its sizes need");
      start = end - need;
    } else if (byte_skip > 0) {
      if (std::uint64_t(byte_skip) > end - start) throw Error(where + ": 'byte skip' runs past the data");
      start += std::uint64_t(byte_skip);
    }
    if (end - start != need) throw wrong_size(end - start);
    if (region) return part(read_region_from_file(data_path, start, type, endian, grid, *stored));
    return volume(GridVolume::decode(type, endian, n, [&](std::span<std::byte> out) {
      read_file_range(data_path, start, out);
    }));
  }
  if (encoding == "gzip" || encoding == "gz") {
    if (byte_skip < 0) throw Error(where + ": 'byte skip: -1' only works with raw encoding (NRRD spec)");
    // deflate expands at most 1032:1: a header claiming more than the
    // compressed bytes could hold is refused before the volume is allocated.
    if ((need + std::uint64_t(byte_skip)) / 1032 > end - start)
      throw Error(where + " declares " + std::to_string(need) + " data bytes, more than its " +
                  std::to_string(end - start) + " gzip bytes can hold");
    const std::vector<std::byte> packed = rest();
    if (region)  // read through once, keeping the region
      return part(read_region_streamed(type, endian, grid, *stored, [&](const auto& piece) {
        const std::uint64_t got = gunzip_each(packed, std::uint64_t(byte_skip), need, piece);
        if (got != need) throw wrong_size(got);
      }));
    return volume(GridVolume::decode(type, endian, n, [&](std::span<std::byte> out) {
      const std::size_t got = gunzip_into(packed, std::size_t(byte_skip), out);
      if (got != need) throw wrong_size(got);
    }));
  }
  if (encoding == "ascii" || encoding == "text" || encoding == "txt") {
    if (byte_skip != 0) throw Error(where + ": 'byte skip' does not apply to ascii encoding");
    // Each value takes at least two bytes: refuse sizes the text cannot hold.
    if (n > (end - start) / 2 + 1)
      throw Error(where + " declares " + std::to_string(n) + " ascii values in " + std::to_string(end - start) + " bytes");
    const std::vector<std::byte> bytes = rest();
    const std::string text(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const auto v = parse_numbers(text, "data");
    if (v.size() != n)
      throw Error(where + " holds " + std::to_string(v.size()) + " ascii values, expected " + std::to_string(n));
    if (region) return cut_region(volume(std::vector<float>(v.begin(), v.end())), *region);
    return volume(std::vector<float>(v.begin(), v.end()));
  }
  throw Error(where + ": encoding '" + encoding + "' is not supported (raw, gzip, ascii)");
}

void write_nrrd(const fs::path& path, const GridVolume& volume, NrrdEncoding encoding) {
  const auto& d = volume.dims();
  // The samples as stored (little-endian, as this machine holds them).
  const std::span<const std::byte> raw = volume.visit([](auto v) { return std::as_bytes(v); });
  const char* type = volume.type() == ScalarType::UInt8    ? "uchar"
                     : volume.type() == ScalarType::UInt16 ? "ushort"
                     : volume.type() == ScalarType::Int16  ? "short"
                                                           : "float";
  std::vector<std::byte> payload = encoding == NrrdEncoding::Gzip ? gzip(raw)
                                                                  : std::vector<std::byte>(raw.begin(), raw.end());
  const bool detached = path.extension() == ".nhdr";
  std::ostringstream h;
  h.precision(17);
  h << "NRRD0004\n# written by vri\ntype: " << type << "\ndimension: 3\n"
    << "sizes: " << d[0] << " " << d[1] << " " << d[2] << "\n"
    << "spacings: " << volume.spacing().x << " " << volume.spacing().y << " " << volume.spacing().z << "\n"
    << "space origin: (" << volume.origin().x << "," << volume.origin().y << "," << volume.origin().z << ")\n"
    << "endian: little\nencoding: " << (encoding == NrrdEncoding::Gzip ? "gzip" : "raw") << "\n";
  if (detached) {
    const fs::path data_name =
        path.stem().string() + (encoding == NrrdEncoding::Gzip ? ".raw.gz" : ".raw");
    h << "data file: " << data_name.string() << "\n";
    write_file_atomically(path.parent_path() / data_name, payload);
    const std::string header = h.str();
    write_file_atomically(path, std::as_bytes(std::span(header)));
    return;
  }
  h << "\n";
  const std::string header = h.str();
  std::vector<std::byte> out(reinterpret_cast<const std::byte*>(header.data()),
                             reinterpret_cast<const std::byte*>(header.data()) + header.size());
  out.insert(out.end(), payload.begin(), payload.end());
  write_file_atomically(path, out);
}

}  // namespace vri
