// Legacy VTK STRUCTURED_POINTS files as regular grids (see
// io/vtk_legacy.hpp): the header, cursor and attribute sections are
// vtk_legacy_reader, shared with the unstructured-grid reader; the chosen
// point array is decoded straight into the volume's storage (vtk_grid).
// Format: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html
// ("Structured Points": DIMENSIONS, ORIGIN, SPACING or ASPECT_RATIO).
#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cstring>
#include <optional>
#include <vector>

#include "core/checked_size.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "io/vtk_legacy.hpp"
#include "vtk_grid.hpp"
#include "vtk_legacy_reader.hpp"

namespace vri {

namespace {

using namespace vtk::legacy;

Vec3 vec3_of(const std::vector<std::string>& w) {
  need(w, 4);
  Vec3 v;
  for (int a = 0; a < 3; ++a) {
    const std::string& s = w[1 + a];
    const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v[a]);
    if (ec != std::errc() || p != s.data() + s.size()) throw Error("bad number '" + s + "' in " + w[0]);
  }
  return v;
}

GridVolume parse(Cursor& in, const std::string& wanted) {
  const Header header = read_header(in);
  if (header.dataset != "STRUCTURED_POINTS")
    throw Error("dataset is " + header.dataset + ", not STRUCTURED_POINTS");
  std::optional<std::array<std::int64_t, 3>> dims;
  std::uint64_t n = 0;
  Vec3 spacing{1, 1, 1}, origin{0, 0, 0};
  Attributes attributes;
  while (!in.at_end()) {
    const auto w = split(in.line());
    if (w.empty()) continue;
    const std::string& key = w[0];
    if (key == "DIMENSIONS") {
      need(w, 4);
      dims = {std::int64_t(count_of(w[1], "dimension")), std::int64_t(count_of(w[2], "dimension")),
              std::int64_t(count_of(w[3], "dimension"))};
      n = GridVolume::checked_sample_count(*dims);  // refused before anything is allocated
    } else if (key == "SPACING" || key == "ASPECT_RATIO") {
      spacing = vec3_of(w);
    } else if (key == "ORIGIN") {
      origin = vec3_of(w);
    } else if (!attributes.read(in, w, n)) {
      throw Error("unsupported section '" + key + "'");
    }
  }
  if (!dims) throw Error("no DIMENSIONS");
  const ArrayRef& array = attributes.choose(wanted, n);
  GridVolume::Samples samples = [&]() -> GridVolume::Samples {
    if (array.color && !in.binary) {  // floats in [0, 1] for unsigned chars
      const auto v = attributes.values(in, array);
      return std::vector<std::uint8_t>(v.begin(), v.end());
    }
    in.seek(array.at);
    if (!in.binary) {
      std::size_t used = 0;
      return vtk::grid_samples_from_text(array.type, n, in.rest_text(), used);
    }
    const std::uint64_t size = n * vtk::num_size(array.type);
    if (in.rest().size() < size) throw Error("binary data ends early");  // checked when skipped, too
    const auto bytes = in.rest().first(size);
    return vtk::grid_samples(array.type, /*big_endian=*/true, n, [&](std::span<std::byte> out) {
      std::copy(bytes.begin(), bytes.end(), out.begin());
    });
  }();
  return GridVolume({int((*dims)[0]), int((*dims)[1]), int((*dims)[2])}, std::move(samples), spacing, origin);
}

}  // namespace

GridVolume parse_vtk_structured_points(std::span<const std::byte> bytes, const std::string& scalars,
                                       const std::string& source) {
  try {
    vtk::legacy::Cursor in(bytes);
    return parse(in, scalars);
  } catch (const Error& e) {
    throw Error(source + ": " + e.what());
  }
}

GridVolume read_vtk_structured_points(const std::filesystem::path& path, const std::string& scalars) {
  const auto bytes = read_file(path);
  return parse_vtk_structured_points(bytes, scalars, "volume '" + path.string() + "'");
}

bool vtk_legacy_is_structured_points(std::span<const std::byte> head) {
  try {
    vtk::legacy::Cursor in(head.first(std::min<std::size_t>(head.size(), 1024)));
    return read_header(in).dataset == "STRUCTURED_POINTS";
  } catch (const Error&) {
    return false;
  }
}

}  // namespace vri
