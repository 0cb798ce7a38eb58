#include "io/vtk_legacy.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "io/mesh_io_test_support.hpp"
#include "test_support.hpp"

namespace vri {
namespace {

const TetMesh& small_mesh() {
  static const TetMesh m = read_vtk_legacy(test::source_path("data/tetra_mesh_small_ascii.vtk"));
  return m;
}

TEST(VtkLegacy, ReadsTheBundledAsciiMesh) {
  // v2.0 ASCII with LOOKUP_TABLE my_table and an empty CELL_DATA section.
  const TetMesh& m = small_mesh();
  EXPECT_EQ(m.points().size(), 55u);
  EXPECT_EQ(m.size(), 160u);
  EXPECT_EQ(m.dropped(), 0u);
  EXPECT_EQ(std::accumulate(m.scalars().begin(), m.scalars().end(), 0.0), 168.0);
  EXPECT_FLOAT_EQ(m.points()[0].x, 9.78032f);
  EXPECT_FLOAT_EQ(m.points()[54].z, -4.90854f);
  EXPECT_EQ(m.min_value(), 0);
  EXPECT_EQ(m.max_value(), 4);
}

// The same mesh rewritten by VTK 9.1 (tools/make_mesh_fixtures.py) in other
// legacy flavours reads back identically; 'height' is a FIELD array there.
TEST(VtkLegacy, VtkWrittenFlavoursReadBackIdentically) {
  for (const char* name : {"legacy42_binary.vtk", "legacy51_binary.vtk", "legacy51_ascii.vtk"}) {
    const TetMesh m = read_vtk_legacy(test::source_path(std::string("tests/data/mesh/") + name));
    ASSERT_EQ(m.size(), small_mesh().size()) << name;
    EXPECT_EQ(m.tets(), small_mesh().tets()) << name;
    EXPECT_EQ(m.scalars(), small_mesh().scalars()) << name;
    for (std::size_t i = 0; i < m.points().size(); ++i)
      EXPECT_FLOAT_EQ(float(m.points()[i].y), float(small_mesh().points()[i].y)) << name;
    const TetMesh h = read_vtk_legacy(test::source_path(std::string("tests/data/mesh/") + name), "height");
    for (std::size_t i = 0; i < h.points().size(); ++i) EXPECT_FLOAT_EQ(h.scalars()[i], float(h.points()[i].z)) << name;
  }
}

TEST(VtkLegacy, ReadsTheBundledBinaryCfdMesh) {
  const TetMesh m = read_vtk_legacy(test::source_path("data/blunt_fin_tet.vtk"), "momentum_magnitude");
  EXPECT_EQ(m.points().size(), 40921u);
  EXPECT_EQ(m.size(), 187318u);
  EXPECT_NEAR(m.max_value(), 6.2557, 1e-4);
  EXPECT_NEAR(m.box_lo().x, -7.82, 0.01);
  EXPECT_NEAR(m.box_hi().y, 8.33, 0.01);
  std::size_t boundary = 0;
  for (std::size_t t = 0; t < m.size(); ++t)
    for (int f = 0; f < 4; ++f) boundary += m.neighbor(t, f) < 0;
  EXPECT_EQ(boundary, 13438u);  // MANIFEST.md §2
}

const std::string kHead = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n"
                          "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\n";

TEST(VtkLegacy, RefusesBadMeshesWithOneLine) {
  auto parse = [](const std::string& text, const std::string& scalars = "") {
    return [=] { parse_vtk_legacy(test::bytes_of(text), scalars, "m.vtk"); };
  };
  const std::string tet = "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
  const std::string data = "POINT_DATA 4\nSCALARS s float 1\nLOOKUP_TABLE default\n0 1 2 3\n";
  EXPECT_NO_THROW(parse(kHead + tet + data)());
  test::expect_mesh_error(parse("hello"), "m.vtk: not a VTK legacy file");
  test::expect_mesh_error(parse(kHead + "CELLS 1 9\n8 0 1 2 3 0 1 2 3\nCELL_TYPES 1\n12\n" + data),
                          "cell 0 has VTK type 12; only tetrahedra");
  test::expect_mesh_error(parse(kHead + "CELLS 1 5\n4 0 1 2 7\nCELL_TYPES 1\n10\n" + data), "refers to point 7");
  test::expect_mesh_error(parse(kHead + tet + "POINT_DATA 4\nSCALARS s float 1\nLOOKUP_TABLE default\n0 nan 2 3\n"),
                          "point 1 has a non-finite scalar");
  test::expect_mesh_error(parse(kHead + tet + data, "density"), "no point scalars named 'density' (the file has: s)");
  test::expect_mesh_error(parse(kHead + tet + "POINT_DATA 4\nSCALARS s float 1\nLOOKUP_TABLE default\n0 1\n"),
                          "data ends early");
  test::expect_mesh_error(parse(kHead + tet), "no one-component point scalars");
  test::expect_mesh_error(parse("# vtk DataFile Version 3.0\nt\nASCII\nDATASET STRUCTURED_POINTS\n"),
                          "only UNSTRUCTURED_GRID");
  test::expect_mesh_error(parse(kHead + "CELLS 1 5\n4 0 1 2 -3\nCELL_TYPES 1\n10\n" + data), "not a valid index");
  // Binary data cut short.
  std::string bin = "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n";
  bin += std::string(20, '\0');
  test::expect_mesh_error(parse(bin), "binary data ends early");
}

// Issue 17 defect 3: a file ending right after "FIELD fd 1" read a word of an
// empty line (SIGSEGV).
TEST(VtkLegacy, RefusesAFileEndingInsideFIELD) {
  auto parse = [](const std::string& text) { return [=] { parse_vtk_legacy(test::bytes_of(text), "", "m.vtk"); }; };
  test::expect_mesh_error(parse(kHead + "FIELD fd 1"), "the file ends where a line was expected");
  test::expect_mesh_error(parse(kHead + "FIELD fd 1\n"), "the file ends where a line was expected");
  test::expect_mesh_error(parse(kHead + "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES"), "incomplete 'CELL_TYPES' line");
}

// Issue 17 defect 9: declared counts are checked against the bytes present
// before anything is allocated (2.5e8 points in a few bytes took 5.7 GB), and
// products of counts cannot wrap.
TEST(VtkLegacy, RefusesCountsTheFileCannotHold) {
  auto parse = [](const std::string& text) { return [=] { parse_vtk_legacy(test::bytes_of(text), "", "m.vtk"); }; };
  const std::string head = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  test::expect_mesh_error(parse(head + "POINTS 250000000 float\n0 0 0 1 0 0\n"), "750000000 values declared, 12 bytes left");
  test::expect_mesh_error(parse(kHead + "POINT_DATA 4\nFIELD fd 1\nf 1099511627776 1099511627776 float\n0\n"),
                          "too large");
  std::string bin = "# vtk DataFile Version 3.0\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 250000000 float\n";
  bin += std::string(24, '\0');
  test::expect_mesh_error(parse(bin), "binary data ends early");
}

}  // namespace
}  // namespace vri
