// MetaImage (.mha, .mhd) against fixtures VTK's vtkMetaImageWriter and hand
// formatted headers wrote (tools/make_mhd_npy_fixtures.py), and against broken
// and hostile headers: one line of vri::Error each, nothing allocated first.
#include "test_support.hpp"
#include "io/metaimage.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "io/pattern_fixtures.hpp"
#include "vri/io.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri {
namespace {

using test::PatternFixture;

const Vec3 kSpacing{0.5, 1.25, 2}, kOrigin{-1, 2, 3.5};
constexpr double k2p33 = 8589934592.0, k2p40 = 1099511627776.0;

const PatternFixture kFixtures[] = {
    // vtkMetaImageWriter
    {"mhd_uchar.mhd", 1, 0, ScalarType::UInt8},
    {"mhd_short_zlib.mhd", 100, -4800, ScalarType::Int16},
    {"mhd_float.mha", 0.5, -10, ScalarType::Float32},
    {"mhd_ushort_zlib.mha", 300, 0, ScalarType::UInt16},
    {"mhd_uchar_zlib.mha", 1, 0, ScalarType::UInt8},
    {"mhd_double_zlib.mha", 0.25, -3, ScalarType::Float32},
    {"mhd_char.mha", 1, -48, ScalarType::Float32},
    {"mhd_int.mha", 100000, -4800000, ScalarType::Float32},
    {"mhd_uint_zlib.mha", 100000, 0, ScalarType::Float32},
    // hand-formatted headers
    {"mhd_msb_short.mha", 100, -4800, ScalarType::Int16},
    {"mhd_flip_xz.mha", 1, 0, ScalarType::UInt8},
    {"mhd_headersize.mhd", 300, 0, ScalarType::UInt16},
    {"mhd_headersize_end.mhd", 300, 0, ScalarType::UInt16},
    {"mhd_long_long_msb.mha", k2p33, -48 * k2p33, ScalarType::Float32},
    {"mhd_ulong.mha", 100000, 0, ScalarType::Float32},
    {"mhd_ulong_long_zlib.mha", k2p40, 0, ScalarType::Float32},
};

TEST(MetaImage, FixturesReadBackToThePattern) {
  for (const auto& f : kFixtures) test::expect_pattern(read_metaimage(test::volume_fixture(f.name)), f, kSpacing, kOrigin);
}

// parse_metaimage over the header's bytes reads the same (a .mhd's data file
// is found in base_dir).
TEST(MetaImage, ParseMatchesRead) {
  for (const auto& f : kFixtures) {
    const auto bytes = read_file(test::volume_fixture(f.name));
    test::expect_pattern(parse_metaimage(bytes, test::volume_fixture(""), f.name), f, kSpacing, kOrigin);
  }
}

struct Files {
  test::TempDir dir;
  std::filesystem::path write(const std::string& name, const std::string& text) {
    test::write_text(dir / name, text);
    return dir / name;
  }
};

std::string head(const std::string& extra, const std::string& dims = "2 2 2", const std::string& type = "MET_UCHAR") {
  return "ObjectType = Image\nNDims = 3\nDimSize = " + dims + "\nElementType = " + type + "\n" + extra +
         "ElementDataFile = LOCAL\n";
}

// A -1 on the diagonal: the file's first sample sits at Offset, the axis runs
// backwards; each sample lands where the file puts it, and the box is the
// file's: [Offset - (n-1) spacing, Offset] along that axis.
TEST(MetaImage, DiagonalDirectionsFlipTheAxis) {
  Files f;
  const std::string data = "\x01\x02\x03\x04\x05\x06\x07\x08";
  for (const char* key : {"TransformMatrix", "Orientation", "Rotation", "Direction"}) {
    const auto v = read_metaimage(f.write("y.mha", head(std::string(key) + " = 1 0 0 0 -1 0 0 0 1\nOffset = 1 5 0\n"
                                                                        "ElementSpacing = 1 2 1\n") + data));
    EXPECT_EQ(v.at(0, 0, 0), 3) << key;  // file sample (0, 1, 0)
    EXPECT_EQ(v.at(1, 1, 1), 6) << key;  // file sample (1, 0, 1)
    EXPECT_DOUBLE_EQ(v.origin().y, 3) << key;
    EXPECT_DOUBLE_EQ(v.box_hi().y, 5) << key;
  }
  const auto same = read_metaimage(f.write("i.mha", head("TransformMatrix = 1 0 0 0 1 0 0 0 1\n") + data));
  EXPECT_EQ(same.at(1, 0, 0), 2);
}

TEST(MetaImage, RefusesBrokenAndHostileHeaders) {
  Files f;
  const std::string data(8, '\x07');
  const auto refuse = [&](const std::string& text, const std::string& fragment) {
    SCOPED_TRACE(fragment);
    const auto path = f.write("bad.mha", text);
    const std::string m = test::expect_error([&] { read_metaimage(path); }, fragment);
    EXPECT_NE(m.find("MetaImage '" + path.string() + "'"), std::string::npos) << m;
    test::expect_error([&] { parse_metaimage(read_file(path), f.dir.path, "bad.mha"); }, fragment);
  };
  refuse(head("") + data.substr(1), "holds 7 data bytes, but DimSize and ElementType need 8");
  refuse(head("") + data + "x", "holds 9 data bytes");
  // 2^40 samples: refused from the header alone, before any allocation.
  refuse(head("", "1048576 1048576 1048576") + data, "exceeds the limit");
  refuse(head("", "1024 1024 1024", "MET_FLOAT") + data, "holds 8 data bytes, but DimSize and ElementType need 4294967296");
  refuse(head("CompressedData = True\n", "1024 1024 1024", "MET_FLOAT") + data, "more than its 8 compressed bytes");
  // fuzz_metaimage: no compressed bytes at all (tests/data/fuzz/metaimage/zero_compressed_bytes)
  refuse(head("CompressedData = True\n"), "declares 8 data bytes, more than its 0 compressed bytes can hold");
  refuse(head("", "2 2 2", "MET_FOO") + data, "ElementType 'MET_FOO' is not supported");
  refuse(head("", "2 2 2", "MET_ASCII_CHAR") + data, "ElementType 'MET_ASCII_CHAR' is not supported");
  refuse(head("", "2 2 0") + data, "DimSize must be 3 positive integers");
  refuse(head("", "2 2") + data, "DimSize needs 3 numbers");
  refuse(head("ElementNumberOfChannels = 3\n") + data + data + data, "3 channels a sample");
  refuse("NDims = 2\nDimSize = 2 2\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n1234", "is 2-D");
  refuse("NDims = 4\nDimSize = 2 2 2 1\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n" + data, "is 4-D");
  refuse("ObjectType = Tube\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n" + data,
         "ObjectType 'Tube' is not an image");
  refuse(head("TransformMatrix = 0 1 0 1 0 0 0 0 1\n") + data, "is not a diagonal of 1 and -1");
  refuse(head("TransformMatrix = 0.8 0.6 0 -0.6 0.8 0 0 0 1\n") + data, "is not a diagonal of 1 and -1");
  refuse(head("TransformMatrix = 2 0 0 0 1 0 0 0 1\n") + data, "is not a diagonal of 1 and -1");
  refuse(head("BinaryData = False\n") + "1 2 3 4 5 6 7 8", "ASCII data");
  refuse(head("ElementSpacing = 1 0 1\n") + data, "ElementSpacing must be positive");
  refuse(head("Offset = 1 nan 1\n") + data, "Offset has a bad number");
  refuse(head("HeaderSize = -2\n") + data, "HeaderSize must be an integer from -1");
  refuse(head("HeaderSize = 3\n") + data, "points inside the header");
  refuse("NDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\n", "lacks ElementDataFile");
  refuse("NDims = 3\nnot a key value line\n", "malformed header line");
  refuse("NDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\nElementDataFile = LIST 2D\na.raw\n", "multi-file data");
  refuse("NDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\nElementDataFile = s%03d.raw 1 2 1\n", "multi-file data");
  refuse("NDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\nElementDataFile = ../up.raw\n", "outside the header's folder");
}

// CompressedDataSize says how many bytes the zlib stream takes: more than
// the file holds, or fewer than the stream needs, is an error.
TEST(MetaImage, RefusesCompressedDataSizesThatLie) {
  Files f;
  const auto packed = read_file(test::volume_fixture("mhd_uchar_zlib.mha"));
  const std::string text(reinterpret_cast<const char*>(packed.data()), packed.size());
  const auto at = text.find("CompressedDataSize = ");
  ASSERT_NE(at, std::string::npos);
  const auto eol = text.find('\n', at);
  const std::size_t size = std::stoul(text.substr(at + 21, eol - at - 21));
  const auto with_size = [&](std::size_t claimed) {
    return f.write("z.mha", text.substr(0, at) + "CompressedDataSize = " + std::to_string(claimed) + text.substr(eol));
  };
  EXPECT_EQ(read_metaimage(with_size(size)).size(), 385u);
  test::expect_error([&] { read_metaimage(with_size(size + 1)); }, "is more than the " + std::to_string(size) + " bytes present");
  test::expect_error([&] { read_metaimage(with_size(size - 5)); }, "truncated");
  test::expect_error([&] { read_metaimage(with_size(0)); }, "CompressedDataSize must be an integer");
  // A stream that inflates to fewer bytes than the header needs.
  std::string longer = text;
  longer.replace(longer.find("DimSize = 11 7 5"), 16, "DimSize = 11 7 6");
  const auto short_stream = f.write("s.mha", longer);
  test::expect_error([&] { read_metaimage(short_stream); },
                     "the compressed data hold 385 bytes, DimSize and ElementType need 462");
}

TEST(MetaImage, DetachedDataFiles) {
  Files f;
  std::filesystem::create_directories(f.dir / "sub");
  test::write_text(f.dir / "outside.raw", "12345678");
  test::write_text(f.dir / "sub" / "inside.raw", "12345678");
  const std::string h = "NDims = 3\nDimSize = 2 2 2\nElementType = MET_UCHAR\nElementDataFile = ";
  EXPECT_EQ(read_metaimage(f.write("sub/ok.mhd", h + "inside.raw\n")).at(1, 1, 1), '8');
  const auto up = f.write("sub/up.mhd", h + "../outside.raw\n");
  test::expect_error([&] { read_metaimage(up); }, "ElementDataFile '../outside.raw' is outside the header's folder");
  EXPECT_EQ(read_metaimage(up, MetaImageOptions{.allow_outside_paths = true}).size(), 8u);
  test::expect_error([&] { read_metaimage(f.write("sub/no.mhd", h + "missing.raw\n")); }, "missing.raw");
  test::expect_error([&] { read_metaimage(f.dir / "absent.mha"); }, "absent.mha");
}

// A scene over the .mha renders the same bytes as over the headerless raw
// (SPEC §1) holding the same samples, spacing and origin.
TEST(MetaImage, RendersAsTheRawFile) {
  GridVolume raw = read_raw_volume(test::volume_fixture(test::pattern_raw()), {11, 7, 5}, ScalarType::UInt8);
  raw.set_spacing(kSpacing);
  raw.set_origin(kOrigin);
  const std::string json = R"({"transfer_function": {"points": [[0, 0, 0, 0, 0], [40, 1, 0.5, 0.2, 0.3], [96, 0.2, 0.4, 1, 0.9]]},
    "camera": {"eye": [20, 16, 30], "target": [1.5, 5.75, 7.5], "width": 24, "height": 20},
    "method": {"name": "riemann", "step": 0.5}})";
  const auto render = [&](const GridVolume& v) {
    const Scene scene = parse_scene(json, v, test::volume_fixture(""));
    return test::pixels(SceneRenderer(scene).render());
  };
  const auto want = render(raw);
  double alpha = 0;
  for (std::size_t i = 3; i < want.size(); i += 4) alpha += want[i];
  EXPECT_GT(alpha, 1);  // the volume is in view
  for (const char* name : {"mhd_uchar_zlib.mha", "mhd_flip_xz.mha"})
    EXPECT_EQ(render(read_metaimage(test::volume_fixture(name))), want) << name;
}

}  // namespace
}  // namespace vri
