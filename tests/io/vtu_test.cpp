#include "io/vtu.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "io/mesh_io_test_support.hpp"
#include "test_support.hpp"
#include "io/vtk_legacy.hpp"

namespace vri {
namespace {

// Every .vtu flavour VTK 9.1 writes (tools/make_mesh_fixtures.py) reads back
// as the bundled legacy mesh it was made from.
TEST(Vtu, EveryEncodingReadsBackIdentically) {
  const TetMesh ref = read_vtk_legacy(test::source_path("data/tetra_mesh_small_ascii.vtk"));
  for (const char* name : {"ascii.vtu", "base64.vtu", "base64_zlib_uint64.vtu", "appended_raw.vtu",
                           "appended_raw_zlib.vtu", "appended_base64_zlib_uint64.vtu"}) {
    const auto path = test::source_path(std::string("tests/data/mesh/") + name);
    const TetMesh m = read_vtu(path);
    ASSERT_EQ(m.size(), ref.size()) << name;
    EXPECT_EQ(m.tets(), ref.tets()) << name;
    EXPECT_EQ(m.scalars(), ref.scalars()) << name;
    for (std::size_t i = 0; i < m.points().size(); ++i)
      EXPECT_FLOAT_EQ(float(m.points()[i].x), float(ref.points()[i].x)) << name;
    const TetMesh h = read_vtu(path, "height");
    for (std::size_t i = 0; i < h.points().size(); ++i) EXPECT_FLOAT_EQ(h.scalars()[i], float(h.points()[i].z)) << name;
  }
}

std::string vtu(const std::string& attrs, const std::string& types, const std::string& scalars) {
  return R"(<?xml version="1.0"?><VTKFile type="UnstructuredGrid" )" + attrs + R"(>
<UnstructuredGrid><Piece NumberOfPoints="4" NumberOfCells="1">
<PointData><DataArray type="Float32" Name="s" format="ascii">)" + scalars + R"(</DataArray></PointData>
<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>
<Cells><DataArray type="Int32" Name="connectivity" format="ascii">0 1 2 3</DataArray>
<DataArray type="Int32" Name="offsets" format="ascii">4</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">)" + types + R"(</DataArray></Cells>
</Piece></UnstructuredGrid></VTKFile>)";
}

TEST(Vtu, RefusesBadFilesWithOneLine) {
  auto parse = [](const std::string& text, const std::string& scalars = "") {
    return [=] { parse_vtu(test::bytes_of(text), scalars, "m.vtu"); };
  };
  EXPECT_EQ(parse_vtu(test::bytes_of(vtu("", "10", "0 1 2 3")), "", "m.vtu").size(), 1u);
  test::expect_mesh_error(parse(vtu("", "12", "0 1 2 3")), "m.vtu: cell 0 has VTK type 12");
  test::expect_mesh_error(parse(vtu("", "10", "0 1 nan 3")), "non-finite scalar");
  test::expect_mesh_error(parse(vtu("", "10", "0 1")), "fewer than 4 values");
  test::expect_mesh_error(parse(vtu("", "10", "0 1 2 3"), "t"), "no point scalars named 't' (the file has: s)");
  test::expect_mesh_error(parse(vtu(R"(compressor="vtkLZMADataCompressor")", "10", "0 1 2 3")),
                          "unsupported compressor 'vtkLZMADataCompressor' (vtkZLibDataCompressor and vtkLZ4DataCompressor are read)");
  test::expect_mesh_error(parse(R"(<VTKFile type="ImageData">)"), "only UnstructuredGrid");
  test::expect_mesh_error(parse("<VTKFile type=\"UnstructuredGrid\"><Piece NumberOfPoints=\"4\""), "unterminated");
}

// A .vtu whose Points are appended raw, zlib-compressed, behind the given
// UInt64 header words (blocks, block size, last block size, compressed sizes).
std::string appended_zlib_points(const std::vector<std::uint64_t>& header, const std::string& points = "4") {
  std::string raw;
  for (std::uint64_t w : header)
    for (int b = 0; b < 8; ++b) raw += char((w >> (8 * b)) & 0xff);
  raw += std::string(16, 'x');
  return R"(<VTKFile type="UnstructuredGrid" header_type="UInt64" compressor="vtkZLibDataCompressor">
<UnstructuredGrid><Piece NumberOfPoints=")" + points + R"(" NumberOfCells="1">
<PointData><DataArray type="Float32" Name="s" format="ascii">0 1 2 3</DataArray></PointData>
<Points><DataArray type="Float32" NumberOfComponents="3" format="appended" offset="0"/></Points>
<Cells><DataArray type="Int32" Name="connectivity" format="ascii">0 1 2 3</DataArray>
<DataArray type="Int32" Name="offsets" format="ascii">4</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">10</DataArray></Cells>
</Piece></UnstructuredGrid><AppendedData encoding="raw">_)" + raw + "</AppendedData></VTKFile>";
}

// Issue 17 defect 2: a compressed size near 2^64 wrapped the bounds check
// (heap over-read); header words near 2^64 went through an undefined
// double -> size_t cast; a huge declared point count was reserved up front.
TEST(Vtu, RefusesHeaderSizesThatWrap) {
  auto parse = [](const std::string& text) { return [=] { parse_vtu(test::bytes_of(text), "", "m.vtu"); }; };
  test::expect_mesh_error(parse(appended_zlib_points({1, 48, 48, ~std::uint64_t{0} - 7})), "compressed array is truncated");
  test::expect_mesh_error(parse(appended_zlib_points({~std::uint64_t{0}, 48, 48, 8})), "more than the data holds");
  test::expect_mesh_error(parse(appended_zlib_points({2, ~std::uint64_t{0}, 49, 8, 8})), "larger than its 48 bytes");
  test::expect_mesh_error(parse(appended_zlib_points({1, 48, 48, 8}, "18446744073709551615")), "too large");
  std::string many = vtu("", "10", "0 1 2 3");
  many.replace(many.find("NumberOfPoints=\"4\""), 18, "NumberOfPoints=\"6148914691236517205\"");
  test::expect_mesh_error(parse(many), "fewer than");
}

}  // namespace
}  // namespace vri
