#include "vri/io.hpp"

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "vri/error.hpp"

namespace vri {
namespace {

TEST(Npy, WritesAnAlignedVersion1HeaderAndReadsItBack) {
  test::TempDir dir;
  Image img(3, 2);
  img.set(2, 1, {0.25, 0.5, 0.75, 1.0});
  write_npy(dir / "i.npy", img);
  const auto bytes = read_file(dir / "i.npy");
  const std::size_t header = std::size_t(bytes[8]) | (std::size_t(bytes[9]) << 8);
  EXPECT_EQ((10 + header) % 64, 0u);
  const std::string text(reinterpret_cast<const char*>(bytes.data()) + 10, header);
  EXPECT_NE(text.find("'shape': (2, 3, 4)"), std::string::npos) << text;
  EXPECT_EQ(text.back(), '\n');
  const auto arr = read_npy(dir / "i.npy");
  EXPECT_EQ(arr.shape, (std::vector<std::size_t>{2, 3, 4}));
  EXPECT_EQ(arr.data, test::pixels(img));
  EXPECT_FLOAT_EQ(arr.data[(1 * 3 + 2) * 4 + 1], 0.5f);
}

TEST(Npy, ReadsFloat64AndRefusesOtherFiles) {
  test::TempDir dir;
  std::string h = "{'descr': '<f8', 'fortran_order': False, 'shape': (2,), }";
  h.append((64 - (10 + h.size() + 1) % 64) % 64, ' ');
  h += '\n';
  std::vector<unsigned char> b{0x93, 'N', 'U', 'M', 'P', 'Y', 1, 0, static_cast<unsigned char>(h.size()), 0};
  b.insert(b.end(), h.begin(), h.end());
  const double vals[2] = {1.5, -2.25};
  const auto* p = reinterpret_cast<const unsigned char*>(vals);
  b.insert(b.end(), p, p + 16);
  test::write_bytes(dir / "d.npy", b);
  const auto arr = read_npy(dir / "d.npy");
  EXPECT_EQ(arr.data, (std::vector<float>{1.5f, -2.25f}));
  b.pop_back();
  test::write_bytes(dir / "short.npy", b);
  EXPECT_THROW(read_npy(dir / "short.npy"), Error);
  test::write_text(dir / "text.npy", "hello world, not numpy");
  EXPECT_THROW(read_npy(dir / "text.npy"), Error);
}

}  // namespace
}  // namespace vri
