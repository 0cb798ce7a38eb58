#pragma once
// One entry per parser for the libFuzzer harnesses (fuzz/*.cpp) and for the
// replay of every input they ever crashed on (tests/io/fuzz_regressions_test.cpp).
// Each entry goes through the same public function the CLI uses; bad input
// must end in vri::Error and nothing else (no crash, no other exception, no
// allocation beyond the memory budget set here).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>

#include "io/gzip.hpp"
#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "io/metaimage.hpp"
#include "vri/io.hpp"
#include "io/nrrd.hpp"
#include "io/tiff.hpp"
#include "io/volvis_dat.hpp"
#include "io/vti.hpp"
#include "io/vtk_legacy.hpp"
#include "io/vtu.hpp"
#include "vri/scene.hpp"
#include "transfer/paraview_colormap.hpp"

namespace vri::fuzz {

// A private folder per process holding the fuzzed file, two small data files
// a detached NRRD header or a scene may name, and a ParaView colour map (cm.json)
// a transfer function may name.
inline const std::filesystem::path& work_dir() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() / ("vri_fuzz_" + std::to_string(::getpid()));
    std::filesystem::create_directories(d);
    std::ofstream(d / "d.raw", std::ios::binary) << std::string(64, '\x07');
    const std::vector<std::byte> zeros(64);
    const auto gz = gzip(zeros);
    std::ofstream(d / "d.raw.gz", std::ios::binary).write(reinterpret_cast<const char*>(gz.data()), std::streamsize(gz.size()));
    std::ofstream(d / "cm.json") << R"([{"Name": "A", "ColorSpace": "Diverging",)"
                                 << R"( "RGBPoints": [0, 0.23, 0.3, 0.75, 1, 0.7, 0.02, 0.15],)"
                                 << R"( "Points": [0, 0, 0.5, 0, 1, 0.8, 0.3, 0.6]},)"
                                 << R"( {"Name": "B", "RGBPoints": [0, 0, 0, 0]}])";
    // Well under libFuzzer's rss limit (2 GB), and small enough that legitimate
    // but heavy inputs (a 64^3 grid split into 1.25 million tetrahedra) are
    // refused by the budget instead of running past the 10 s timeout under ASan.
    set_memory_limit(std::uint64_t{16} << 20);
    std::atexit([] {
      std::error_code ec;
      std::filesystem::remove_all(std::filesystem::temp_directory_path() / ("vri_fuzz_" + std::to_string(::getpid())), ec);
    });
    return d;
  }();
  return dir;
}

inline std::filesystem::path file_of(std::span<const std::byte> data, const std::string& name) {
  const auto path = work_dir() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
  return path;
}

inline std::string_view text_of(std::span<const std::byte> data) {
  return {reinterpret_cast<const char*>(data.data()), data.size()};
}

// Raw volume: the first 4 bytes choose dims (1..16 each, or a huge dim), type
// and endianness, as a scene's volume block would; the rest is the file.
inline void raw(std::span<const std::byte> data) {
  if (data.size() < 4) return;
  const auto b = [&](int i) { return std::to_integer<unsigned>(data[i]); };
  const auto dim = [&](unsigned v) -> std::int64_t { return v >= 0xf0 ? (std::int64_t{1} << (v - 0xdc)) : std::int64_t(v % 17); };
  static const ScalarType types[] = {ScalarType::UInt8, ScalarType::Int8, ScalarType::UInt16, ScalarType::Int16,
                                     ScalarType::UInt32, ScalarType::Int32, ScalarType::Float32, ScalarType::Float64};
  read_raw_volume(file_of(data.subspan(4), "f.raw"), {dim(b(0)), dim(b(1)), dim(b(2))}, types[b(3) % 8],
                  b(3) & 8 ? Endian::Big : Endian::Little);
}

inline void nrrd(std::span<const std::byte> data) {
  // A name ending .nhdr or .nrrd reads the same; detached data lies beside it.
  read_nrrd(file_of(data, "f.nrrd"));
}

// gzip NRRD: a fixed header whose sizes come from the first 3 bytes, then the
// input's remaining bytes as the gzip payload.
inline void nrrd_gzip(std::span<const std::byte> data) {
  if (data.size() < 3) return;
  std::string text = "NRRD0004\ntype: uchar\ndimension: 3\nencoding: gzip\nsizes:";
  for (int a = 0; a < 3; ++a) (text += ' ') += std::to_string(1 + std::to_integer<unsigned>(data[a]) % 16);
  text += "\n\n";
  text.append(text_of(data.subspan(3)));
  read_nrrd(file_of(std::as_bytes(std::span(text)), "g.nrrd"));
}

inline void volvis_dat(std::span<const std::byte> data) { read_volvis_dat(file_of(data, "f.dat")); }

// MetaImage: the input is an .mha (header and data); a header naming a data
// file finds d.raw and d.raw.gz in the work folder.
inline void metaimage(std::span<const std::byte> data) { parse_metaimage(data, work_dir(), "fuzz.mha"); }

inline void npy_volume(std::span<const std::byte> data) { parse_npy_volume(data, "fuzz.npy"); }

// A multi-page TIFF in memory (libtiff through TIFFClientOpen).
inline void tiff(std::span<const std::byte> data) { parse_tiff_volume(data, "fuzz.tif"); }

inline void vtk_legacy(std::span<const std::byte> data) { parse_vtk_legacy(data, "", "fuzz.vtk"); }

inline void vtu(std::span<const std::byte> data) { parse_vtu(data, "", "fuzz.vtu"); }

inline void vti(std::span<const std::byte> data) { parse_vti(data, "", "fuzz.vti"); }

inline void vtk_structured_points(std::span<const std::byte> data) {
  vtk_legacy_is_structured_points(data);
  parse_vtk_structured_points(data, "", "fuzz.vtk");
}

inline void scene(std::span<const std::byte> data) { parse_scene(text_of(data), work_dir(), "fuzz scene"); }

// Transfer functions: every JSON form ("paraview": "cm.json" finds a preset in
// the work folder); an input starting with '[' is a ParaView colour-map file
// itself, read and reduced to linear pieces.
inline void transfer_function(std::span<const std::byte> data) {
  const std::string_view text = text_of(data);
  if (!text.empty() && text.front() == '[') {
    const ParaviewColormap map = parse_paraview_colormap(text, "fuzz paraview");
    linear_colors(map);
    if (!map.opacity.empty()) linear_opacity(map.opacity);
    return;
  }
  parse_transfer_function(text, "fuzz tf", nullptr, work_dir());
}

// Runs one input; vri::Error is the expected outcome of bad input, anything
// else escapes (libFuzzer reports it as a crash).
inline void run(const std::function<void(std::span<const std::byte>)>& target, const std::uint8_t* data, std::size_t size) {
  work_dir();  // sets the memory budget too
  try {
    target(std::as_bytes(std::span(data, size)));
  } catch (const Error&) {
  }
}

inline const std::map<std::string, std::function<void(std::span<const std::byte>)>>& targets() {
  static const std::map<std::string, std::function<void(std::span<const std::byte>)>> all = {
      {"raw", raw},         {"nrrd", nrrd}, {"nrrd_gzip", nrrd_gzip}, {"volvis_dat", volvis_dat},
      {"vtk_legacy", vtk_legacy}, {"vtu", vtu}, {"vti", vti}, {"vtk_structured_points", vtk_structured_points}, {"metaimage", metaimage}, {"npy_volume", npy_volume}, {"tiff", tiff}, {"scene", scene},    {"transfer_function", transfer_function}};
  return all;
}

}  // namespace vri::fuzz
