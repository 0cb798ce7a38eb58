#pragma once
// Shared by the .vti and legacy STRUCTURED_POINTS tests: the fixtures VTK
// wrote (tests/data/volume/, tools/make_vtk_volume_fixtures.py), the
// reference volumes (the same samples as headerless raw files, loaded
// through their scene "volume" blocks) and an exact comparison. In a
// namespace of their own: test_io links other tests' fixture helpers.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <string>

#include "io/mesh_io_test_support.hpp"
#include "test_support.hpp"
#include "vri/scene.hpp"

namespace vri::test::vtk_fixtures {

inline std::string volume_fixture(const std::string& name) { return source_path("tests/data/volume/" + name); }

inline std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A scene over the fixtures' world box (x 1..6, y -2..5.5, z 3..11) without
// its "volume"; `tf_max` is the top of the transfer function's range.
inline std::string volume_scene_rest(double tf_max, double tf_min = 0) {
  const std::string lo = std::to_string(tf_min), hi = std::to_string(tf_max), mid = std::to_string((tf_min + tf_max) / 2);
  return R"("transfer_function": {"points": [[)" + lo + R"(, 1, 0, 0, 0], [)" + mid + R"(, 0, 1, 0, 0.3], [)" + hi +
         R"(, 0, 0, 1, 0.8]]},
    "camera": {"eye": [20, 14, 30], "target": [3.5, 1.75, 7], "width": 24, "height": 18},
    "method": {"name": "riemann", "step": 0.5})";
}

// The scene "volume" block of the raw reference of "scalars" (uint8) or "height" (float64).
inline std::string raw_volume_block(const std::string& array) {
  return file_text(volume_fixture(array == "scalars" ? "vtk_scalars_uint8.json" : "vtk_height_float64.json"));
}

// The raw reference volume of "scalars" or "height", read by the raw reader.
inline GridVolume reference_volume(const std::string& array) {
  const Scene s = parse_scene("{\"volume\": " + raw_volume_block(array) + ", " + volume_scene_rest(1) + "}",
                              volume_fixture(""));
  return s.grid();
}

// Same dims, storage type, spacing, origin and samples, exactly.
inline void expect_same_volume(const GridVolume& got, const GridVolume& want, const std::string& what) {
  EXPECT_EQ(got.dims(), want.dims()) << what;
  EXPECT_EQ(got.type(), want.type()) << what;
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(got.spacing()[a], want.spacing()[a]) << what << " axis " << a;
    EXPECT_EQ(got.origin()[a], want.origin()[a]) << what << " axis " << a;
  }
  EXPECT_EQ(floats(got), floats(want)) << what;
}

}  // namespace vri::test::vtk_fixtures
