#include "vri/render.hpp"

#include <cmath>

#include "vri/error.hpp"

namespace vri {

std::vector<ChannelDifference> compare_images(std::span<const float> a, std::span<const float> b,
                                              int channels, double tolerance) {
  if (a.size() != b.size()) throw Error("images differ in size");
  if (channels <= 0 || a.size() % channels != 0) throw Error("bad channel count");
  const std::size_t pixels = a.size() / channels;
  std::vector<ChannelDifference> out(channels);
  std::vector<double> sq(channels, 0.0);
  std::vector<std::size_t> over(channels, 0);
  for (std::size_t p = 0; p < pixels; ++p)
    for (int c = 0; c < channels; ++c) {
      const double d = std::abs(double(a[p * channels + c]) - double(b[p * channels + c]));
      // NaN counts as over the tolerance and makes the maximum NaN for good
      // (a later finite difference must not hide it).
      if (!(d <= tolerance)) ++over[c];
      sq[c] += d * d;
      if (std::isnan(d)) ++out[c].nan;
      if (!(d <= out[c].max) && !std::isnan(out[c].max)) out[c].max = d;
    }
  for (int c = 0; c < channels; ++c) {
    out[c].share_over = pixels ? double(over[c]) / pixels : 0.0;
    out[c].rms = pixels ? std::sqrt(sq[c] / pixels) : 0.0;
  }
  return out;
}

}  // namespace vri
