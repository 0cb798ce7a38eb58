#pragma once
// An SVG figure of a RaySignal in the manner of El Hajjar et al.'s Figures 1,
// 2, 4 and 5: one panel per order, the signal in black, the approximation in
// red, their difference shaded green, the samples as dots and xi written.
#include <string>

#include "vri/analysis/ray_signal.hpp"

namespace vri {

std::string ray_signal_svg(const RaySignal& signal);

}  // namespace vri
