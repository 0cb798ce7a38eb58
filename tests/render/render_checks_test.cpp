#include "vri/render.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "vri/error.hpp"
#include "vri/image.hpp"

namespace vri {
namespace {

using Limits = std::numeric_limits<float>;

std::string refusal(const Image& image) {
  try {
    refuse_non_finite(image, "the image");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// Every finite float passes, down to denormals and out to the largest; each
// kind of non-finite value is refused wherever it lies, with the count and
// the first one's pixel and channel.
TEST(RefuseNonFinite, PassesEveryFiniteValueAndNamesTheFirstOther) {
  Image image(37, 5);  // 740 values: the check's vector loop and its tail
  const float finite[] = {0.f, -0.f, Limits::denorm_min(), -Limits::denorm_min(), Limits::min(), 1.f, -1.f,
                          Limits::max(), -Limits::max(), std::nextafter(Limits::max(), 0.f)};
  int at = 0;
  for (float v : finite) image.set(at++ % 37, 0, {v, v, v, v});
  EXPECT_EQ(refusal(image), "");
  const float others[] = {Limits::infinity(), -Limits::infinity(), Limits::quiet_NaN(), -Limits::quiet_NaN(),
                          Limits::signaling_NaN()};
  for (float v : others)
    for (const auto [x, y, c] : {std::array{0, 0, 0}, std::array{36, 4, 3}, std::array{5, 2, 1}}) {
      Image bad = image;
      bad.pixel(x, y)[c] = v;
      const std::string what = refusal(bad);
      static const char* channel[] = {"r", "g", "b", "a"};
      EXPECT_NE(what.find("the image holds 1 non-finite values"), std::string::npos) << what;
      EXPECT_NE(what.find("at pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " + channel[c]),
                std::string::npos)
          << what;
    }
  Image two = image;
  two.pixel(3, 1)[2] = Limits::infinity();
  two.pixel(1, 3)[0] = Limits::quiet_NaN();
  EXPECT_NE(refusal(two).find("holds 2 non-finite values (first inf at pixel (3, 1) channel b)"), std::string::npos)
      << refusal(two);
}

}  // namespace
}  // namespace vri
