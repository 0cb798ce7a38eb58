// Reading one part of a grid (distributed rendering's bricks): raw and NRRD
// files read only the region's rows, gzip is read through keeping it, and
// each gives the samples and geometry of the same region cut from the whole.
#include "vri/io/grid_region.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "io/gzip.hpp"
#include "test_support.hpp"
#include "vri/core/error.hpp"
#include "vri/io/nrrd.hpp"
#include "vri/io/raw_volume.hpp"
#include "vri/volume/builtin_volumes.hpp"

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
