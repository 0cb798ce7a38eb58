#include "fast_path.hpp"

#include <utility>

#include "vri/error.hpp"

namespace vri {

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

}  // namespace vri
