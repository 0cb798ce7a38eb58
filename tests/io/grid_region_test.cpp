// Reading one part of a grid (distributed rendering's bricks): raw and NRRD
// files read only the region's rows, gzip is read through keeping it, and
// each gives the samples and geometry of the same region cut from the whole.
#include "io/grid_region.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "io/gzip.hpp"
#include "test_support.hpp"
#include "vri/error.hpp"
#include "io/nrrd.hpp"
#include "vri/io.hpp"
#include "volume/builtin_volumes.hpp"

namespace vri {
namespace {

void expect_same_part(const GridVolume& part, const GridVolume& expected) {
  ASSERT_TRUE(part.brick());
  EXPECT_EQ(part.dims(), expected.dims());
  EXPECT_EQ(test::floats(part), test::floats(expected));
  EXPECT_EQ(part.brick()->offset, expected.brick()->offset);
  EXPECT_EQ(part.brick()->whole_dims, expected.brick()->whole_dims);
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(part.origin()[a], expected.origin()[a]);
    EXPECT_EQ(part.whole_hi()[a], expected.whole_hi()[a]);
  }
}

const GridRegion kRegion{{1, 2, 0}, {5, 3, 2}};

TEST(GridRegion, RawReadsTheRegionAlone) {
  test::TempDir dir;
  const GridVolume whole = random_field({7, 6, 4}, 3);
  std::vector<unsigned char> bytes;
  for (float v : test::floats(whole)) bytes.push_back(static_cast<unsigned char>(v * 255));
  test::write_bytes(dir / "v.raw", bytes);
  const GridVolume read_whole = read_raw_volume(dir / "v.raw", {7, 6, 4}, ScalarType::UInt8);
  const GridVolume part =
      read_raw_volume(dir / "v.raw", {7, 6, 4}, ScalarType::UInt8, Endian::Little, [](auto) { return kRegion; });
  expect_same_part(part, cut_region(read_whole, kRegion));
  EXPECT_EQ(part.bytes(), 5u * 2 * 3);  // the region's samples, no more
  EXPECT_THROW(read_raw_volume(dir / "v.raw", {7, 6, 4}, ScalarType::UInt8, Endian::Little,
                               [](auto) { return GridRegion{{0, 0, 0}, {7, 1, 1}}; }),
               Error);  // past the grid
}

// Issue 47: a rank read 7.7 times its brick's bytes, 8 KiB at a time. Rows
// that lie end to end in the file are read in one call, and no byte outside
// the region is asked for.
TEST(GridRegion, ReadsRunsOfRowsAndNothingElse) {
  const std::array<int, 3> dims{8, 5, 4};
  auto reads = [&](const GridRegion& region) {
    std::vector<std::pair<std::uint64_t, std::size_t>> calls;
    read_region(ScalarType::UInt8, Endian::Little, dims, region, [&](std::uint64_t offset, std::span<std::byte> out) {
      calls.emplace_back(offset, out.size());
      for (std::size_t i = 0; i < out.size(); ++i) out[i] = std::byte((offset + i) % 251);
    });
    return calls;
  };
  using Calls = std::vector<std::pair<std::uint64_t, std::size_t>>;
  EXPECT_EQ(reads({{0, 0, 0}, {7, 4, 3}}), (Calls{{0, 160}}));                         // the whole grid: one read
  EXPECT_EQ(reads({{0, 1, 1}, {7, 3, 2}}), (Calls{{48, 24}, {88, 24}}));                // full width: a plane's rows at once
  EXPECT_EQ(reads({{2, 1, 0}, {4, 2, 1}}), (Calls{{10, 3}, {18, 3}, {50, 3}, {58, 3}}));  // part of the width: row by row
  std::uint64_t bytes = 0;
  for (const auto& [offset, size] : reads(kRegion)) bytes += size;
  EXPECT_EQ(bytes, 5u * 2 * 3);
  // The samples land where the rows belong.
  const GridVolume::Samples s = read_region(ScalarType::UInt8, Endian::Little, dims, {{0, 1, 1}, {7, 3, 2}},
                                            [](std::uint64_t offset, std::span<std::byte> out) {
                                              for (std::size_t i = 0; i < out.size(); ++i)
                                                out[i] = std::byte((offset + i) % 251);
                                            });
  const auto& v = std::get<std::vector<std::uint8_t>>(s);
  EXPECT_EQ(v[0], 48);
  EXPECT_EQ(v[24], 88);
  EXPECT_EQ(v[47], 88 + 23);
}

TEST(GridRegion, NrrdRawGzipAndFlippedAxesReadTheRegion) {
  test::TempDir dir;
  GridVolume whole = random_field({7, 6, 4}, 5);
  whole.set_spacing({0.5, 1.25, 2});
  whole.set_origin({-1, 2, 3.5});
  for (auto enc : {NrrdEncoding::Raw, NrrdEncoding::Gzip}) {
    write_nrrd(dir / "v.nrrd", whole, enc);
    const GridVolume part = read_nrrd(dir / "v.nrrd", {.region = [](auto) { return kRegion; }});
    expect_same_part(part, cut_region(read_nrrd(dir / "v.nrrd"), kRegion));
  }
  // An axis stored backwards (negative direction): the file's mirror region is read, then flipped.
  const std::vector<float> v = test::floats(whole);
  std::ofstream out(dir / "flip.nrrd", std::ios::binary);
  out << "NRRD0004\ntype: float\ndimension: 3\nsizes: 7 6 4\nspace dimension: 3\n"
         "space directions: (0.5,0,0) (0,-1.25,0) (0,0,2)\nspace origin: (0,0,0)\nendian: little\nencoding: raw\n\n";
  out.write(reinterpret_cast<const char*>(v.data()), std::streamsize(v.size() * sizeof(float)));
  out.close();
  const GridVolume flipped = read_nrrd(dir / "flip.nrrd");
  expect_same_part(read_nrrd(dir / "flip.nrrd", {.region = [](auto) { return kRegion; }}), cut_region(flipped, kRegion));
}

TEST(GridRegion, StreamedPiecesOfAnySizeGiveTheRegion) {
  const GridVolume whole = random_field({9, 5, 4}, 7);
  const std::vector<float> v = test::floats(whole);
  const auto* bytes = reinterpret_cast<const std::byte*>(v.data());
  const GridRegion region{{2, 1, 1}, {6, 4, 3}};
  for (std::size_t piece : {1, 3, 4, 36, 1000}) {
    const GridVolume::Samples samples = read_region_streamed(
        ScalarType::Float32, Endian::Little, {9, 5, 4}, region, [&](const auto& sink) {
          for (std::size_t at = 0; at < v.size() * 4; at += piece)
            sink(at, std::span<const std::byte>(bytes + at, std::min(piece, v.size() * 4 - at)));
        });
    expect_same_part(make_part(samples, {9, 5, 4}, region), cut_region(whole, region));
  }
  EXPECT_THROW(read_region_streamed(ScalarType::Float32, Endian::Little, {9, 5, 4}, region,
                                    [&](const auto& sink) { sink(0, std::span<const std::byte>(bytes, 40)); }),
               Error);  // the stream ends inside the region
}

}  // namespace
}  // namespace vri
