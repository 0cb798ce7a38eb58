#pragma once
// Per-channel differences between two images (SPEC §10 `vri compare`).
#include <array>
#include <span>
#include <vector>

namespace vri {

struct ChannelDifference {
  double share_over = 0;  // share of pixels with |a - b| > tolerance, in [0, 1]
  double rms = 0;
  double max = 0;         // NaN when any difference is NaN (it stays: issue 46)
  std::size_t nan = 0;    // pixels whose difference is NaN (either image NaN there)
};

// a and b hold `channels` interleaved values per pixel; sizes must match.
std::vector<ChannelDifference> compare_images(std::span<const float> a, std::span<const float> b,
                                              int channels, double tolerance);

}  // namespace vri
