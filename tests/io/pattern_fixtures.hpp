#pragma once
// The MetaImage, .npy and NRRD fixtures of tests/data/volume/ (mhd_*, npy_*,
// nrrd_*), written independently of vri by tools/make_mhd_npy_fixtures.py:
// each holds scale * p + shift of one 11 x 7 x 5 pattern p, which lies
// headerless (x fastest) in mhd_npy_nrrd_pattern_uint8.raw.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/io.hpp"
#include "vri/volume.hpp"

namespace vri::test {

struct PatternFixture {
  const char* name;
  double scale, shift;
  ScalarType stored;    // the type the reader keeps the samples in
  bool parity = false;  // a bool array: p mod 2
};

inline std::filesystem::path volume_fixture(const std::string& name) {
  return source_path("tests/data/volume/" + name);
}

inline std::string pattern_raw() { return "mhd_npy_nrrd_pattern_uint8.raw"; }

// The dims, the storage type and every sample, exactly; then spacing and origin.
inline void expect_pattern(const GridVolume& v, const PatternFixture& f, Vec3 spacing = {1, 1, 1},
                           Vec3 origin = {0, 0, 0}) {
  SCOPED_TRACE(f.name);
  const auto p = read_file(volume_fixture(pattern_raw()));
  EXPECT_EQ(v.dims(), (std::array<int, 3>{11, 7, 5}));
  EXPECT_EQ(scalar_type_name(v.type()), scalar_type_name(f.stored));
  ASSERT_EQ(v.size(), p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double s = std::to_integer<int>(p[i]);
    const auto want = static_cast<float>(f.parity ? std::fmod(s, 2) : f.scale * s + f.shift);
    if (v.value(i) != want) {
      ADD_FAILURE() << "sample " << i << " is " << v.value(i) << ", expected " << want;
      break;
    }
  }
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(v.spacing()[a], spacing[a]) << "axis " << a;
    EXPECT_DOUBLE_EQ(v.origin()[a], origin[a]) << "axis " << a;
  }
}

// The message of the vri::Error `f` throws ("no error" if none): one line
// holding `fragment`.
template <class F>
std::string expect_error(F&& f, const std::string& fragment) {
  std::string message = "no error";
  try {
    f();
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_NE(message.find(fragment), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  return message;
}

}  // namespace vri::test
