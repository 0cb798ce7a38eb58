// TIFF stacks (io/tiff.hpp; SPEC §11: page = z, row = y) against files
// VTK's vtkTIFFWriter, tifffile and tiffcp wrote (tools/make_tiff_fixtures.py):
// each reads back exactly the samples of the formula the generator used and
// of its .npy twin (the same array through numpy.save), renders the same
// bytes as the twin, and bad input ends in one line of vri::Error.
#include "io/tiff.hpp"

#include <gtest/gtest.h>
#include <tiffio.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "io/pattern_fixtures.hpp"
#include "test_support.hpp"
#include "vri/memory.hpp"
#include "vri/io.hpp"
#include "vri/render.hpp"
#include "vri/scene.hpp"

namespace vri {
namespace {

namespace fs = std::filesystem;
using test::expect_error;
using test::volume_fixture;

struct TiffFixture {
  const char* name;  // in tests/data/volume/; its twin is the same name with .npy
  std::array<int, 3> dims;
  double scale, shift;
  ScalarType stored;
};

// The generator's values: scale * p + shift, p = (7i + 13j + 29k + ijk) mod 97.
const TiffFixture kFixtures[] = {
    {"tiff_u8_packbits.tif", {11, 7, 5}, 1, 0, ScalarType::UInt8},
    {"tiff_u16_lzw.tif", {9, 6, 4}, 300, 0, ScalarType::UInt16},
    {"tiff_f32_tiled.tif", {18, 17, 3}, 0.5, -10, ScalarType::Float32},
    {"tiff_i16_deflate_be.tif", {7, 5, 6}, 100, -4800, ScalarType::Int16},
    {"tiff_i8.tif", {6, 5, 3}, 1, -48, ScalarType::Float32},
    {"tiff_i32.tif", {5, 4, 3}, 100000, -4800000, ScalarType::Float32},
    {"tiff_f64_bigtiff.tif", {5, 4, 3}, 0.25, -3, ScalarType::Float32},
    {"tiff_slices", {6, 5, 11}, 3, 0, ScalarType::UInt16},
};

std::string twin(const std::string& name) { return name.substr(0, name.find('.')) + ".npy"; }

void expect_fixture(const GridVolume& v, const TiffFixture& f) {
  ASSERT_EQ(v.dims(), f.dims);
  EXPECT_EQ(scalar_type_name(v.type()), scalar_type_name(f.stored));
  for (int k = 0; k < f.dims[2]; ++k)
    for (int j = 0; j < f.dims[1]; ++j)
      for (int i = 0; i < f.dims[0]; ++i) {
        const int p = (7 * i + 13 * j + 29 * k + i * j * k) % 97;
        ASSERT_EQ(v.at(i, j, k), static_cast<float>(f.scale * p + f.shift)) << i << " " << j << " " << k;
      }
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(v.spacing()[a], 1.0) << "axis " << a;
    EXPECT_EQ(v.origin()[a], 0.0) << "axis " << a;
  }
}

TEST(TiffVolume, FixturesReadTheGeneratorsValues) {
  for (const auto& f : kFixtures) {
    SCOPED_TRACE(f.name);
    expect_fixture(read_tiff_volume(volume_fixture(f.name)), f);
    if (!fs::is_directory(volume_fixture(f.name)))
      expect_fixture(parse_tiff_volume(read_file(volume_fixture(f.name)), f.name), f);
  }
  // One sample by hand: page 1, row 2, column 3 of the uint8 stack is p(3, 2, 1).
  EXPECT_EQ(read_tiff_volume(volume_fixture("tiff_u8_packbits.tif")).at(3, 2, 1), (21 + 26 + 29 + 6) % 97);
}

TEST(TiffVolume, FixturesEqualTheirNpyTwinsSampleBySample) {
  for (const auto& f : kFixtures) {
    SCOPED_TRACE(f.name);
    const GridVolume t = read_tiff_volume(volume_fixture(f.name));
    const GridVolume n = read_npy_volume(volume_fixture(twin(f.name)));
    ASSERT_EQ(t.dims(), n.dims());
    EXPECT_EQ(t.type(), n.type());
    ASSERT_EQ(t.size(), n.size());
    for (std::size_t i = 0; i < t.size(); ++i) ASSERT_EQ(t.value(i), n.value(i)) << "sample " << i;
  }
}

// A scene over each renders the same bytes as over its twin (and vri info's load_volume reads it).
TEST(TiffVolume, RendersAsItsNpyTwin) {
  for (const auto& f : kFixtures) {
    SCOPED_TRACE(f.name);
    const GridVolume n = read_npy_volume(volume_fixture(twin(f.name)));
    const std::string tf = "{\"points\": [[" + std::to_string(n.min_value()) + ", 0.2, 0.5, 1, 0], [" +
                           std::to_string(n.max_value()) + ", 1, 0.8, 0.2, 0.4]]}";
    auto render = [&](const std::string& file) {
      const std::string scene = "{\"volume\": {\"file\": \"" + file + "\"}, \"transfer_function\": " + tf +
                                R"(, "camera": {"width": 24, "height": 16}, "method": {"name": "preint1"}})";
      return test::pixels(SceneRenderer(parse_scene(scene, volume_fixture(""), "scene")).render());
    };
    const auto image = render(f.name);
    EXPECT_EQ(image, render(twin(f.name)));
    float alpha = 0;
    for (std::size_t i = 3; i < image.size(); i += 4) alpha = std::max(alpha, image[i]);
    EXPECT_GT(alpha, 0.01f);  // not an empty image
    const Volume v = load_volume(volume_fixture(f.name));
    ASSERT_TRUE(std::holds_alternative<GridVolume>(v));
    EXPECT_EQ(std::get<GridVolume>(v).dims(), f.dims);
  }
}

TEST(TiffVolume, SlicesOfAFolderInNaturalOrder) {
  std::vector<std::string> names;
  for (const auto& p : tiff_slice_files(volume_fixture("tiff_slices"))) names.push_back(p.filename().string());
  EXPECT_EQ(names, (std::vector<std::string>{"s1.tif", "s2.tif", "s3.tif", "s4.tif", "s5.tif", "s6.tif", "s7.tif",
                                             "s8.tif", "s9.tif", "s10.tif", "s11.tif"}));  // README.txt left out
  EXPECT_TRUE(natural_less("s2.tif", "s10.tif"));
  EXPECT_FALSE(natural_less("s10.tif", "s2.tif"));
  EXPECT_TRUE(natural_less("img_001.tif", "img_2.tif"));
  EXPECT_TRUE(natural_less("s2.tif", "s02.tif"));  // equal numbers: the shorter run first
  EXPECT_FALSE(natural_less("s02.tif", "s2.tif"));
  EXPECT_TRUE(natural_less("a9", "b1"));
  EXPECT_TRUE(natural_less("s1", "s1.tif"));
  EXPECT_FALSE(natural_less("s1.tif", "s1.tif"));
  EXPECT_TRUE(natural_less("x99999999999999999999998", "x99999999999999999999999"));  // no overflow
}

TEST(TiffVolume, DetectedByMagicBytesAndFolders) {
  EXPECT_EQ(volume_format(volume_fixture("tiff_u8_packbits.tif")), VolumeFormat::Tiff);     // II*
  EXPECT_EQ(volume_format(volume_fixture("tiff_i16_deflate_be.tif")), VolumeFormat::Tiff);  // MM*
  EXPECT_EQ(volume_format(volume_fixture("tiff_f64_bigtiff.tif")), VolumeFormat::Tiff);     // II+
  EXPECT_EQ(volume_format(volume_fixture("tiff_slices")), VolumeFormat::Tiff);              // a folder
  for (const char* magic : {"II*\0", "MM\0*", "II+\0", "MM\0+"})
    EXPECT_EQ(volume_format(std::as_bytes(std::span(magic, 4)), "x.raw"), VolumeFormat::Tiff) << magic;
  EXPECT_EQ(volume_format(std::as_bytes(std::span("II*\1", 4)), "x.raw"), VolumeFormat::Raw);
  EXPECT_EQ(format_name(VolumeFormat::Tiff), "TIFF");
  EXPECT_NE(std::string(supported_formats()).find("TIFF (.tif, .tiff"), std::string::npos);
  // The name does not decide.
  test::TempDir dir;
  fs::copy_file(volume_fixture("tiff_u16_lzw.tif"), dir / "stack.dat");
  EXPECT_EQ(volume_format(dir / "stack.dat"), VolumeFormat::Tiff);
  EXPECT_EQ(std::get<GridVolume>(load_volume(dir / "stack.dat")).dims(), (std::array<int, 3>{9, 6, 4}));
}

// A minimal little-endian TIFF written here, for what no writer produces:
// uncompressed pages of one strip each, their samples at `offset`.
struct Page {
  std::uint32_t width, height;
  std::uint16_t bits = 8, format = 1;
  std::uint32_t offset = 8, bytes = 0;  // the strip; bytes 0: width * height * bits / 8
};

std::vector<std::byte> crafted_tiff(const std::vector<Page>& pages, const std::vector<std::uint8_t>& data) {
  std::vector<std::byte> out;
  auto put = [&](std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) out.push_back(std::byte((v >> (8 * i)) & 0xff));
  };
  out.reserve(8 + data.size() + pages.size() * 126);
  put('I' | 'I' << 8 | 42 << 16, 4);  // "II*\0": little-endian classic TIFF
  put(8 + data.size(), 4);
  for (auto b : data) out.push_back(std::byte(b));
  for (std::size_t p = 0; p < pages.size(); ++p) {
    const Page& g = pages[p];
    const std::uint32_t bytes = g.bytes ? g.bytes : std::uint32_t(std::uint64_t(g.width) * g.height * g.bits / 8);
    put(10, 2);  // entries, in the order of their tags; type 3 SHORT, 4 LONG
    auto entry = [&](std::uint16_t tag, std::uint16_t type, std::uint32_t value) {
      put(tag, 2), put(type, 2), put(1, 4), put(value, 4);
    };
    entry(256, 4, g.width);   // ImageWidth
    entry(257, 4, g.height);  // ImageLength
    entry(258, 3, g.bits);    // BitsPerSample
    entry(259, 3, 1);         // Compression: none
    entry(262, 3, 1);         // PhotometricInterpretation: min-is-black
    entry(273, 4, g.offset);  // StripOffsets
    entry(277, 3, 1);         // SamplesPerPixel
    entry(278, 4, g.height);  // RowsPerStrip
    entry(279, 4, bytes);     // StripByteCounts
    entry(339, 3, g.format);  // SampleFormat
    put(p + 1 < pages.size() ? out.size() + 4 : 0, 4);  // the next IFD follows this one
  }
  return out;
}

void write(const fs::path& path, const std::vector<std::byte>& bytes) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// A stack as ImageJ saves it: pixels per unit in X/YResolution, the slice
// spacing in its ImageDescription; `description` null leaves the tag out.
void write_imagej_stack(const fs::path& path, const char* description, float xres, float yres) {
  TIFF* tif = TIFFOpen(path.c_str(), "w");
  ASSERT_NE(tif, nullptr);
  const std::uint8_t row[4] = {0, 50, 100, 200};
  for (int page = 0; page < 3; ++page) {
    TIFFSetField(tif, TIFFTAG_IMAGEWIDTH, 4);
    TIFFSetField(tif, TIFFTAG_IMAGELENGTH, 2);
    TIFFSetField(tif, TIFFTAG_BITSPERSAMPLE, 8);
    TIFFSetField(tif, TIFFTAG_SAMPLESPERPIXEL, 1);
    TIFFSetField(tif, TIFFTAG_PHOTOMETRIC, PHOTOMETRIC_MINISBLACK);
    TIFFSetField(tif, TIFFTAG_XRESOLUTION, xres);
    TIFFSetField(tif, TIFFTAG_YRESOLUTION, yres);
    TIFFSetField(tif, TIFFTAG_RESOLUTIONUNIT, RESUNIT_NONE);
    if (description) TIFFSetField(tif, TIFFTAG_IMAGEDESCRIPTION, description);
    for (int y = 0; y < 2; ++y) TIFFWriteScanline(tif, const_cast<std::uint8_t*>(row), y, 0);
    TIFFWriteDirectory(tif);
  }
  TIFFClose(tif);
}

// ImageJ's voxel size (issue 51 item 6): x, y from the resolutions, z from "spacing=".
TEST(TiffVolume, ImageJStacksKeepTheirVoxelSize) {
  test::TempDir dir;
  write_imagej_stack(dir / "fiji.tif", "ImageJ=1.54f\nimages=3\nslices=3\nunit=micron\nspacing=2.5\nloop=false\n", 4, 2);
  const GridVolume v = read_tiff_volume(dir / "fiji.tif");
  EXPECT_EQ(v.dims(), (std::array<int, 3>{4, 2, 3}));
  EXPECT_DOUBLE_EQ(v.spacing().x, 0.25);
  EXPECT_DOUBLE_EQ(v.spacing().y, 0.5);
  EXPECT_DOUBLE_EQ(v.spacing().z, 2.5);
  // Without "spacing=", z stays 1; a bad value is left at 1 too.
  write_imagej_stack(dir / "flat.tif", "ImageJ=1.54f\nimages=3\nspacing=-4\n", 4, 4);
  EXPECT_DOUBLE_EQ(read_tiff_volume(dir / "flat.tif").spacing().z, 1);
  EXPECT_DOUBLE_EQ(read_tiff_volume(dir / "flat.tif").spacing().x, 0.25);
  // Not ImageJ's: a scanner's 72 dpi is no voxel size.
  write_imagej_stack(dir / "scan.tif", "scanned page", 72, 72);
  EXPECT_DOUBLE_EQ(read_tiff_volume(dir / "scan.tif").spacing().x, 1);
  write_imagej_stack(dir / "bare.tif", nullptr, 72, 72);
  EXPECT_DOUBLE_EQ(read_tiff_volume(dir / "bare.tif").spacing().y, 1);
}

TEST(TiffVolume, CraftedFilesAreValid) {
  // 3 x 2, two pages: the helper writes what libtiff reads (so the refusals below refuse for their reason).
  const GridVolume v = parse_tiff_volume(crafted_tiff({{3, 2}, {3, 2, 8, 1, 14}}, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}), "c.tif");
  ASSERT_EQ(v.dims(), (std::array<int, 3>{3, 2, 2}));
  EXPECT_EQ(v.at(0, 0, 0), 1);
  EXPECT_EQ(v.at(2, 1, 0), 6);
  EXPECT_EQ(v.at(0, 1, 1), 10);
}

// Issue 47, defect 11: a strip whose byte count is shorter than its samples
// was read on into the next page's bytes, and rendered with exit 0.
TEST(TiffVolume, RefusesAStripShorterThanItsSamples) {
  const std::vector<std::uint8_t> data{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  const std::string m = expect_error(
      [&] { parse_tiff_volume(crafted_tiff({{3, 2, 8, 1, 8, 3}, {3, 2, 8, 1, 14}}, data), "short.tif"); },
      "TIFF 'short.tif'");
  EXPECT_NE(m.find("page 0: its strip or tile byte counts are shorter than its samples"), std::string::npos) << m;
  // The second page's count short too.
  expect_error([&] { parse_tiff_volume(crafted_tiff({{3, 2}, {3, 2, 8, 1, 14, 5}}, data), "short2.tif"); },
               "byte counts are shorter than its samples");
}

TEST(TiffVolume, RefusesWhatIsNotAGreyStack) {
  const auto refuse = [](const std::string& name, const std::string& fragment) {
    const std::string m = expect_error([&] { read_tiff_volume(volume_fixture(name)); }, fragment);
    EXPECT_NE(m.find(volume_fixture(name).string()), std::string::npos) << m;
  };
  refuse("tiff_err_rgb.tif", "page 0: has 3 samples per pixel (RGB); a volume needs one (grey): convert it to one channel");
  refuse("tiff_err_sizes.tif", "page 2: is 6 x 4 uint8; the first is 5 x 4 uint8");
  refuse("tiff_err_types.tif", "page 2: is 5 x 4 uint16; the first is 5 x 4 uint8");
  refuse("tiff_slices/s1.tif", "has one page; a TIFF volume needs at least 2 pages");
  const auto crafted = [](const std::vector<Page>& pages, const std::string& fragment) {
    expect_error([&] { parse_tiff_volume(crafted_tiff(pages, std::vector<std::uint8_t>(64)), "c.tif"); },
                 "TIFF 'c.tif', " + fragment);
  };
  crafted({{4, 2, 12}, {4, 2, 12}}, "page 0: samples of uint12 are not supported");
  crafted({{2, 2, 64, 6}, {2, 2, 64, 6}}, "page 0: samples of sample format 6 of 64 bits are not supported");
  crafted({{1, 4}, {1, 4}}, "page 0: volume dims must each be at least 2, got 1");
  // A NaN among float samples (0xffffffff).
  expect_error([] { parse_tiff_volume(crafted_tiff({{2, 2, 32, 3}, {2, 2, 32, 3}}, std::vector<std::uint8_t>(16, 0xff)), "nan.tif"); },
               "TIFF 'nan.tif': volume sample 0 is not finite");
}

TEST(TiffVolume, FoldersOfSlicesMustMatch) {
  test::TempDir dir;
  test::write_text(dir / "notes.txt", "not a slice");
  expect_error([&] { read_tiff_volume(dir.path); }, "holds no .tif or .tiff files");
  expect_error([&] { load_volume(dir.path); }, "holds no .tif or .tiff files");
  // Slices 1 and 2 of 6 x 5 uint16, then one of 7 x 5.
  fs::copy_file(volume_fixture("tiff_slices/s1.tif"), dir / "a1.tif");
  expect_error([&] { read_tiff_volume(dir.path); }, "has one page");
  write(dir / "a2.TIFF", crafted_tiff({{6, 5, 16}}, std::vector<std::uint8_t>(60, 7)));
  const GridVolume two = read_tiff_volume(dir.path);
  EXPECT_EQ(two.dims(), (std::array<int, 3>{6, 5, 2}));
  EXPECT_EQ(two.at(5, 4, 1), 7 + 256 * 7);
  write(dir / "a10.tif", crafted_tiff({{7, 5, 16}}, std::vector<std::uint8_t>(70)));
  expect_error([&] { read_tiff_volume(dir.path); }, "TIFF slice '" + (dir / "a10.tif").string() +
                                                        "': is 7 x 5 uint16; the first is 6 x 5 uint16");
  write(dir / "a10.tif", crafted_tiff({{6, 5, 16}, {6, 5, 16}}, std::vector<std::uint8_t>(60)));
  expect_error([&] { read_tiff_volume(dir.path); }, "a10.tif': has more than one page");
  // Hidden files (._a3.tif from macOS) are not slices.
  fs::remove(dir / "a10.tif");
  write(dir / "._a3.tif", {std::byte{0}});
  EXPECT_EQ(read_tiff_volume(dir.path).dims(), (std::array<int, 3>{6, 5, 2}));
  // Links: inside the folder followed, out of it refused.
  fs::create_symlink(dir / "a1.tif", dir / "a3.tif");
  EXPECT_EQ(read_tiff_volume(dir.path).dims(), (std::array<int, 3>{6, 5, 3}));
  fs::create_symlink(volume_fixture("tiff_slices/s2.tif"), dir / "a4.tif");
  expect_error([&] { read_tiff_volume(dir.path); }, "'a4.tif' links to a file outside the folder");
}

TEST(TiffVolume, RefusesTruncatedFilesWithOneLineAndNothingOnStderr) {
  const auto whole = read_file(volume_fixture("tiff_u16_lzw.tif"));
  test::TempDir dir;
  for (const std::size_t size : {std::size_t{0}, std::size_t{3}, std::size_t{8}, std::size_t{80}, whole.size() / 2,
                                 whole.size() - 40}) {
    SCOPED_TRACE(size);
    const std::vector<std::byte> cut(whole.begin(), whole.begin() + std::ptrdiff_t(size));
    testing::internal::CaptureStderr();
    expect_error([&] { parse_tiff_volume(cut, "cut.tif"); }, "TIFF 'cut.tif'");
    write(dir / "cut.tif", cut);
    expect_error([&] { read_tiff_volume(dir / "cut.tif"); }, "TIFF '" + (dir / "cut.tif").string() + "'");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  }
  // libtiff's own words, after the file's name: a damaged LZW strip.
  std::vector<std::byte> damaged(whole.begin(), whole.end());
  for (std::size_t i = 16; i < 60; ++i) damaged[i] = std::byte{0xff};
  testing::internal::CaptureStderr();
  const std::string m = expect_error([&] { parse_tiff_volume(damaged, "bad.tif"); },
                                     "TIFF 'bad.tif', page 0: cannot read row 0: ");
  EXPECT_EQ(m.find("TIFF", 1), std::string::npos) << m;  // named once
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
  expect_error([] { read_tiff_volume(volume_fixture("absent.tif")); }, "absent.tif");
}

TEST(TiffVolume, RefusesHugeClaimsQuicklyWithoutAllocating) {
  const auto start = std::chrono::steady_clock::now();
  // 100000 x 100000 pages: the first page is over the 2^30-sample limit.
  expect_error([] { parse_tiff_volume(crafted_tiff({{100000, 100000}, {100000, 100000}}, {1, 2}), "huge.tif"); },
               "TIFF 'huge.tif', page 0: volume of 100000x100000x2 samples exceeds the limit");
  // 1025 pages of 1024 x 1024: refused at the page that crosses 2^30.
  expect_error([] { parse_tiff_volume(crafted_tiff(std::vector<Page>(1025, Page{1024, 1024}), {1, 2}), "deep.tif"); },
               "TIFF 'deep.tif', page 1024: volume of 1024x1024x1025 samples exceeds the limit");
  // 2 x 4096 x 4096 bytes claimed by a file of 2 KiB: refused before allocating 32 MiB.
  expect_error([] { parse_tiff_volume(crafted_tiff({{4096, 4096}, {4096, 4096}}, std::vector<std::uint8_t>(2048)), "thin.tif"); },
               "TIFF 'thin.tif': its 2308 bytes cannot hold 2 pages of 4096 x 4096 uint8 (33554432 bytes");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
  // The memory budget: 2 pages of 1024 x 1024 really present, over a 1 MiB budget.
  const std::vector<std::uint8_t> data(2 << 20, 5);
  const auto pages = crafted_tiff({{1024, 1024, 8, 1, 8}, {1024, 1024, 8, 1, 8 + (1 << 20)}}, data);
  EXPECT_EQ(parse_tiff_volume(pages, "fits.tif").at(1023, 1023, 1), 5);
  set_memory_limit(1 << 20);
  expect_error([&] { parse_tiff_volume(pages, "budget.tif"); }, "over the memory limit of 1 MiB");
  set_memory_limit(0);
}

}  // namespace
}  // namespace vri
