#include "vri/io.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <utility>

#include "test_support.hpp"
#include "vri/error.hpp"

namespace vri {
namespace {

TEST(RawVolume, ReadsEveryTypeInBothByteOrders) {
  test::TempDir dir;
  // 2x2x2 samples: uint16 little-endian 0x0102 = 258 at index 1
  std::vector<unsigned char> u16(16, 0);
  u16[2] = 0x02;
  u16[3] = 0x01;
  test::write_bytes(dir / "a.raw", u16);
  EXPECT_FLOAT_EQ(read_raw_volume(dir / "a.raw", {2, 2, 2}, ScalarType::UInt16).at(1, 0, 0), 258);
  EXPECT_FLOAT_EQ(read_raw_volume(dir / "a.raw", {2, 2, 2}, ScalarType::UInt16, Endian::Big).at(1, 0, 0), 513);
  std::vector<unsigned char> i16(16, 0);
  i16[14] = 0xfe;  // -2 at the last sample
  i16[15] = 0xff;
  test::write_bytes(dir / "b.raw", i16);
  EXPECT_FLOAT_EQ(read_raw_volume(dir / "b.raw", {2, 2, 2}, ScalarType::Int16).at(1, 1, 1), -2);
  std::vector<unsigned char> f32(32, 0);
  const float v = -3.25f;
  std::memcpy(&f32[4 * 6], &v, 4);  // sample (0, 1, 1)
  test::write_bytes(dir / "c.raw", f32);
  EXPECT_FLOAT_EQ(read_raw_volume(dir / "c.raw", {2, 2, 2}, ScalarType::Float32).at(0, 1, 1), -3.25f);
  std::vector<unsigned char> u8{0, 1, 2, 3, 4, 5, 6, 255};
  test::write_bytes(dir / "d.raw", u8);
  const auto vol = read_raw_volume(dir / "d.raw", {2, 2, 2}, ScalarType::UInt8);
  EXPECT_FLOAT_EQ(vol.at(1, 1, 1), 255);
  EXPECT_FLOAT_EQ(vol.at(0, 1, 0), 2);
}

// uint8, uint16 and int16 stay in their type (1 or 2 bytes a sample); the
// others become float.
TEST(RawVolume, KeepsTheFilesTypeWhereItCan) {
  test::TempDir dir;
  test::write_bytes(dir / "e.raw", std::vector<unsigned char>(32, 1));
  const std::pair<ScalarType, ScalarType> kept[] = {{ScalarType::UInt8, ScalarType::UInt8},
                                                    {ScalarType::UInt16, ScalarType::UInt16},
                                                    {ScalarType::Int16, ScalarType::Int16},
                                                    {ScalarType::Float32, ScalarType::Float32},
                                                    {ScalarType::Int32, ScalarType::Float32}};
  for (const auto& [file, stored] : kept) {
    const std::int64_t n = static_cast<std::int64_t>(32 / scalar_type_size(file));
    const auto vol = read_raw_volume(dir / "e.raw", {2, 2, n / 4}, file);
    EXPECT_EQ(vol.type(), stored) << scalar_type_name(file);
    EXPECT_EQ(vol.bytes(), std::size_t(n) * scalar_type_size(stored)) << scalar_type_name(file);
  }
  EXPECT_EQ(read_raw_volume(dir / "e.raw", {2, 2, 4}, ScalarType::UInt16).value(7), 257);
  EXPECT_EQ(read_raw_volume(dir / "e.raw", {2, 2, 2}, ScalarType::Int32).value(7), 0x01010101);
}

TEST(RawVolume, BundledNeghipHasItsKnownChecksum) {
  const auto vol = read_raw_volume(test::source_path("data/neghip_64x64x64_uint8.raw"), {64, 64, 64}, ScalarType::UInt8);
  double sum = 0;
  for (float v : test::floats(vol)) sum += v;
  EXPECT_EQ(sum, 4824177.0);  // numpy: fromfile(...).sum()
}

TEST(RawVolume, RefusesWrongSizesAndMissingFiles) {
  test::TempDir dir;
  test::write_bytes(dir / "short.raw", std::vector<unsigned char>(7));
  test::write_bytes(dir / "long.raw", std::vector<unsigned char>(9));
  EXPECT_THROW(read_raw_volume(dir / "short.raw", {2, 2, 2}, ScalarType::UInt8), Error);
  EXPECT_THROW(read_raw_volume(dir / "long.raw", {2, 2, 2}, ScalarType::UInt8), Error);
  EXPECT_THROW(read_raw_volume(dir / "long.raw", {2, 2, 2}, ScalarType::UInt16), Error);
  EXPECT_THROW(read_raw_volume(dir / "none.raw", {2, 2, 2}, ScalarType::UInt8), Error);
  EXPECT_THROW(read_raw_volume(dir / "long.raw", {1 << 20, 1 << 20, 1 << 20}, ScalarType::UInt8), Error);
  EXPECT_THROW(parse_scalar_type("uint12"), Error);
  try {
    read_raw_volume(dir / "short.raw", {2, 2, 2}, ScalarType::UInt8);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("7 bytes"), std::string::npos) << e.what();
  }
}

// Issue 17 defect 1: dims whose product wraps 64 bits matched an empty file.
TEST(RawVolume, RefusesDimsWhoseProductOverflows) {
  test::TempDir dir;
  test::write_text(dir / "empty.raw", "");
  const std::int64_t big = std::int64_t{1} << 24;
  EXPECT_THROW(read_raw_volume(dir / "empty.raw", {big, big, big}, ScalarType::UInt8), Error);
  EXPECT_THROW(read_raw_volume(dir / "empty.raw", {big, big, std::int64_t{1} << 16}, ScalarType::UInt8), Error);
}

}  // namespace
}  // namespace vri
