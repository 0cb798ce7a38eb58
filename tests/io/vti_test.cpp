// The VTK XML image data reader (io/vti.hpp): every flavour VTK 9 writes
// (tests/data/volume/, tools/make_vtk_volume_fixtures.py) reads back as the
// raw file holding the same samples; every numeric type; a flipped Direction;
// hostile files refused with one line before anything is allocated.
#include "io/vti.hpp"

#include <gtest/gtest.h>
#if !VRI_NO_LZ4_TEST
#include <lz4.h>
#endif

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include "io/vtk_volume_test_support.hpp"
#include "vri/memory.hpp"
#include "vri/render.hpp"

namespace vri {
namespace {

namespace fx = test::vtk_fixtures;

const char* const kFixtures[] = {
    "ascii.vti",          "base64.vti",          "base64_zlib.vti",
    "base64_zlib_uint64.vti", "base64_big_endian.vti", "appended_raw.vti",
    "appended_raw_zlib.vti",  "appended_raw_uint64_big_endian.vti", "appended_base64.vti",
    "appended_base64_zlib_uint64.vti", "extent_start.vti"};

TEST(Vti, EveryModeReadsBackTheRawData) {
  const GridVolume scalars = fx::reference_volume("scalars"), height = fx::reference_volume("height");
  EXPECT_EQ(scalars.type(), ScalarType::UInt8);
  for (const char* name : kFixtures) {
    const auto path = fx::volume_fixture(name);
    fx::expect_same_volume(read_vti(path), scalars, name);  // the active scalars
    fx::expect_same_volume(read_vti(path, "scalars"), scalars, name);
    fx::expect_same_volume(read_vti(path, "height"), height, std::string(name) + " height");
  }
}

// Direction -1 on x and z: index i lies at Origin.x - i * Spacing.x. The
// volume keeps positive spacing, covers the same world box, and holds at each
// world point the value VTK puts there.
TEST(Vti, FlipsAReversedDirection) {
  const GridVolume raw = fx::reference_volume("scalars");
  const GridVolume v = read_vti(fx::volume_fixture("direction_flip_xz.vti"));
  ASSERT_EQ(v.dims(), raw.dims());
  EXPECT_EQ(v.type(), ScalarType::UInt8);
  EXPECT_EQ(v.spacing().x, 0.5);
  EXPECT_EQ(v.spacing().z, 2);
  EXPECT_EQ(v.origin().x, 1 - 10 * 0.5);
  EXPECT_EQ(v.origin().y, -2);
  EXPECT_EQ(v.origin().z, 3 - 4 * 2);
  EXPECT_EQ(v.box_hi().x, 1);
  EXPECT_EQ(v.box_hi().z, 3);
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 11; ++i) {
        ASSERT_EQ(v.at(10 - i, j, 4 - k), raw.at(i, j, k)) << i << " " << j << " " << k;
        EXPECT_EQ(v.sample({1 - 0.5 * i, -2 + 1.25 * j, 3 - 2.0 * k}), raw.at(i, j, k));
      }
}

// Rendering the scene over the .vti gives the bytes of the scene over the raw file.
TEST(Vti, RendersTheSameBytesAsTheRawFile) {
  for (const auto& [array, lo, hi] : {std::tuple{"scalars", 0.0, 255.0}, std::tuple{"height", -2.5, 2.0}}) {
    const std::string rest = fx::volume_scene_rest(hi, lo);
    const Scene raw = parse_scene("{\"volume\": " + fx::raw_volume_block(array) + ", " + rest + "}",
                                  fx::volume_fixture(""));
    const Scene vti = parse_scene("{" + rest + "}", read_vti(fx::volume_fixture("appended_raw_zlib.vti"), array),
                                  fx::volume_fixture(""));
    const Image a = SceneRenderer(raw).render(), b = SceneRenderer(vti).render();
    EXPECT_EQ(test::pixels(a), test::pixels(b)) << array;
    float alpha = 0;
    for (std::size_t i = 3; i < a.data().size(); i += 4) alpha = std::max(alpha, a.data()[i]);
    EXPECT_GT(alpha, 0.05f) << array << ": the image shows the volume";
  }
}

std::string vti(const std::string& arrays, const std::string& extent = "0 1 0 1 0 1",
                const std::string& image = R"(Origin="0 0 0" Spacing="1 1 1")", const std::string& file = "",
                const std::string& appended = "") {
  return R"(<?xml version="1.0"?>
<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian" header_type="UInt32" )" + file + R"(>
<ImageData WholeExtent=")" + extent + "\" " + image + R"(>
<Piece Extent=")" + extent + R"("><PointData>)" + arrays + R"(</PointData></Piece></ImageData>
)" + (appended.empty() ? "" : "<AppendedData encoding=\"raw\">_" + appended + "</AppendedData>") + "</VTKFile>";
}

// Packed little-endian values of an XML type name (the test machines are little-endian).
std::string packed(const std::string& type, const std::vector<double>& values) {
  std::string out;
  auto put = [&](auto x) { out.append(reinterpret_cast<const char*>(&x), sizeof x); };
  for (double v : values) {
    if (type == "Int8") put(std::int8_t(v));
    else if (type == "UInt8") put(std::uint8_t(v));
    else if (type == "Int16") put(std::int16_t(v));
    else if (type == "UInt16") put(std::uint16_t(v));
    else if (type == "Int32") put(std::int32_t(v));
    else if (type == "UInt32") put(std::uint32_t(v));
    else if (type == "Int64") put(std::int64_t(v));
    else if (type == "UInt64") put(std::uint64_t(v));
    else if (type == "Float32") put(float(v));
    else put(v);
  }
  return out;
}

std::string header32(std::size_t n) { return packed("UInt32", {double(n)}); }

TEST(Vti, ReadsEveryNumericType) {
  const std::pair<const char*, ScalarType> types[] = {
      {"Int8", ScalarType::Float32},   {"UInt8", ScalarType::UInt8},     {"Int16", ScalarType::Int16},
      {"UInt16", ScalarType::UInt16},  {"Int32", ScalarType::Float32},   {"UInt32", ScalarType::Float32},
      {"Int64", ScalarType::Float32},  {"UInt64", ScalarType::Float32},  {"Float32", ScalarType::Float32},
      {"Float64", ScalarType::Float32}};
  for (const auto& [type, stored] : types) {
    const std::string t = type;
    std::vector<double> values{0, 1, 2, 3, 4, 5, 6, 100};
    if (t[0] != 'U') values[0] = -7;
    if (t[0] == 'F') values[1] = 0.25;
    std::ostringstream text;
    for (double v : values) text << v << ' ';
    const std::string ascii = vti(R"(<DataArray type=")" + t + R"(" Name="s" format="ascii">)" + text.str() + "</DataArray>");
    const std::string data = packed(t, values);
    const std::string appended = vti(R"(<DataArray type=")" + t + R"(" Name="s" format="appended" offset="0"/>)",
                                     "0 1 0 1 0 1", R"(Origin="0 0 0" Spacing="1 1 1")", "", header32(data.size()) + data);
    for (const std::string& file : {ascii, appended}) {
      const GridVolume v = parse_vti(test::bytes_of(file), "", "t.vti");
      EXPECT_EQ(v.type(), stored) << t;
      EXPECT_EQ(test::floats(v), std::vector<float>(values.begin(), values.end())) << t;
    }
  }
}

#if !VRI_NO_LZ4_TEST
// vtkLZ4DataCompressor (issue 51 item 6): blocks of the UInt32 header's
// sizes, decompressed with liblz4; a corrupt block is one line.
TEST(Vti, ReadsLz4CompressedArrays) {
  std::vector<double> values;
  for (int i = 0; i < 4 * 3 * 2; ++i) values.push_back(i % 5 * 10);
  const std::string data = packed("UInt8", values);
  std::string compressed(static_cast<std::size_t>(LZ4_compressBound(int(data.size()))), '\0');
  compressed.resize(static_cast<std::size_t>(
      LZ4_compress_default(data.data(), compressed.data(), int(data.size()), int(compressed.size()))));
  const std::string header = header32(1) + header32(data.size()) + header32(data.size()) + header32(compressed.size());
  const std::string array = R"(<DataArray type="UInt8" Name="s" format="appended" offset="0"/>)";
  const std::string file =
      vti(array, "0 3 0 2 0 1", R"(Origin="0 0 0" Spacing="1 1 1")", R"(compressor="vtkLZ4DataCompressor")", header + compressed);
  const GridVolume v = parse_vti(test::bytes_of(file), "", "lz4.vti");
  EXPECT_EQ(v.dims(), (std::array<int, 3>{4, 3, 2}));
  EXPECT_EQ(test::floats(v), std::vector<float>(values.begin(), values.end()));
  std::string corrupt = compressed;
  corrupt[0] = '\xff';
  const std::string bad = vti(array, "0 3 0 2 0 1", R"(Origin="0 0 0" Spacing="1 1 1")",
                              R"(compressor="vtkLZ4DataCompressor")", header + corrupt);
  test::expect_mesh_error([&] { parse_vti(test::bytes_of(bad), "", "t.vti"); }, "cannot decompress an LZ4 block");
}
#endif

// Cell data: the grid of the cells' centres (one point fewer a side, half a
// step in); point scalars, where there are any, win.
TEST(Vti, CellDataIsTheGridOfTheCellCentres) {
  const std::string cells = R"(<?xml version="1.0"?>
<VTKFile type="ImageData" version="0.1" byte_order="LittleEndian">
<ImageData WholeExtent="0 3 0 2 0 2" Origin="1 2 3" Spacing="0.5 1 2">
<Piece Extent="0 3 0 2 0 2"><CellData Scalars="c">
<DataArray type="Float32" Name="c" format="ascii">0 1 2 3 4 5 6 7 8 9 10 11</DataArray>
</CellData></Piece></ImageData></VTKFile>)";
  const GridVolume v = parse_vti(test::bytes_of(cells), "", "cells.vti");
  EXPECT_EQ(v.dims(), (std::array<int, 3>{3, 2, 2}));
  EXPECT_DOUBLE_EQ(v.origin().x, 1.25);
  EXPECT_DOUBLE_EQ(v.origin().y, 2.5);
  EXPECT_DOUBLE_EQ(v.origin().z, 4);
  EXPECT_DOUBLE_EQ(v.spacing().z, 2);
  EXPECT_EQ(v.at(2, 1, 1), 11);
  EXPECT_EQ(v.at(1, 0, 1), 7);
  // Cell data one cell thin on an axis leaves a grid of one point there: refused.
  std::string thin = cells;
  thin.replace(thin.find("0 3 0 2 0 2"), 11, "0 3 0 2 0 1");
  thin.replace(thin.find("0 3 0 2 0 2"), 11, "0 3 0 2 0 1");
  EXPECT_THROW(parse_vti(test::bytes_of(thin), "", "thin.vti"), Error);
}

TEST(Vti, RefusesBadFilesWithOneLine) {
  auto parse = [](const std::string& text, const std::string& scalars = "") {
    return [=] { parse_vti(test::bytes_of(text), scalars, "t.vti"); };
  };
  const std::string s8 = R"(<DataArray type="UInt8" Name="s" format="ascii">0 1 2 3 4 5 6 7</DataArray>)";
  EXPECT_EQ(parse_vti(test::bytes_of(vti(s8)), "", "t.vti").max_value(), 7);
  test::expect_mesh_error(parse("hello"), "t.vti: not a VTK XML file");
  test::expect_mesh_error(parse("<VTKFile type=\"UnstructuredGrid\"><Piece/></VTKFile>"), "only ImageData");
  test::expect_mesh_error(parse(vti(s8, "0 16383 0 8191 0 8191")), "exceeds the limit");  // 2^40 samples
  test::expect_mesh_error(parse(vti(s8, "0 1 0 1 0")), "Extent must be 6 numbers");
  test::expect_mesh_error(parse(vti(s8, "0 1 0 1 2 1")), "not a valid extent");
  test::expect_mesh_error(parse(vti(R"(<DataArray type="Complex64" Name="s" format="ascii">0</DataArray>)")),
                          "unsupported type 'Complex64'");
  test::expect_mesh_error(parse(vti(R"(<DataArray type="UInt8" Name="s" format="binary">CAAAAA@@</DataArray>)")),
                          "DataArray 's': bad base64");
  test::expect_mesh_error(parse(vti(R"(<DataArray type="UInt8" Name="s" format="ascii">0 1 2</DataArray>)")),
                          "data ends early");
  test::expect_mesh_error(parse(vti(R"(<DataArray type="UInt8" Name="s" format="ascii">0 1 2 3 4 5 6 7 8</DataArray>)")),
                          "holds more than the 8 values");
  test::expect_mesh_error(parse(vti(R"(<DataArray type="UInt8" Name="s" format="ascii">0 1 2 3 4 5 6 256</DataArray>)")),
                          "value '256' is not a valid UInt8");
  test::expect_mesh_error(parse(vti(s8), "height"), "no point scalars named 'height' (the file has: s)");
  const std::string v3 = R"(<DataArray type="Float32" Name="v" NumberOfComponents="3" format="ascii">0</DataArray>)";
  test::expect_mesh_error(parse(vti(v3), "v"), "point array 'v' has 3 components");
  test::expect_mesh_error(parse(vti(v3)), "no one-component point scalars (the file has: v [3 components])");
  test::expect_mesh_error(parse(vti(s8, "0 1 0 1 0 1", R"(Direction="0 1 0 1 0 0 0 0 1")")), "is not diagonal");
  test::expect_mesh_error(parse(vti(s8, "0 1 0 1 0 1", R"(Direction="2 0 0 0 1 0 0 0 1")")), "is not diagonal");
  test::expect_mesh_error(parse(vti(s8, "0 1 0 1 0 1", R"(Spacing="1 0 1")")), "spacing must be positive");
  // zlib: a valid header over garbage.
  const std::string zlib_header = packed("UInt32", {1, 8, 8, 8});
  test::expect_mesh_error(parse(vti(R"(<DataArray type="UInt8" Name="s" format="appended" offset="0"/>)", "0 1 0 1 0 1",
                                    R"(Origin="0 0 0" Spacing="1 1 1")", R"(compressor="vtkZLibDataCompressor")",
                                    zlib_header + "garbage!")),
                          "cannot decompress a zlib block");
}

// Sizes a header declares are checked against the bytes present before the
// volume is allocated: with a 1 MiB budget, 512^3 declared samples end in
// the error about the data, not the budget's.
TEST(Vti, RefusesDeclaredSizesBeforeAllocating) {
  auto parse = [](const std::string& text) { return [=] { parse_vti(test::bytes_of(text), "", "t.vti"); }; };
  set_memory_limit(1 << 20);
  const std::string big = "0 511 0 511 0 511";
  const std::string appended = R"(<DataArray type="UInt8" Name="s" format="appended" offset="0"/>)";
  const std::string image = R"(Origin="0 0 0" Spacing="1 1 1")";
  test::expect_mesh_error(parse(vti(appended, big, image, "", header32(1 << 27) + "12345678")), "binary array ends early");
  test::expect_mesh_error(parse(vti(appended, big, image, "", header32(8) + "12345678")), "holds 8 bytes, expected 134217728");
  test::expect_mesh_error(parse(vti(appended, big, image, R"(compressor="vtkZLibDataCompressor")",
                                    packed("UInt32", {1, 1 << 27, 1 << 27, 8}) + "12345678")),
                          "compressed array is truncated");
  test::expect_mesh_error(parse(vti(R"(<DataArray type="UInt8" Name="s" format="ascii">0 1 2</DataArray>)", big)),
                          "data ends early");
  set_memory_limit(0);
}

TEST(Vti, RefusesTruncatedFiles) {
  for (const char* name : {"ascii.vti", "base64_zlib.vti", "appended_raw.vti", "appended_base64_zlib_uint64.vti"}) {
    const std::string text = fx::file_text(fx::volume_fixture(name));
    for (double cut : {0.05, 0.3, 0.6, 0.9}) {
      const std::string part = text.substr(0, std::size_t(cut * double(text.size())));
      test::expect_mesh_error([&] { parse_vti(test::bytes_of(part), "height", "t.vti"); }, "t.vti: ");
    }
  }
}

}  // namespace
}  // namespace vri
