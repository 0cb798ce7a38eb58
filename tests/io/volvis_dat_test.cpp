#include "io/volvis_dat.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vri/error.hpp"

namespace vri {
namespace {

TEST(VolvisDat, RoundTripAndLayout) {
  test::TempDir dir;
  const auto vol = test::volume_from({3, 2, 2}, [](double x, double y, double z) { return x + 10 * y + 100 * z + 4000; });
  write_volvis_dat(dir / "v.dat", vol);
  const auto back = read_volvis_dat(dir / "v.dat");
  EXPECT_EQ(test::floats(back), test::floats(vol));
  EXPECT_EQ(std::filesystem::file_size(dir / "v.dat"), 6u + 2 * 12);
  // a hand-made file: dims 2 2 2 then 8 little-endian values
  std::vector<unsigned char> b{2, 0, 2, 0, 2, 0};
  for (int i = 0; i < 8; ++i) {
    b.push_back(static_cast<unsigned char>(i));
    b.push_back(0x10);
  }
  test::write_bytes(dir / "h.dat", b);
  const GridVolume h = read_volvis_dat(dir / "h.dat");
  EXPECT_EQ(h.type(), ScalarType::UInt16);
  EXPECT_EQ(h.bytes(), 16u);
  EXPECT_FLOAT_EQ(h.at(1, 0, 1), 0x1000 + 5);
}

TEST(VolvisDat, RefusesWrongSizes) {
  test::TempDir dir;
  test::write_bytes(dir / "short.dat", {2, 0, 2, 0, 2, 0, 1, 2, 3});
  EXPECT_THROW(read_volvis_dat(dir / "short.dat"), Error);
  test::write_bytes(dir / "tiny.dat", {2, 0});
  EXPECT_THROW(read_volvis_dat(dir / "tiny.dat"), Error);
  test::write_bytes(dir / "one.dat", {1, 0, 2, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_THROW(read_volvis_dat(dir / "one.dat"), Error);
}

}  // namespace
}  // namespace vri
