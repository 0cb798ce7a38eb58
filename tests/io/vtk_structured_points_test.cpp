// The legacy VTK STRUCTURED_POINTS reader (io/vtk_legacy.hpp): the files
// VTK 9 writes (tests/data/volume/, tools/make_vtk_volume_fixtures.py: the
// active uint8 array as COLOR_SCALARS, the other as a FIELD array; or
// SCALARS double) read back as the raw file holding the same samples; every
// numeric type; hostile files refused with one line.
#include <gtest/gtest.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "io/vtk_volume_test_support.hpp"
#include "io/vtk_legacy.hpp"

namespace vri {
namespace {

namespace fx = test::vtk_fixtures;

TEST(VtkStructuredPoints, EveryFixtureReadsBackTheRawData) {
  const GridVolume scalars = fx::reference_volume("scalars"), height = fx::reference_volume("height");
  for (const char* name : {"legacy_ascii.vtk", "legacy_binary.vtk", "legacy42_binary.vtk"}) {
    const auto path = fx::volume_fixture(name);
    fx::expect_same_volume(read_vtk_structured_points(path), scalars, name);  // COLOR_SCALARS, the first
    fx::expect_same_volume(read_vtk_structured_points(path, "height"), height, std::string(name) + " height");
  }
  for (const char* name : {"legacy_height_ascii.vtk", "legacy_height_binary.vtk"}) {
    const auto path = fx::volume_fixture(name);
    fx::expect_same_volume(read_vtk_structured_points(path), height, name);  // SCALARS height double
    fx::expect_same_volume(read_vtk_structured_points(path, "scalars"), scalars, std::string(name) + " scalars");
  }
}

TEST(VtkStructuredPoints, TellsGridsFromMeshes) {
  auto head = [](const std::string& path) {
    const std::string text = fx::file_text(path);
    return vtk_legacy_is_structured_points(test::bytes_of(text));
  };
  EXPECT_TRUE(head(fx::volume_fixture("legacy_binary.vtk")));
  EXPECT_TRUE(head(fx::volume_fixture("legacy_height_ascii.vtk")));
  EXPECT_FALSE(head(test::source_path("tests/data/mesh/legacy51_binary.vtk")));
  EXPECT_FALSE(head(test::source_path("data/tetra_mesh_small_ascii.vtk")));
  EXPECT_FALSE(head(fx::volume_fixture("ascii.vti")));
  EXPECT_FALSE(vtk_legacy_is_structured_points(test::bytes_of("# vtk DataFile Version 3.0\n")));
  const std::string far = "# vtk DataFile Version 3.0\n" + std::string(1100, 't') + "\nASCII\nDATASET STRUCTURED_POINTS\n";
  EXPECT_FALSE(vtk_legacy_is_structured_points(test::bytes_of(far)));  // beyond the first 1 KiB
}

const std::string kHead = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 2\n";

// Big-endian packed values of a legacy type name.
std::string big_endian(const std::string& type, const std::vector<double>& values) {
  std::string out;
  auto put = [&](auto x) {
    const char* p = reinterpret_cast<const char*>(&x);
    for (std::size_t b = sizeof x; b-- > 0;) out += p[b];
  };
  for (double v : values) {
    if (type == "char") put(std::int8_t(v));
    else if (type == "unsigned_char") put(std::uint8_t(v));
    else if (type == "short") put(std::int16_t(v));
    else if (type == "unsigned_short") put(std::uint16_t(v));
    else if (type == "int") put(std::int32_t(v));
    else if (type == "unsigned_int") put(std::uint32_t(v));
    else if (type == "vtktypeint64") put(std::int64_t(v));
    else if (type == "vtktypeuint64") put(std::uint64_t(v));
    else if (type == "float") put(float(v));
    else put(v);
  }
  return out;
}

TEST(VtkStructuredPoints, ReadsEveryNumericTypeAndTheHeaderLines) {
  const std::pair<const char*, ScalarType> types[] = {
      {"char", ScalarType::Float32},          {"unsigned_char", ScalarType::UInt8},    {"short", ScalarType::Int16},
      {"unsigned_short", ScalarType::UInt16}, {"int", ScalarType::Float32},            {"unsigned_int", ScalarType::Float32},
      {"vtktypeint64", ScalarType::Float32},  {"vtktypeuint64", ScalarType::Float32},  {"float", ScalarType::Float32},
      {"double", ScalarType::Float32}};
  for (const auto& [type, stored] : types) {
    const std::string t = type;
    std::vector<double> values{0, 1, 2, 3, 4, 5, 6, 100};
    if (t.rfind("unsigned", 0) != 0 && t != "vtktypeuint64") values[0] = -7;
    if (t == "float" || t == "double") values[1] = 0.25;
    std::ostringstream text;
    for (double v : values) text << v << ' ';
    const std::string scalars = "POINT_DATA 8\nSCALARS s " + t + " 1\nLOOKUP_TABLE default\n";
    std::string binary = kHead + scalars + big_endian(t, values) + "\n";
    binary.replace(binary.find("ASCII"), 5, "BINARY");
    for (const std::string& file : {kHead + scalars + text.str() + "\n", binary}) {
      const GridVolume v = parse_vtk_structured_points(test::bytes_of(file), "", "t.vtk");
      EXPECT_EQ(v.type(), stored) << t;
      EXPECT_EQ(test::floats(v), std::vector<float>(values.begin(), values.end())) << t;
    }
  }
  // ASPECT_RATIO (the older SPACING), ORIGIN, METADATA blocks and other sections skipped.
  const GridVolume v = parse_vtk_structured_points(
      test::bytes_of(kHead + "ASPECT_RATIO 2 3 0.5\nORIGIN -1 0 2.5\nCELL_DATA 1\nSCALARS c int\nLOOKUP_TABLE default\n7\n"
                             "POINT_DATA 8\nVECTORS v float\n0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n"
                             "METADATA\nINFORMATION 0\n\nFIELD FieldData 2\na 1 8 float\n0 0 0 0 0 0 0 0\n"
                             "METADATA\nCOMPONENT_NAMES\nx\n\nb 1 8 unsigned_short\n1 2 3 4 5 6 7 8\n"),
      "b", "t.vtk");
  EXPECT_EQ(v.spacing().x, 2);
  EXPECT_EQ(v.spacing().y, 3);
  EXPECT_EQ(v.spacing().z, 0.5);
  EXPECT_EQ(v.origin().x, -1);
  EXPECT_EQ(v.origin().z, 2.5);
  EXPECT_EQ(v.type(), ScalarType::UInt16);
  EXPECT_EQ(v.max_value(), 8);
}

TEST(VtkStructuredPoints, RefusesBadFilesWithOneLine) {
  auto parse = [](const std::string& text, const std::string& scalars = "") {
    return [=] { parse_vtk_structured_points(test::bytes_of(text), scalars, "t.vtk"); };
  };
  const std::string data = "POINT_DATA 8\nSCALARS s float\nLOOKUP_TABLE default\n0 1 2 3 4 5 6 7\n";
  EXPECT_EQ(parse_vtk_structured_points(test::bytes_of(kHead + data), "", "t.vtk").max_value(), 7);
  test::expect_mesh_error(parse("hello"), "t.vtk: not a VTK legacy file");
  test::expect_mesh_error(parse("# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n"),
                          "dataset is UNSTRUCTURED_GRID, not STRUCTURED_POINTS");
  test::expect_mesh_error(parse("# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\n" + data), "POINT_DATA has 8 values for 0 points");
  test::expect_mesh_error(parse("# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\n"), "no DIMENSIONS");
  // 2^40 samples: refused when DIMENSIONS is read, before anything else.
  test::expect_mesh_error(parse("# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 16384 8192 8192\n"),
                          "exceeds the limit");
  test::expect_mesh_error(parse(kHead + "SPACING 1 1\n"), "incomplete 'SPACING' line");
  test::expect_mesh_error(parse(kHead + "ORIGIN 0 x 0\n"), "bad number 'x' in ORIGIN");
  test::expect_mesh_error(parse(kHead + "SPACING 1 -1 1\n" + data), "spacing must be positive");
  test::expect_mesh_error(parse(kHead + "POINT_DATA 8\nSCALARS s complex\nLOOKUP_TABLE default\n0\n"),
                          "unsupported data type 'complex'");
  test::expect_mesh_error(parse(kHead + "POINT_DATA 8\nSCALARS s float\nLOOKUP_TABLE default\n0 1 2\n"), "data ends early");
  test::expect_mesh_error(parse(kHead + "POINT_DATA 8\nSCALARS s unsigned_char\nLOOKUP_TABLE default\n0 1 2 3 4 5 6 -1\n"),
                          "value '-1' is not a valid UInt8");
  std::string v3 = "POINT_DATA 8\nSCALARS v float 3\nLOOKUP_TABLE default\n";
  for (int i = 0; i < 24; ++i) v3 += "0 ";
  test::expect_mesh_error(parse(kHead + v3, "v"), "point array 'v' has 3 components");
  test::expect_mesh_error(parse(kHead + v3), "no one-component point scalars (the file has: v [3 components])");
  test::expect_mesh_error(parse(kHead + data, "rho"), "no point scalars named 'rho' (the file has: s)");
  // Binary data cut short, and every fixture cut anywhere.
  std::string bin = "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET STRUCTURED_POINTS\nDIMENSIONS 2 2 2\n"
                    "POINT_DATA 8\nSCALARS s double\nLOOKUP_TABLE default\n" + std::string(60, '\0');
  test::expect_mesh_error(parse(bin), "binary data ends early");
  for (const char* name : {"legacy_ascii.vtk", "legacy_binary.vtk", "legacy_height_binary.vtk"}) {
    const std::string text = fx::file_text(fx::volume_fixture(name));
    for (double cut : {0.05, 0.3, 0.6, 0.9})
      test::expect_mesh_error(parse(text.substr(0, std::size_t(cut * double(text.size())))), "t.vtk: ");
  }
  // A mesh reader handed a grid says so.
  test::expect_mesh_error([] { read_vtk_legacy(fx::volume_fixture("legacy_binary.vtk")); }, "only UNSTRUCTURED_GRID");
}

}  // namespace
}  // namespace vri
