#pragma once
// The histogram of a volume's scalars, and the transfer function it suggests:
// what `vri info` prints and what the viewer draws its editor over.
#include <cstdint>
#include <span>
#include <vector>

#include "vri/transfer/transfer_function.hpp"
#include "vri/volume/grid_volume.hpp"

namespace vri {

struct Histogram {
  double lo = 0, hi = 0;               // the scalar range; bin i covers lo + i (hi - lo) / bins
  std::vector<std::uint64_t> counts;  // the maximum falls in the last bin
};

Histogram histogram(const GridVolume& volume, int bins = 256);
Histogram histogram(std::span<const float> scalars, int bins = 256);

// A first transfer function for a volume never seen: transparent up to just
// above the background - the most common value when it lies in the lowest
// quarter of the range, where CT and MRI backgrounds lie - then a blue ->
// orange -> white ramp whose densest value stops half the light over a tenth
// of `diagonal` (the box's diagonal, world units).
TransferFunction suggest_transfer_function(const Histogram& h, double diagonal);

}  // namespace vri
