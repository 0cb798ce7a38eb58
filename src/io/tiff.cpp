// TIFF stacks (tiff.hpp): a multi-page file or a folder of one-page slices,
// page = z, row = y, column = x (SPEC §11), decoded by libtiff
// (tiff_handle.hpp) straight into the volume's storage. Two passes: the
// first reads every page's directory (sizes, types) and checks the whole
// volume before anything is allocated; the second reads the samples.
#include "io/tiff.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <string_view>

#include "grid_samples.hpp"
#include "tiff_handle.hpp"
#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "vri/io.hpp"

namespace vri {

namespace fs = std::filesystem;
using tiff::Handle;

namespace {

// What every page must share with the first.
struct PageFormat {
  std::uint32_t width = 0, height = 0;
  std::uint16_t bits = 0, format = SAMPLEFORMAT_UINT;
  bool operator==(const PageFormat&) const = default;
};

std::string type_text(const PageFormat& f) {
  const char* kind = f.format == SAMPLEFORMAT_UINT     ? "uint"
                     : f.format == SAMPLEFORMAT_INT    ? "int"
                     : f.format == SAMPLEFORMAT_IEEEFP ? "float"
                     : f.format == SAMPLEFORMAT_VOID   ? "void"
                                                       : nullptr;
  if (!kind) return "sample format " + std::to_string(f.format) + " of " + std::to_string(f.bits) + " bits";
  return kind + std::to_string(f.bits);
}

std::string format_text(const PageFormat& f) {
  return std::to_string(f.width) + " x " + std::to_string(f.height) + " " + type_text(f);
}

FileSampleType sample_type(const PageFormat& f, const std::string& where) {
  // SampleFormat "void" (untyped) reads as unsigned, as libtiff's default.
  const bool uint = f.format == SAMPLEFORMAT_UINT || f.format == SAMPLEFORMAT_VOID;
  if (uint && f.bits == 8) return FileSampleType::UInt8;
  if (uint && f.bits == 16) return FileSampleType::UInt16;
  if (uint && f.bits == 32) return FileSampleType::UInt32;
  if (uint && f.bits == 64) return FileSampleType::UInt64;
  if (f.format == SAMPLEFORMAT_INT && f.bits == 8) return FileSampleType::Int8;
  if (f.format == SAMPLEFORMAT_INT && f.bits == 16) return FileSampleType::Int16;
  if (f.format == SAMPLEFORMAT_INT && f.bits == 32) return FileSampleType::Int32;
  if (f.format == SAMPLEFORMAT_INT && f.bits == 64) return FileSampleType::Int64;
  if (f.format == SAMPLEFORMAT_IEEEFP && f.bits == 16) return FileSampleType::Float16;
  if (f.format == SAMPLEFORMAT_IEEEFP && f.bits == 32) return FileSampleType::Float32;
  if (f.format == SAMPLEFORMAT_IEEEFP && f.bits == 64) return FileSampleType::Float64;
  throw Error(where + ": samples of " + type_text(f) + " are not supported; vri reads 8-, 16-, 32- and 64-bit " +
              "integers and 16-, 32- and 64-bit floats");
}

// The largest expansion of each codec: a file of B bytes decodes to at most
// B times this (PackBits 128 bytes from 2, Deflate's 1032:1, LZW's 12-bit
// codes of at most 4096 bytes; other codecs generously).
std::uint64_t largest_expansion(std::uint16_t compression) {
  switch (compression) {
    case COMPRESSION_NONE: return 1;
    case COMPRESSION_PACKBITS: return 64;
    case COMPRESSION_ADOBE_DEFLATE:
    case COMPRESSION_DEFLATE: return 1032;
    case COMPRESSION_LZW: return 4096;
    default: return std::uint64_t{1} << 20;
  }
}

// The current directory's format; vri::Error for what is not a grey image.
PageFormat page_format(const Handle& h, const std::string& where) {
  TIFF* tif = h.get();
  PageFormat f;
  std::uint16_t samples = 1, photometric = PHOTOMETRIC_MINISBLACK;
  std::uint32_t depth = 1;
  if (!TIFFGetField(tif, TIFFTAG_IMAGEWIDTH, &f.width) || !TIFFGetField(tif, TIFFTAG_IMAGELENGTH, &f.height))
    throw Error(where + ": has no ImageWidth or ImageLength");
  TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLESPERPIXEL, &samples);
  TIFFGetFieldDefaulted(tif, TIFFTAG_BITSPERSAMPLE, &f.bits);
  TIFFGetFieldDefaulted(tif, TIFFTAG_SAMPLEFORMAT, &f.format);
  TIFFGetFieldDefaulted(tif, TIFFTAG_IMAGEDEPTH, &depth);
  const bool has_photometric = TIFFGetField(tif, TIFFTAG_PHOTOMETRIC, &photometric);
  if (samples != 1)
    throw Error(where + ": has " + std::to_string(samples) + " samples per pixel" +
                (samples >= 3 ? " (RGB)" : "") + "; a volume needs one (grey): convert it to one channel");
  if (has_photometric && photometric != PHOTOMETRIC_MINISBLACK && photometric != PHOTOMETRIC_MINISWHITE)
    throw Error(where + ": is a " + (photometric == PHOTOMETRIC_PALETTE ? "palette (colour-mapped)" : "colour") +
                " image (photometric " + std::to_string(photometric) +
                "); a volume needs grey samples: convert it to one channel");
  if (depth != 1)
    throw Error(where + ": has ImageDepth " + std::to_string(depth) + " (an SGI volume image), which vri does not read");
  sample_type(f, where);
  return f;
}

// Reads the current directory's samples into `out` (height rows of width
// samples, row 0 first).
void read_page(const Handle& h, const PageFormat& f, std::span<std::byte> out, const std::string& where) {
  TIFF* tif = h.get();
  const std::uint64_t sample = f.bits / 8, row = std::uint64_t(f.width) * sample;
  h.clear_error();
  // libtiff replaces byte counts too short for the samples by an estimate
  // from the image's size, which reads on into the next page's bytes: they
  // were rendered with exit 0 (issue 47).
  if (h.byte_counts_replaced())
    throw Error(where + ": its strip or tile byte counts are shorter than its samples");
  if (!TIFFIsTiled(tif)) {
    if (TIFFScanlineSize64(tif) != row) h.fail(where, "its rows are not " + std::to_string(row) + " bytes");
    for (std::uint32_t y = 0; y < f.height; ++y)
      if (TIFFReadScanline(tif, out.data() + y * row, y, 0) < 0) h.fail(where, "cannot read row " + std::to_string(y));
    return;
  }
  std::uint32_t tw = 0, th = 0;
  if (!TIFFGetField(tif, TIFFTAG_TILEWIDTH, &tw) || !TIFFGetField(tif, TIFFTAG_TILELENGTH, &th) || tw == 0 || th == 0)
    throw Error(where + ": is tiled but has no tile size");
  const std::uint64_t tile_row = std::uint64_t(tw) * sample, tile_bytes = tile_row * th;
  if (TIFFTileRowSize64(tif) != tile_row || TIFFTileSize64(tif) != tile_bytes)
    h.fail(where, "its tiles of " + std::to_string(tw) + " x " + std::to_string(th) + " have an unexpected size");
  // A tile may exceed a small image (256 x 256 tiles of a 5 x 4 image), not absurdly.
  if (tile_bytes > std::max<std::uint64_t>(out.size(), std::uint64_t{64} << 20))
    throw Error(where + ": its tiles of " + std::to_string(tw) + " x " + std::to_string(th) + " samples are far " +
                "larger than the image");
  check_allocation(tile_bytes, "a TIFF tile");
  std::vector<std::byte> tile(tile_bytes);
  for (std::uint64_t ty = 0; ty < f.height; ty += th)
    for (std::uint64_t tx = 0; tx < f.width; tx += tw) {
      if (TIFFReadTile(tif, tile.data(), std::uint32_t(tx), std::uint32_t(ty), 0, 0) < 0)
        h.fail(where, "cannot read the tile at " + std::to_string(tx) + ", " + std::to_string(ty));
      const std::uint64_t rows = std::min<std::uint64_t>(th, f.height - ty);
      const std::uint64_t bytes = std::min<std::uint64_t>(tw, f.width - tx) * sample;
      for (std::uint64_t r = 0; r < rows; ++r)
        std::memcpy(out.data() + (ty + r) * row + tx * sample, tile.data() + r * tile_row, bytes);
    }
}

// A stack's pages, however they are stored: `count` of them, each visited by
// `each(z, handle, where)` with the handle on that page's directory.
struct Pages {
  std::string where;  // the file or folder, for errors about the whole
  std::uint64_t file_bytes = 0;
  std::function<void(const std::function<void(std::uint32_t, const Handle&, const std::string&)>&)> walk;
};

// ImageJ's voxel size (a stack ImageJ or Fiji saved: its ImageDescription
// starts "ImageJ="): x and y from XResolution and YResolution (pixels per
// unit), z from the description's "spacing=". Only for ImageJ's files: a
// scanner's 72 dpi is not a voxel size. Values that are not positive and
// finite are left at 1.
Vec3 imagej_spacing(const Handle& h) {
  TIFF* tif = h.get();
  Vec3 spacing{1, 1, 1};
  char* text = nullptr;
  if (!TIFFGetField(tif, TIFFTAG_IMAGEDESCRIPTION, &text) || !text || std::string_view(text).rfind("ImageJ=", 0) != 0)
    return spacing;
  const auto take = [](double v, double& into) {
    if (v > 0 && std::isfinite(v)) into = v;
  };
  float xres = 0, yres = 0;
  if (TIFFGetField(tif, TIFFTAG_XRESOLUTION, &xres) && xres > 0) take(1.0 / double(xres), spacing.x);
  if (TIFFGetField(tif, TIFFTAG_YRESOLUTION, &yres) && yres > 0) take(1.0 / double(yres), spacing.y);
  const std::string description(text);
  if (const auto at = description.find("\nspacing="); at != std::string::npos)
    take(std::strtod(description.c_str() + at + 9, nullptr), spacing.z);
  return spacing;
}

GridVolume read_pages(const Pages& pages) {
  // First pass: formats, sizes, the codecs' bounds, ImageJ's voxel size.
  PageFormat first;
  Vec3 spacing{1, 1, 1};
  std::uint32_t count = 0;
  std::uint64_t expansion = 1;
  pages.walk([&](std::uint32_t z, const Handle& h, const std::string& where) {
    const PageFormat f = page_format(h, where);
    if (z == 0) {
      first = f;
      spacing = imagej_spacing(h);
    }
    else if (!(f == first))
      throw Error(where + ": is " + format_text(f) + "; the first is " + format_text(first) +
                  " (every page must have the same size and sample type)");
    std::uint16_t compression = COMPRESSION_NONE;
    TIFFGetFieldDefaulted(h.get(), TIFFTAG_COMPRESSION, &compression);
    expansion = std::max(expansion, largest_expansion(compression));
    count = z + 1;
    // The volume so far (z at least 2 here: a width or height under 2 fails now).
    naming_file(where, [&] { return GridVolume::checked_sample_count({first.width, first.height, std::max(count, 2u)}); });
  });
  if (count < 2)
    throw Error(pages.where + ": has one page; a TIFF volume needs at least 2 pages (z), or a folder of one-page slices");
  const std::array<std::int64_t, 3> dims{first.width, first.height, count};
  const std::uint64_t n = naming_file(pages.where, [&] { return GridVolume::checked_sample_count(dims); });
  const FileSampleType type = sample_type(first, pages.where);
  const std::uint64_t page_bytes = std::uint64_t(first.width) * first.height * (first.bits / 8);
  const std::uint64_t need = page_bytes * count;
  if (pages.file_bytes > std::numeric_limits<std::uint64_t>::max() / expansion || need > pages.file_bytes * expansion)
    throw Error(pages.where + ": its " + std::to_string(pages.file_bytes) + " bytes cannot hold " + std::to_string(count) +
                " pages of " + format_text(first) + " (" + std::to_string(need) + " bytes; its compression expands at most " +
                std::to_string(expansion) + " times)");
  // Second pass, straight into the storage. The memory budget first, as
  // decode_file_samples checks it (the samples, and the file's bytes beside
  // them for a type converted to float), so that its error names the file.
  const bool kept = type == FileSampleType::UInt8 || type == FileSampleType::UInt16 ||
                    type == FileSampleType::Int16 || type == FileSampleType::Float32;
  naming_file(pages.where, [&] {
    check_allocation(n, file_sample_size(type) + (kept ? 0 : sizeof(float)), "a volume of " + std::to_string(n) + " samples");
    return 0;
  });
  const Endian native = std::endian::native == std::endian::big ? Endian::Big : Endian::Little;
  GridVolume::Samples samples = decode_file_samples(type, native, n, [&](std::span<std::byte> out) {
    std::uint32_t read = 0;
    pages.walk([&](std::uint32_t z, const Handle& h, const std::string& where) {
      if (z >= count || !(page_format(h, where) == first)) throw Error(where + ": changed while it was read");
      read_page(h, first, out.subspan(z * page_bytes, page_bytes), where);
      read = z + 1;
    });
    if (read != count) throw Error(pages.where + ": changed while it was read");
  });
  return naming_file(pages.where, [&] {
    GridVolume volume({int(dims[0]), int(dims[1]), int(dims[2])}, std::move(samples));
    volume.set_spacing(spacing);
    return volume;
  });
}

// The pages of one multi-page TIFF, opened by `open`.
Pages file_pages(const std::string& where, std::uint64_t file_bytes,
                 const std::function<std::unique_ptr<Handle>()>& open) {
  Pages pages{where, file_bytes, {}};
  pages.walk = [where, open](const auto& each) {
    const auto h = open();
    for (std::uint32_t z = 0;; ++z) {
      const std::string page = where + ", page " + std::to_string(z);
      each(z, *h, page);
      if (TIFFLastDirectory(h->get())) break;
      h->clear_error();
      if (!h->next_directory()) h->fail(where + ", page " + std::to_string(z + 1), "cannot read its directory");
    }
  };
  return pages;
}

std::string where_of(const std::string& source) { return "TIFF '" + source + "'"; }

}  // namespace

bool natural_less(std::string_view a, std::string_view b) {
  const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (digit(a[i]) && digit(b[j])) {
      std::size_t ie = i, je = j;
      while (ie < a.size() && digit(a[ie])) ++ie;
      while (je < b.size() && digit(b[je])) ++je;
      // Without leading zeros, a longer run is a larger number; equal lengths compare as text.
      std::size_t is = i, js = j;
      while (is + 1 < ie && a[is] == '0') ++is;
      while (js + 1 < je && b[js] == '0') ++js;
      const std::string_view x = a.substr(is, ie - is), y = b.substr(js, je - js);
      if (x.size() != y.size()) return x.size() < y.size();
      if (x != y) return x < y;
      if (ie - i != je - j) return ie - i < je - j;  // s2 before s02
      i = ie;
      j = je;
    } else {
      if (a[i] != b[j]) return static_cast<unsigned char>(a[i]) < static_cast<unsigned char>(b[j]);
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j;
}

std::vector<fs::path> tiff_slice_files(const fs::path& folder) {
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    std::string ext = it->path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    std::error_code type_ec;
    if (name.empty() || name[0] == '.' || (ext != ".tif" && ext != ".tiff") || !it->is_regular_file(type_ec)) continue;
    // A link leaving the folder is not followed (a folder from a stranger must
    // not read arbitrary files; docs/RELIABILITY.md).
    if (it->is_symlink(type_ec)) {
      std::error_code canon_ec;
      const fs::path rel = fs::canonical(it->path(), canon_ec).lexically_relative(fs::canonical(folder, canon_ec));
      if (canon_ec || rel.empty() || *rel.begin() == "..")
        throw Error("TIFF folder '" + folder.string() + "': '" + name + "' links to a file outside the folder, "
                    "which vri does not follow");
    }
    files.push_back(it->path());
  }
  if (ec) throw FileError("cannot list the folder '" + folder.string() + "': " + ec.message());
  if (files.empty()) throw Error("TIFF folder '" + folder.string() + "' holds no .tif or .tiff files");
  std::sort(files.begin(), files.end(),
            [](const fs::path& a, const fs::path& b) { return natural_less(a.filename().string(), b.filename().string()); });
  return files;
}

GridVolume read_tiff_volume(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_directory(path, ec)) {
    const std::string where = where_of(path.string());
    return read_pages(file_pages(where, checked_file_size(path), [path, where] {
      return std::make_unique<Handle>(path, where);
    }));
  }
  // A folder of slices: slice z is the z-th file in natural order.
  const std::vector<fs::path> files = tiff_slice_files(path);
  Pages pages{"TIFF folder '" + path.string() + "'", 0, {}};
  for (const fs::path& f : files) pages.file_bytes += checked_file_size(f);
  pages.walk = [files](const auto& each) {
    for (std::uint32_t z = 0; z < files.size(); ++z) {
      const std::string where = "TIFF slice '" + files[z].string() + "'";
      const Handle h(files[z], where);
      each(z, h, where);
      if (!TIFFLastDirectory(h.get()))
        throw Error(where + ": has more than one page; the slices of a folder must have one page each");
    }
  };
  return read_pages(pages);
}

GridVolume parse_tiff_volume(std::span<const std::byte> bytes, const std::string& source) {
  const std::string where = where_of(source);
  return read_pages(file_pages(where, bytes.size(), [bytes, source, where] {
    return std::make_unique<Handle>(bytes, source, where);
  }));
}

}  // namespace vri
