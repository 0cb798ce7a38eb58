#pragma once
// What an integrator holds for its fast path (FastPath, vri/methods.hpp):
// the macro cells of its volume, their classification against its transfer
// function and the termination threshold.
#include <memory>
#include <optional>
#include <string>

#include "vri/methods.hpp"
#include "tables/zero_opacity.hpp"
#include "volume/empty_space.hpp"
#include "volume/macro_cells.hpp"

namespace vri {

// To test slabs against the classification, Skipping also keeps the transfer
// function's zero-opacity ranges.
class Skipping {
 public:
  // Throws vri::Error unless 0 <= termination < 1.
  Skipping(const GridVolume& volume, ZeroOpacity zero, const FastPath& fast, const std::string& method);
  const EmptySpace* space() const { return space_ ? &*space_ : nullptr; }
  const ZeroOpacity* zero() const { return zero_ ? &*zero_ : nullptr; }  // null without skipping
  double termination() const { return termination_; }
  // Integrator::footprint of a method that skips this way: with skipping,
  // the non-empty macro cells (EmptySpace::occupied_parts; a ray that meets
  // none leaps to its end from its first sample, or reads only zero
  // entries: it adds exactly nothing), else the volume's box.
  const Footprint& footprint() const { return footprint_; }

 private:
  std::unique_ptr<MacroCells> cells_;
  std::optional<ZeroOpacity> zero_;
  std::optional<EmptySpace> space_;
  Footprint footprint_;
  double termination_;
};

}  // namespace vri
