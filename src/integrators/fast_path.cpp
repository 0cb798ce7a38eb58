#include "vri/integrators/fast_path.hpp"

#include <algorithm>
#include <utility>

#include "vri/core/error.hpp"
#include "vri/core/printable.hpp"

namespace vri {

TerminationBound termination_bound(const Image& image, double termination) {
  TerminationBound bound;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const double remaining = 1 - double(image.pixel(x, y)[3]);
      if (!(remaining < termination)) continue;
      ++bound.pixels;
      bound.max_remaining = std::max(bound.max_remaining, remaining);
    }
  return bound;
}

namespace detail {

Skipping::Skipping(const GridVolume& volume, ZeroOpacity zero, const FastPath& fast, const std::string& method)
    : footprint_{volume.whole_box(), {}}, termination_(fast.termination) {
  if (!(fast.termination >= 0 && fast.termination < 1))
    throw Error(method + ": termination must be in [0, 1), got " + format_g(fast.termination));
  if (!fast.skip_empty) return;
  cells_ = std::make_unique<MacroCells>(volume);
  zero_.emplace(std::move(zero));
  space_.emplace(*cells_, *zero_);
  footprint_ = {space_->occupied_box(), space_->occupied_parts()};
}

}  // namespace detail
}  // namespace vri
