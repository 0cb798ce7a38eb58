#include "io/nrrd.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "io/gzip.hpp"
#include "io/pattern_fixtures.hpp"
#include "test_support.hpp"
#include "vri/error.hpp"
#include "volume/builtin_volumes.hpp"

namespace vri {
namespace {

void expect_same(const GridVolume& a, const GridVolume& b) {
  EXPECT_EQ(a.dims(), b.dims());
  EXPECT_EQ(test::floats(a), test::floats(b));
  for (int i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(a.spacing()[i], b.spacing()[i]);
    EXPECT_DOUBLE_EQ(a.origin()[i], b.origin()[i]);
  }
}

TEST(Nrrd, RoundTripsAttachedAndDetachedRawAndGzip) {
  test::TempDir dir;
  GridVolume vol = random_field({5, 4, 3}, 2);
  vol.set_spacing({0.5, 1.25, 2});
  vol.set_origin({-1, 2, 3.5});
  for (auto enc : {NrrdEncoding::Raw, NrrdEncoding::Gzip})
    for (const char* name : {"v.nrrd", "v.nhdr"}) {
      write_nrrd(dir / name, vol, enc);
      expect_same(read_nrrd(dir / name), vol);
    }
}

// A typed volume comes back in its own type, raw or gzip, attached or detached.
TEST(Nrrd, RoundTripsTheStoredType) {
  test::TempDir dir;
  std::vector<std::int16_t> v(4 * 3 * 2);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<std::int16_t>(1000 * (int(i) - 12) + 7);
  const GridVolume vol({4, 3, 2}, v);
  for (auto enc : {NrrdEncoding::Raw, NrrdEncoding::Gzip})
    for (const char* name : {"t.nrrd", "t.nhdr"}) {
      write_nrrd(dir / name, vol, enc);
      const GridVolume back = read_nrrd(dir / name);
      EXPECT_EQ(back.type(), ScalarType::Int16) << name;
      expect_same(back, vol);
    }
}

// gzip inflates into the volume, past a byte skip; a line skip before raw data.
TEST(Nrrd, GzipByteSkipAndLineSkip) {
  test::TempDir dir;
  std::vector<std::uint8_t> bytes(20);
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<std::uint8_t>(i);
  write_nrrd(dir / "g.nhdr", GridVolume({2, 2, 5}, bytes), NrrdEncoding::Gzip);  // g.raw.gz: bytes 0 .. 19
  const std::string head = "NRRD0004\ntype: uint16\ndimension: 3\nencoding: gzip\ndata file: g.raw.gz\n";
  test::write_text(dir / "s.nhdr", head + "sizes: 2 2 2\nbyte skip: 4\n");
  const GridVolume skipped = read_nrrd(dir / "s.nhdr");
  EXPECT_EQ(skipped.type(), ScalarType::UInt16);
  EXPECT_EQ(skipped.value(0), 5 * 256 + 4);  // bytes 4 5, little-endian
  EXPECT_EQ(skipped.value(7), 19 * 256 + 18);
  test::write_text(dir / "m.nhdr", head + "sizes: 2 2 2\n");
  EXPECT_THROW(read_nrrd(dir / "m.nhdr"), Error);  // 20 bytes where 16 are needed
  test::write_text(dir / "n.nhdr", head + "sizes: 2 2 3\n");
  EXPECT_THROW(read_nrrd(dir / "n.nhdr"), Error);  // 20 bytes where 24 are needed
  test::write_text(dir / "l.nrrd", "NRRD0004\ntype: uchar\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n"
                                   "line skip: 2\n\nfirst\nsecond\nABCDEFGH");
  const GridVolume lines = read_nrrd(dir / "l.nrrd");
  EXPECT_EQ(lines.type(), ScalarType::UInt8);
  EXPECT_EQ(lines.value(7), 'H');
}

TEST(Nrrd, ReadsHandWrittenHeaders) {
  test::TempDir dir;
  // big-endian uint16, space directions (spacing 2, 3, 4), a byte skip and a comment
  std::string header =
      "NRRD0005\n# a comment\ntype: unsigned short\ndimension: 3\nsizes: 2 2 2\n"
      "space: right-anterior-superior\nspace directions: (2,0,0) (0,-3,0) (0,0,4)\n"
      "space origin: (1,2,3)\nendian: big\nencoding: raw\nbyte skip: 2\nkey:=value\n\n";
  std::vector<unsigned char> bytes(header.begin(), header.end());
  bytes.push_back(0xAA);  // skipped
  bytes.push_back(0xBB);
  for (int i = 0; i < 8; ++i) {
    bytes.push_back(0x01);
    bytes.push_back(static_cast<unsigned char>(i));
  }
  test::write_bytes(dir / "h.nrrd", bytes);
  const auto vol = read_nrrd(dir / "h.nrrd");
  EXPECT_EQ(vol.type(), ScalarType::UInt16);
  // swapped in place; the y direction is negative: file sample (1, 1, 1) is
  // the volume's (1, 0, 1), and the origin the low corner (2 - 3 = -1)
  EXPECT_FLOAT_EQ(vol.at(1, 0, 1), 256 + 7);
  EXPECT_DOUBLE_EQ(vol.spacing().y, 3);
  EXPECT_DOUBLE_EQ(vol.spacing().z, 4);
  EXPECT_DOUBLE_EQ(vol.origin().y, -1);
  EXPECT_DOUBLE_EQ(vol.origin().z, 3);
  // ascii encoding with a leading size-1 axis
  test::write_text(dir / "a.nrrd", "NRRD0004\ntype: float\ndimension: 4\nsizes: 1 2 2 2\nencoding: ascii\n\n1 2 3 4\n5 6 7 8.5\n");
  EXPECT_FLOAT_EQ(read_nrrd(dir / "a.nrrd").at(1, 1, 1), 8.5);
}

TEST(Nrrd, BundledEngineDecodes) {
  const auto vol = read_nrrd(test::source_path("data/engine.nrrd"));
  EXPECT_EQ(vol.dims(), (std::array<int, 3>{256, 256, 128}));
  EXPECT_EQ(vol.type(), ScalarType::UInt8);
  EXPECT_EQ(vol.bytes(), 256u * 256 * 128);  // a byte a sample
  double sum = 0;
  for (float v : test::floats(vol)) sum += v;
  EXPECT_EQ(sum, 187475057.0);  // the sum of the raw file listed in data/PROVENANCE.md
}

TEST(Nrrd, RefusesBrokenFiles) {
  test::TempDir dir;
  const std::string ok = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\n";
  auto refuse = [&](const std::string& text) {
    test::write_text(dir / "bad.nrrd", text);
    EXPECT_THROW(read_nrrd(dir / "bad.nrrd"), Error) << text;
  };
  refuse("P6\n");                                                   // not NRRD
  refuse(ok + "encoding: raw\n\n1234567");                          // one byte short
  refuse(ok + "encoding: raw\n\n123456789");                        // one byte long
  refuse(ok + "encoding: gzip\n\nnot gzip at all");                 // corrupt gzip
  refuse(ok + "encoding: bzip2\n\n12345678");                       // unsupported encoding
  refuse("NRRD0004\ntype: uint8\ndimension: 2\nsizes: 2 2\nencoding: raw\n\n1234");
  refuse("NRRD0004\ntype: quaternion\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\n12345678");
  refuse("NRRD0004\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\n12345678");  // no type
  refuse(ok + "encoding: raw\ndata file: missing.raw\n");
  EXPECT_THROW(read_nrrd(dir / "absent.nrrd"), Error);
}

std::string error_of(const std::filesystem::path& path, const NrrdOptions& options = {}) {
  try {
    read_nrrd(path, options);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

// Issue 17 defects 1 and 10: sizes are checked integers (1e300 was an
// undefined cast) whose product cannot wrap (2^24 per axis wrapped to 0).
TEST(Nrrd, RefusesSizesThatOverflow) {
  test::TempDir dir;
  auto error = [&](const std::string& sizes) {
    test::write_text(dir / "big.nrrd", "NRRD0004\ntype: uint8\ndimension: 3\nsizes: " + sizes + "\nencoding: raw\n\nx");
    return error_of(dir / "big.nrrd");
  };
  EXPECT_NE(error("1e300 2 2").find("'sizes' must be an integer"), std::string::npos) << error("1e300 2 2");
  EXPECT_NE(error("2 2 99999999999999999999999").find("must be an integer"), std::string::npos);
  EXPECT_NE(error("2.5 2 2").find("must be an integer"), std::string::npos);
  EXPECT_NE(error("16777216 16777216 16777216").find("exceeds the limit"), std::string::npos)
      << error("16777216 16777216 16777216");
  EXPECT_NE(error("16777216 16777216 65536").find("exceeds the limit"), std::string::npos);
}

// Issue 17 defect 9: a 120-byte gzip NRRD declaring 1024^3 floats allocated
// 4 GiB before inflating; deflate cannot expand that much, so it is refused
// up front. Ascii sizes the text cannot hold are refused the same way.
TEST(Nrrd, RefusesDeclaredSizesTheDataCannotHold) {
  test::TempDir dir;
  const std::vector<std::byte> zeros(64);
  const auto packed = gzip(zeros);
  std::string text = "NRRD0004\ntype: float\ndimension: 3\nsizes: 1024 1024 1024\nencoding: gzip\n\n";
  text.append(reinterpret_cast<const char*>(packed.data()), packed.size());
  test::write_text(dir / "bomb.nrrd", text);
  EXPECT_NE(error_of(dir / "bomb.nrrd").find("more than its"), std::string::npos) << error_of(dir / "bomb.nrrd");
  test::write_text(dir / "a.nrrd", "NRRD0004\ntype: float\ndimension: 3\nsizes: 1024 1024 1024\nencoding: ascii\n\n1 2 3\n");
  EXPECT_NE(error_of(dir / "a.nrrd").find("1073741824 ascii values in 6 bytes"), std::string::npos) << error_of(dir / "a.nrrd");
}

// Issue 17 defect 12: a negative byte skip other than -1 was silently ignored;
// -1 (raw: the data are the last bytes) has no meaning for gzip.
TEST(Nrrd, NegativeByteSkip) {
  test::TempDir dir;
  const std::string head = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\n";
  test::write_text(dir / "m1.nrrd", head + "encoding: raw\nbyte skip: -1\n\nJUNK\1\2\3\4\5\6\7\10");
  const auto v = read_nrrd(dir / "m1.nrrd");
  EXPECT_EQ(test::floats(v), (std::vector<float>{1, 2, 3, 4, 5, 6, 7, 8}));
  test::write_text(dir / "m2.nrrd", head + "encoding: raw\nbyte skip: -2\n\n12345678");
  EXPECT_NE(error_of(dir / "m2.nrrd").find("'byte skip' must be an integer from -1"), std::string::npos)
      << error_of(dir / "m2.nrrd");
  test::write_text(dir / "m3.nrrd", head + "encoding: gzip\nbyte skip: -1\n\n12345678");
  EXPECT_NE(error_of(dir / "m3.nrrd").find("only works with raw"), std::string::npos) << error_of(dir / "m3.nrrd");
  test::write_text(dir / "m4.nrrd", head + "encoding: raw\nbyte skip: lots\n\n12345678");
  EXPECT_NE(error_of(dir / "m4.nrrd").find("'byte skip' must be an integer"), std::string::npos);
}

// Issue 17 defect 13: concatenated gzip members (as gzip -d reads them).
TEST(Nrrd, ReadsMultiMemberGzip) {
  test::TempDir dir;
  std::vector<std::byte> a(5), b(3);
  for (std::size_t i = 0; i < a.size(); ++i) a[i] = std::byte(i + 1);
  for (std::size_t i = 0; i < b.size(); ++i) b[i] = std::byte(i + 6);
  const auto ga = gzip(a), gb = gzip(b);
  std::string text = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: gzip\n\n";
  text.append(reinterpret_cast<const char*>(ga.data()), ga.size());
  text.append(reinterpret_cast<const char*>(gb.data()), gb.size());
  test::write_text(dir / "two.nrrd", text);
  EXPECT_EQ(test::floats(read_nrrd(dir / "two.nrrd")), (std::vector<float>{1, 2, 3, 4, 5, 6, 7, 8}));
}

// Issue 17 defect 13: a detached header may not name data outside its folder
// unless allowed.
TEST(Nrrd, DataFileStaysInTheHeadersFolder) {
  test::TempDir dir;
  std::filesystem::create_directories(dir / "sub");
  test::write_text(dir / "outside.raw", "12345678");
  test::write_text(dir / "sub" / "inside.raw", "12345678");
  const std::string head = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\ndata file: ";
  test::write_text(dir / "sub" / "ok.nhdr", head + "inside.raw\n");
  EXPECT_EQ(read_nrrd(dir / "sub" / "ok.nhdr").size(), 8u);
  test::write_text(dir / "sub" / "up.nhdr", head + "../outside.raw\n");
  test::write_text(dir / "sub" / "abs.nhdr", head + (dir / "outside.raw").string() + "\n");
  test::write_text(dir / "sub" / "sneaky.nhdr", head + "./x/../../outside.raw\n");
  std::filesystem::create_symlink(dir / "outside.raw", dir / "sub" / "link.raw");
  test::write_text(dir / "sub" / "link.nhdr", head + "link.raw\n");
  for (const char* name : {"up.nhdr", "abs.nhdr", "sneaky.nhdr", "link.nhdr"}) {
    EXPECT_NE(error_of(dir / "sub" / name).find("outside the header's folder"), std::string::npos)
        << name << ": " << error_of(dir / "sub" / name);
    if (std::string(name) != "sneaky.nhdr") {  // sub/x does not exist: the OS cannot resolve it
      EXPECT_EQ(read_nrrd(dir / "sub" / name, NrrdOptions{.allow_outside_paths = true}).size(), 8u) << name;
    }
  }
}

// Issue 20: a negative `space directions` entry runs that axis backwards; the
// samples are mirrored so that each sits where the file puts it, and the box
// is the file's (fixtures by tools/make_mhd_npy_fixtures.py).
TEST(Nrrd, NegativeSpaceDirectionsFlipTheAxis) {
  const Vec3 spacing{0.5, 1.25, 2}, origin{-1, 2, 3.5};
  test::expect_pattern(read_nrrd(test::volume_fixture("nrrd_neg_x.nrrd")),
                       {"nrrd_neg_x.nrrd", 300, 0, ScalarType::UInt16}, spacing, origin);
  test::expect_pattern(read_nrrd(test::volume_fixture("nrrd_neg_yz_gzip.nrrd")),
                       {"nrrd_neg_yz_gzip.nrrd", 0.5, -10, ScalarType::Float32}, spacing, origin);
  test::TempDir dir;
  const std::string head = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\nspace origin: (5,0,0)\n";
  test::write_text(dir / "x.nrrd", head + "space directions: (-2,0,0) (0,1,0) (0,0,1)\n\n\1\2\3\4\5\6\7\10");
  const auto v = read_nrrd(dir / "x.nrrd");
  EXPECT_EQ(test::floats(v), (std::vector<float>{2, 1, 4, 3, 6, 5, 8, 7}));
  EXPECT_DOUBLE_EQ(v.origin().x, 3);
  EXPECT_DOUBLE_EQ(v.box_hi().x, 5);
  // a 4D file's leading "none" axis, and `spacings` (no directions): unchanged
  test::write_text(dir / "n.nrrd", "NRRD0004\ntype: uint8\ndimension: 4\nsizes: 1 2 2 2\nencoding: raw\n"
                                   "space directions: none (1,0,0) (0,-1,0) (0,0,1)\n\n\1\2\3\4\5\6\7\10");
  EXPECT_EQ(test::floats(read_nrrd(dir / "n.nrrd")), (std::vector<float>{3, 4, 1, 2, 7, 8, 5, 6}));
}

TEST(Nrrd, RefusesSpaceDirectionsThatAreNotAxisAligned) {
  const auto path = test::volume_fixture("nrrd_oblique.nrrd");
  const std::string m =
      test::expect_error([&] { read_nrrd(path); }, "'space directions' vector (0.5,0.5,0) is not along its axis");
  EXPECT_NE(m.find("NRRD '" + path.string() + "'"), std::string::npos) << m;
  test::TempDir dir;
  const std::string head = "NRRD0004\ntype: uint8\ndimension: 3\nsizes: 2 2 2\nencoding: raw\nspace directions: ";
  const auto refuse = [&](const std::string& dirs, const std::string& fragment) {
    test::write_text(dir / "d.nrrd", head + dirs + "\n\n12345678");
    test::expect_error([&] { read_nrrd(dir / "d.nrrd"); }, fragment);
  };
  refuse("(0,1,0) (1,0,0) (0,0,1)", "vector (0,1,0) has no step along its axis");
  refuse("(1,0,0) (0,1,0) (0,0.001,1)", "vector (0,0.001,1) is not along its axis");
  refuse("(1,0) (0,1) (0,0)", "vector (1,0) needs 3 components");
  refuse("(1,0,0) (0,1,0)", "'space directions' does not match 'dimension'");
}

}  // namespace
}  // namespace vri
