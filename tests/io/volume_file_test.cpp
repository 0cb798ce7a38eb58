// Volume files told apart by what they are: each format by its magic bytes
// (whatever the file is called), scenes that name any of them, and one line
// naming every supported format when a file has no header vri knows.
#include "vri/io.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "test_support.hpp"
#include "vri/error.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri {
namespace {

std::filesystem::path fixture(const std::string& name) { return test::source_path("tests/data/volume/" + name); }

TEST(VolumeFile, EachFormatByItsMagicBytes) {
  EXPECT_EQ(volume_format(fixture("base64_zlib.vti")), VolumeFormat::Vti);
  EXPECT_EQ(volume_format(fixture("legacy_binary.vtk")), VolumeFormat::VtkStructuredPoints);
  EXPECT_EQ(volume_format(test::source_path("data/blunt_fin_tet.vtk")), VolumeFormat::VtkLegacyMesh);
  EXPECT_EQ(volume_format(test::source_path("tests/data/mesh/base64.vtu")), VolumeFormat::Vtu);
  EXPECT_EQ(volume_format(fixture("mhd_uchar.mhd")), VolumeFormat::MetaImage);
  EXPECT_EQ(volume_format(fixture("mhd_float.mha")), VolumeFormat::MetaImage);
  EXPECT_EQ(volume_format(fixture("npy_u1.npy")), VolumeFormat::Npy);
  EXPECT_EQ(volume_format(fixture("nrrd_neg_x.nrrd")), VolumeFormat::Nrrd);
  EXPECT_EQ(volume_format(test::source_path("data/neghip_64x64x64_uint8.raw")), VolumeFormat::Raw);
  // The name does not decide: an .npy called .dat is still NumPy; a headerless .dat is volvis.
  test::TempDir dir;
  std::filesystem::copy_file(fixture("npy_u1.npy"), dir / "renamed.dat");
  EXPECT_EQ(volume_format(dir / "renamed.dat"), VolumeFormat::Npy);
  std::filesystem::copy_file(test::source_path("data/neghip_64x64x64_uint8.raw"), dir / "x.dat");
  EXPECT_EQ(volume_format(dir / "x.dat"), VolumeFormat::VolvisDat);
}

TEST(VolumeFile, RefusesOtherVtkXmlTypesAndMissingFiles) {
  const std::string polydata = R"(<?xml version="1.0"?><VTKFile type="PolyData" version="1.0"></VTKFile>)";
  const auto bytes = std::as_bytes(std::span(polydata.data(), polydata.size()));
  EXPECT_THROW(volume_format(bytes, "x.vtp"), Error);
  EXPECT_THROW(volume_format(fixture("no_such_file.vti")), FileError);
}

// A scene may name any of them; each renders what the same samples given raw render.
TEST(VolumeFile, ScenesOverEveryFormatRenderAsRaw) {
  const std::string rest = R"("transfer_function": {"points": [[0, 0.2, 0.5, 1, 0], [255, 1, 0.8, 0.2, 0.4]]},
    "camera": {"width": 24, "height": 16}, "method": {"name": "preint1"})";
  auto render = [&](const std::string& volume) {
    const Scene s = parse_scene("{\"volume\": " + volume + ", " + rest + "}", fixture(""), "scene");
    return test::pixels(SceneRenderer(s).render());
  };
  // The VTK fixtures hold vtk_scalars_uint8.raw with its spacing and origin.
  const auto raw = render(R"({"file": "vtk_scalars_uint8.raw", "dims": [11, 7, 5], "type": "uint8",
                              "spacing": [0.5, 1.25, 2.0], "origin": [1.0, -2.0, 3.0]})");
  for (const char* f : {"ascii.vti", "appended_raw_zlib.vti", "legacy_binary.vtk"})
    EXPECT_EQ(render(std::string(R"({"file": ")") + f + "\"}"), raw) << f;
  // The MetaImage and NumPy fixtures hold the pattern of mhd_npy_nrrd_pattern_uint8.raw
  // (VTK's MetaImage writer with spacing 0.5 1.25 2 and offset -1 2 3.5).
  const auto pattern = render(R"({"file": "mhd_npy_nrrd_pattern_uint8.raw", "dims": [11, 7, 5]})");
  for (const char* f : {"npy_u1.npy", "npy_u1_fortran.npy"})
    EXPECT_EQ(render(std::string(R"({"file": ")") + f + "\"}"), pattern) << f;
  const auto placed = render(R"({"file": "mhd_npy_nrrd_pattern_uint8.raw", "dims": [11, 7, 5],
                                 "spacing": [0.5, 1.25, 2], "origin": [-1, 2, 3.5]})");
  for (const char* f : {"mhd_uchar.mhd", "mhd_uchar_zlib.mha"})
    EXPECT_EQ(render(std::string(R"({"file": ")") + f + "\"}"), placed) << f;
}

TEST(VolumeFile, SceneKeysThatDoNotApplyAreRefused) {
  const std::string rest = R"("transfer_function": {"points": [[0, 1, 1, 1, 0.1]]}, "camera": {})";
  auto refusal = [&](const std::string& volume) -> std::string {
    try {
      parse_scene("{\"volume\": " + volume + ", " + rest + "}", fixture(""), "scene");
    } catch (const Error& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_NE(refusal(R"({"file": "npy_u1.npy", "dims": [11, 7, 5]})").find("applies to headerless raw files"),
            std::string::npos);
  EXPECT_NE(refusal(R"({"file": "mhd_float.mha", "scalars": "x"})").find("names an array of a VTK file"),
            std::string::npos);
  const std::string no_dims = refusal(R"({"file": "vtk_scalars_uint8.raw"})");
  EXPECT_NE(no_dims.find("needs 'dims'"), std::string::npos) << no_dims;
  EXPECT_NE(no_dims.find("MetaImage (.mhd, .mha)"), std::string::npos) << no_dims;
  EXPECT_NE(refusal(R"({"file": "../mesh/base64.vtu", "spacing": [1, 1, 1]})").find("not to meshes"),
            std::string::npos);
}

TEST(VolumeFile, LoadVolumeReadsSelfDescribingFiles) {
  const Volume v = load_volume(fixture("base64.vti"));
  ASSERT_TRUE(std::holds_alternative<GridVolume>(v));
  EXPECT_EQ(std::get<GridVolume>(v).dims(), (std::array<int, 3>{11, 7, 5}));
  EXPECT_TRUE(std::holds_alternative<TetMesh>(load_volume(test::source_path("data/blunt_fin_tet.vtk"), "density")));
  EXPECT_THROW(load_volume(fixture("vtk_scalars_uint8.raw")), Error);
}

}  // namespace
}  // namespace vri
