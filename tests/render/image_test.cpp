#include "vri/image.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace vri {
namespace {

// An image starts transparent black, rows top to bottom and 4 floats a
// pixel; release() hands its floats over (to NumPy) and leaves it empty.
TEST(Image, StartsAtZeroAndHandsItsPixelsOver) {
  for (const auto [w, h] : {std::array{3, 2}, std::array{512, 512}, std::array{700, 401}}) {
    Image image(w, h);
    ASSERT_EQ(image.data().size(), std::size_t(w) * h * 4);
    for (float v : image.data()) ASSERT_EQ(v, 0.f);
    image.set(w - 1, h - 1, {0.25, 0.5, 0.75, 1});
    image.set(1, 0, {0.125, 0, 0, 0.5});
    EXPECT_EQ(image.data()[4], 0.125f);
    EXPECT_EQ(image.data()[7], 0.5f);
    EXPECT_EQ(image.data()[image.data().size() - 2], 0.75f);
    EXPECT_EQ(image.pixel(w - 1, h - 1)[3], 1.f);
    const float* pixels = image.data().data();
    const ZeroedFloats released = std::move(image).release();
    EXPECT_EQ(released.data(), pixels);  // no copy
    EXPECT_EQ(released[4], 0.125f);
    EXPECT_EQ(image.width(), 0);  // NOLINT(bugprone-use-after-move): released
    EXPECT_EQ(image.data().size(), 0u);
  }
}

}  // namespace
}  // namespace vri
