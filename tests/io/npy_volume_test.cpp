// Volumes from .npy (SPEC §11: [z, y, x], x fastest) against files numpy.save
// wrote (tools/make_mhd_npy_fixtures.py): every numeric dtype, both byte
// orders, C and Fortran order, format versions 1.0 to 3.0; and the refusals.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "io/pattern_fixtures.hpp"
#include "vri/io.hpp"

namespace vri {
namespace {

using test::PatternFixture;

constexpr double k2p33 = 8589934592.0, k2p40 = 1099511627776.0;

const PatternFixture kFixtures[] = {
    {"npy_u1.npy", 1, 0, ScalarType::UInt8},
    {"npy_u1_fortran.npy", 1, 0, ScalarType::UInt8},
    {"npy_b1.npy", 1, 0, ScalarType::UInt8, true},
    {"npy_i1.npy", 1, -48, ScalarType::Float32},
    {"npy_u2_le.npy", 300, 0, ScalarType::UInt16},
    {"npy_u2_be.npy", 300, 0, ScalarType::UInt16},
    {"npy_i2_le_fortran.npy", 100, -4800, ScalarType::Int16},
    {"npy_i2_be.npy", 100, -4800, ScalarType::Int16},
    {"npy_i4_le.npy", 100000, -4800000, ScalarType::Float32},
    {"npy_i4_be.npy", 100000, -4800000, ScalarType::Float32},
    {"npy_u4_be.npy", 100000, 0, ScalarType::Float32},
    {"npy_i8_be.npy", k2p33, -48 * k2p33, ScalarType::Float32},
    {"npy_u8_le.npy", k2p40, 0, ScalarType::Float32},
    {"npy_f2_le.npy", 0.5, -10, ScalarType::Float32},
    {"npy_f4_le.npy", 0.5, -10, ScalarType::Float32},
    {"npy_f4_be_fortran.npy", 0.5, -10, ScalarType::Float32},
    {"npy_f8_le.npy", 0.25, -3, ScalarType::Float32},
    {"npy_f8_be.npy", 0.25, -3, ScalarType::Float32},
    {"npy_v2.npy", 0.5, -10, ScalarType::Float32},
    {"npy_v3.npy", 300, 0, ScalarType::UInt16},
};

TEST(NpyVolume, FixturesReadBackToThePattern) {
  for (const auto& f : kFixtures) {
    test::expect_pattern(read_npy_volume(test::volume_fixture(f.name)), f);
    test::expect_pattern(parse_npy_volume(read_file(test::volume_fixture(f.name)), f.name), f);
  }
}

TEST(NpyVolume, RefusesWhatIsNotANumericVolume) {
  const std::pair<const char*, const char*> refused[] = {
      {"npy_err_complex.npy", "dtype '<c8' (complex numbers) is not supported"},
      {"npy_err_structured.npy", "structured dtype"},
      {"npy_err_object.npy", "dtype '|O' (Python objects) is not supported"},
      {"npy_err_string.npy", "dtype '<U2' (strings) is not supported"},
      {"npy_err_2d.npy", "the array's shape (7, 11) is 2-D; a volume needs a 3-D array indexed [z, y, x]"},
      {"npy_err_4d.npy", "the array's shape (1, 5, 7, 11) is 4-D"},
  };
  for (const auto& [name, fragment] : refused) {
    const auto path = test::volume_fixture(name);
    const std::string m = test::expect_error([&] { read_npy_volume(path); }, fragment);
    EXPECT_NE(m.find("NumPy '" + path.string() + "'"), std::string::npos) << m;
    test::expect_error([&] { parse_npy_volume(read_file(path), name); }, fragment);
  }
}

// A version 1.0 file with `dict` as its header and `data` after it.
std::vector<std::byte> npy(std::string dict, std::size_t data_bytes, int major = 1) {
  dict.append((64 - (10 + dict.size() + 1) % 64) % 64, ' ');
  dict += '\n';
  std::vector<std::byte> out(10 + dict.size() + data_bytes, std::byte{0x11});
  std::memcpy(out.data(), "\x93NUMPY", 6);
  out[6] = std::byte(major);
  out[7] = std::byte{0};
  out[8] = std::byte(dict.size() & 0xff);
  out[9] = std::byte(dict.size() >> 8);
  std::memcpy(out.data() + 10, dict.data(), dict.size());
  return out;
}

std::string dict(const std::string& descr, const std::string& shape, const std::string& fortran = "False") {
  return "{'descr': '" + descr + "', 'fortran_order': " + fortran + ", 'shape': " + shape + ", }";
}

TEST(NpyVolume, RefusesBrokenAndHostileHeaders) {
  const auto refuse = [](const std::vector<std::byte>& bytes, const std::string& fragment) {
    const std::string m = test::expect_error([&] { parse_npy_volume(bytes, "h.npy"); }, fragment);
    EXPECT_NE(m.find("NumPy 'h.npy'"), std::string::npos) << m;
  };
  EXPECT_EQ(parse_npy_volume(npy(dict("|u1", "(2, 3, 4)"), 24), "ok.npy").dims(), (std::array<int, 3>{4, 3, 2}));
  // Truncated data, and one byte too many.
  refuse(npy(dict("<u2", "(2, 3, 4)"), 47), "holds 47 data bytes; its shape (2, 3, 4) and dtype '<u2' need 48");
  refuse(npy(dict("<u2", "(2, 3, 4)"), 49), "holds 49 data bytes");
  // 2^40 samples, and 2^30 floats over 16 bytes: refused before allocating.
  refuse(npy(dict("<f4", "(16384, 8192, 8192)"), 16), "exceeds the limit");
  refuse(npy(dict("<f4", "(1024, 1024, 1024)"), 16), "need 4294967296");
  refuse(npy(dict("<f4", "(99999999999999999999999, 2, 2)"), 16), "bad dimension");
  refuse(npy(dict("<f4", "(1, 2, 2)"), 16), "dims must each be at least 2");
  // dtypes
  refuse(npy(dict("<c16", "(2, 2, 2)"), 128), "dtype '<c16' (complex numbers)");
  refuse(npy(dict("<M8[ns]", "(2, 2, 2)"), 64), "(dates or times)");
  refuse(npy(dict("|V4", "(2, 2, 2)"), 32), "(raw records)");
  refuse(npy(dict("<f16", "(2, 2, 2)"), 128), "(an unknown type)");
  refuse(npy(dict("f4", "(2, 2, 2)"), 32), "dtype 'f4'");
  refuse(npy("{'descr': [('a', '<f4')], 'fortran_order': False, 'shape': (2, 2, 2), }", 32), "structured dtype");
  // the header itself
  refuse(npy(dict("<f4", "(2, 2, 2)", "Maybe"), 32), "fortran_order is Maybe");
  refuse(npy("{'descr': '<f4', 'shape': (2, 2, 2), }", 32), "lacks 'fortran_order'");
  refuse(npy("{'descr': '<f4', 'fortran_order': False, 'shape': (2, 2, 2)", 32), "malformed .npy header");
  refuse(npy(dict("<f4", "(2, 2, 2)"), 32, 4), "unsupported .npy version 4.0");
  auto long_header = npy(dict("<f4", "(2, 2, 2)"), 0);
  long_header[8] = long_header[9] = std::byte{0xff};
  refuse(long_header, "truncated inside its .npy header");
  refuse(std::vector<std::byte>(5, std::byte{0x93}), "is not a .npy file");
  test::expect_error([] { read_npy_volume(test::volume_fixture("absent.npy")); }, "absent.npy");
}

// Fortran order: the first index ([z]) fastest in the file.
TEST(NpyVolume, FortranOrderIsTransposed) {
  auto bytes = npy(dict("|u1", "(2, 3, 4)", "True"), 24);
  for (int i = 0; i < 24; ++i) bytes[bytes.size() - 24 + i] = std::byte(i);
  const GridVolume v = parse_npy_volume(bytes, "f.npy");
  ASSERT_EQ(v.dims(), (std::array<int, 3>{4, 3, 2}));
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 3; ++y)
      for (int z = 0; z < 2; ++z) EXPECT_EQ(v.at(x, y, z), z + 2 * (y + 3 * x)) << x << y << z;
}

}  // namespace
}  // namespace vri
