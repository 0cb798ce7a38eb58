#pragma once
// Images as the page receives them: previews as JPEG (libturbojpeg), final
// frames as PNG (the bytes `vri render -o x.png` writes), and the error map:
// the per-pixel error of a frame against `exact` as an 8-bit log-scale grey
// PNG with its statistics.
#include <cstddef>
#include <vector>

#include "vri/geometry.hpp"
#include "vri/image.hpp"

namespace vri::viewer {

// The image composited over `background` (as the PNG), JPEG at `quality` (1..100).
std::vector<std::byte> encode_jpeg(const Image& image, Vec3 background, int quality = 85);

struct ErrorMap {
  std::vector<std::byte> png;  // grey v: an error of 10^(6 v / 255 - 6); 0 at or below 1e-6
  double share_over = 0;       // pixels whose error exceeds the tolerance, over all pixels
  double max = 0;              // largest error
  double rms = 0;              // root mean square over pixels and the four channels
};

// A pixel's error is the largest absolute difference of its four premultiplied
// channels (r, g, b, alpha; before the background). vri::Error if the sizes differ.
ErrorMap error_map(const Image& frame, const Image& reference, double tolerance);

}  // namespace vri::viewer
