// VTK XML image data (.vti): a regular grid read through the shared VTK XML
// machinery (vtk_xml: DataArrays, base64, appended data, zlib blocks) and
// decoded straight into the volume's storage (vtk_grid). See io/vti.hpp.
// Format: https://docs.vtk.org/en/latest/design_documents/VTKFileFormats.html
// ("ImageData": WholeExtent, Origin, Spacing, Direction; Piece Extent).
#include "io/vti.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string_view>
#include <vector>

#include "core/checked_size.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "grid_samples.hpp"
#include "vtk_grid.hpp"
#include "vtk_xml.hpp"

namespace vri {

namespace {

// Exactly `n` numbers from an attribute's text (T: long long or double).
template <class T>
std::vector<T> numbers(const std::string& text, std::size_t n, const std::string& what) {
  std::vector<T> out;
  const char* p = text.data();
  const char* const end = p + text.size();
  while (true) {
    while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
    if (p == end) break;
    T v{};
    const auto [q, ec] = std::from_chars(p, end, v);
    if (ec != std::errc() || (q < end && !std::isspace(static_cast<unsigned char>(*q))) || out.size() == n)
      throw Error(what + " must be " + std::to_string(n) + " numbers, got '" + text + "'");
    out.push_back(v);
    p = q;
  }
  if (out.size() != n) throw Error(what + " must be " + std::to_string(n) + " numbers, got '" + text + "'");
  return out;
}

GridVolume parse(std::string_view text, const std::string& wanted) {
  const vtk::xml::Document doc = vtk::xml::read_document(text, "ImageData");
  std::string extent_text = doc.piece.attr("Extent", doc.dataset.attr("WholeExtent"));
  if (extent_text.empty()) throw Error("the Piece has no Extent");
  const auto extent = numbers<long long>(extent_text, 6, "Extent");
  std::array<std::int64_t, 3> dims{};
  for (int a = 0; a < 3; ++a) {
    const long long lo = extent[2 * a], hi = extent[2 * a + 1];
    constexpr long long kLimit = 1LL << 40;
    if (lo < -kLimit || hi > kLimit || hi < lo) throw Error("Extent '" + extent_text + "' is not a valid extent");
    dims[a] = hi - lo + 1;
  }
  // Cell data (a value per cell, VTK's CellData) where the points hold no
  // scalars to render: the grid of the cells' centres, one point fewer a side
  // and half a step in (as ParaView's Cell Centers filter places them).
  const bool cells = !doc.has_scalars("PointData", wanted) && doc.has_scalars("CellData", wanted);
  if (cells)
    for (std::int64_t& d : dims) d -= 1;
  // Refused before anything of the volume's size is allocated.
  const std::uint64_t n = GridVolume::checked_sample_count(dims);
  const auto origin_in = numbers<double>(doc.dataset.attr("Origin", "0 0 0"), 3, "Origin");
  const auto spacing_in = numbers<double>(doc.dataset.attr("Spacing", "1 1 1"), 3, "Spacing");
  const std::string direction_text = doc.dataset.attr("Direction", "1 0 0 0 1 0 0 0 1");
  const auto direction = numbers<double>(direction_text, 9, "Direction");
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      if (r == c ? std::abs(direction[3 * r + c]) != 1 : direction[3 * r + c] != 0)
        throw Error("Direction '" + direction_text +
                    "' is not diagonal with entries of +-1; vri reads axis-aligned grids only");
  // Sample index i along axis a lies at Origin + D_aa * Spacing * i, i in the
  // extent: an axis whose step is negative is flipped, and the volume starts at
  // its far end.
  Vec3 spacing, origin;
  std::array<bool, 3> flipped{};
  for (int a = 0; a < 3; ++a) {
    const double step = direction[4 * a] * spacing_in[a];
    flipped[a] = step < 0;
    spacing[a] = std::abs(step);
    origin[a] = origin_in[a] + step * double(extent[2 * a + (flipped[a] ? 1 : 0)]);
    if (cells) origin[a] += 0.5 * spacing[a];
  }

  const vtk::xml::Array& array = cells ? doc.section_array("CellData", wanted, doc.active_cell_scalars)
                                       : doc.point_array(wanted, doc.active_scalars);
  GridVolume::Samples samples = vtk::xml::for_array(array, [&] {
    if (array.format == "ascii") {
      const std::string_view data = text.substr(array.content_begin, array.content_end - array.content_begin);
      std::size_t used = 0;
      auto s = vtk::grid_samples_from_text(array.type, n, data, used);
      if (data.find_first_not_of(" \t\r\n", used) != std::string_view::npos)
        throw Error("holds more than the " + std::to_string(n) + " values its Extent needs");
      return s;
    }
    const vtk::xml::Payload payload(doc, array, checked_product({n, vtk::num_size(array.type)}, "the array size"));
    return vtk::grid_samples(array.type, doc.format.big_endian, n,
                             [&](std::span<std::byte> out) { payload.copy_to(out); });
  });
  const std::array<int, 3> idims{int(dims[0]), int(dims[1]), int(dims[2])};
  flip_samples(samples, idims, flipped);
  return GridVolume(idims, std::move(samples), spacing, origin);
}

}  // namespace

GridVolume parse_vti(std::span<const std::byte> bytes, const std::string& scalars, const std::string& source) {
  try {
    return parse(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), scalars);
  } catch (const Error& e) {
    throw Error(source + ": " + e.what());
  }
}

GridVolume read_vti(const std::filesystem::path& path, const std::string& scalars) {
  const auto bytes = read_file(path);
  return parse_vti(bytes, scalars, "volume '" + path.string() + "'");
}

}  // namespace vri
